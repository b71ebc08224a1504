#include "core/track/truth_request.hpp"

#include <charconv>
#include <optional>
#include <sstream>

#include "core/common/error.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/coco_keypoints.hpp"
#include "core/track/ground_truth.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {
namespace truth_request_detail {

namespace fs = std::filesystem;
using R = TruthRequest;

std::vector<Option<R>> makeOptions() {
  const auto path = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(commandOption(name, help), field);
  };
  return {
      path("in",
           "Start from this tracks CSV, ground-truth CSV or COCO keypoints JSON (.json; keyframes "
           "are kept)",
           &R::in),
      integerOption<R>(commandOption("frames",
                                     "Frames of the video: pads the table with empty frames up "
                                     "to this count (without --in, starts from an empty ground "
                                     "truth)",
                                     0, kMaxGroundTruthFrames),
                       &R::frames),
      textListOption<R>(commandOption("keyframe",
                                      "FRAME=FILE: the hand-placed points of a frame from a "
                                      "landmark file (.pts, .ljson, .csv), marked as a keyframe "
                                      "(repeatable)"),
                        &R::keyframes),
      textListOption<R>(commandOption("clear-keyframe",
                                      "FRAME: no longer a keyframe; its points stay (repeatable)"),
                        &R::clear),
      flagOption<R>(commandOption("interpolate", "Fill every frame between two keyframes linearly"),
                    &R::interpolate),
      textOption<R>(requiredOption("out", "Ground-truth CSV to write (may be the --in file)"),
                    &R::out),
      path("pts", "Also write DIR/frame_000042.pts for every frame", &R::pts),
      path("coco",
           "Also write COCO keypoints JSON (images frame_000042.png, one annotation per frame "
           "with points, the scheme's names and skeleton)",
           &R::coco),
      path("video", "The video: the COCO images' width and height", &R::video),
      textOption<R>(
          commandOption("image-size", "WIDTHxHEIGHT of the frames for --coco, instead of --video"),
          &R::imageSize),
      textOption<R>(commandOption("scheme",
                                  "Landmark scheme for the COCO keypoint names: thesis25, ibug68 "
                                  "or a scheme .json (default: the built-in scheme with the "
                                  "set's landmark count)"),
                    &R::scheme),
  };
}

int frameNumber(const std::string& text, const std::string& option) {
  int frame = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, frame);
  if (text.empty() || ec != std::errc() || ptr != end || frame < 0) {
    throw InputError(option + ": \"" + text + "\" is not a frame number");
  }
  return frame;
}

// FRAME=FILE: the frame's points from a landmark file (.pts, .ljson, .csv), x and y only.
void setKeyframeFromFile(GroundTruthSet& set, const std::string& spec) {
  const auto equals = spec.find('=');
  if (equals == std::string::npos) {
    throw InputError("--keyframe: \"" + spec + "\" is not FRAME=FILE");
  }
  const int frame = frameNumber(spec.substr(0, equals), "--keyframe");
  const fs::path file = spec.substr(equals + 1);
  const auto points = readLandmarks(file);
  if (set.table.landmarkCount != 0 && points.size() != set.table.landmarkCount) {
    throwInputError(file, "has " + std::to_string(points.size()) +
                              " points, the ground truth has " +
                              std::to_string(set.table.landmarkCount));
  }
  set.setKeyframe(frame, points.matrix().topRows(2));
}

// --image-size WxH, or the --video's size: the COCO images' width and height.
CocoImageSize cocoImageSize(const R& args) {
  if (!args.imageSize.empty()) {
    const auto x = args.imageSize.find('x');
    CocoImageSize size;
    try {
      if (x != std::string::npos) {
        size.width = frameNumber(args.imageSize.substr(0, x), "--image-size");
        size.height = frameNumber(args.imageSize.substr(x + 1), "--image-size");
      }
    } catch (const InputError&) {
      size = {};  // reported below, as the whole option
    }
    if (size.width <= 0 || size.height <= 0) {
      throw InputError("--image-size: \"" + args.imageSize + "\" is not WIDTHxHEIGHT (640x480)");
    }
    return size;
  }
  if (args.video.empty()) {
    throw InputError("truth: --coco needs the frames' size: give --video or --image-size WxH");
  }
  const VideoReader reader(args.video);
  return {reader.width(), reader.height()};
}

// --scheme, else the built-in scheme of the set's landmark count.
Scheme truthScheme(const R& args, int landmarkCount) {
  if (!args.scheme.empty()) return Scheme::byNameOrPath(args.scheme);
  if (const Scheme* builtIn = builtInSchemeOfSize(landmarkCount)) return *builtIn;
  throw InputError("truth: no built-in scheme has " + std::to_string(landmarkCount) +
                   " landmarks; give --scheme (a scheme .json) for the COCO keypoint names");
}

GroundTruthSet loadTruthInput(const R& args) {
  if (args.in.empty()) return GroundTruthSet::fromTrack(TrackTable{}, args.frames);
  if (!isCocoKeypointsFile(args.in)) return loadGroundTruth(args.in);
  if (args.scheme.empty()) return loadCocoKeypoints(args.in);
  const Scheme scheme = Scheme::byNameOrPath(args.scheme);
  return loadCocoKeypoints(args.in, &scheme);
}

}  // namespace truth_request_detail

const std::vector<Option<TruthRequest>>& truthOptions() {
  static const std::vector<Option<TruthRequest>> table = truth_request_detail::makeOptions();
  return table;
}

std::string runTruth(const TruthRequest& args) {
  std::vector<int> clear;
  for (const std::string& text : args.clear) {
    try {
      clear.push_back(truth_request_detail::frameNumber(text, "--clear-keyframe"));
    } catch (const InputError& error) {
      throw UsageError("--clear-keyframe", error.what());
    }
  }
  if (args.in.empty() && args.frames < 0) {
    throw InputError(
        "truth: give --in (a tracks or ground-truth CSV, or COCO keypoints JSON) or --frames (to "
        "start empty)");
  }
  // Checked before anything is written, so a missing size does not leave a half-done export.
  const std::optional<CocoImageSize> cocoSize =
      args.coco.empty() ? std::nullopt
                        : std::optional<CocoImageSize>(truth_request_detail::cocoImageSize(args));
  GroundTruthSet set = truth_request_detail::loadTruthInput(args);
  if (args.frames >= 0) {
    if (args.frames < set.frameCount()) {
      throwInputError(args.in, "has " + std::to_string(set.frameCount()) +
                                   " frames, more than --frames " + std::to_string(args.frames));
    }
    set.padTo(args.frames);
  }
  for (const int frame : clear) set.clearKeyframe(frame);
  for (const auto& spec : args.keyframes) truth_request_detail::setKeyframeFromFile(set, spec);
  const int filled = args.interpolate ? set.interpolateKeyframes() : 0;

  std::optional<Scheme> scheme;
  if (cocoSize) scheme = truth_request_detail::truthScheme(args, set.table.landmarkCount);
  saveGroundTruth(args.out, set, args.pts);
  if (cocoSize) saveCocoKeypoints(args.coco, set, *scheme, *cocoSize);
  std::ostringstream out;
  out << "ground truth: " << args.out.string() << " (" << set.frameCount() << " frames, "
      << set.keyframeCount() << " keyframes, " << set.table.landmarkCount << " landmarks)\n";
  if (args.interpolate) out << "interpolated: " << filled << " frames\n";
  if (!args.pts.empty()) {
    out << "pts: " << args.pts.string() << " (" << set.frameCount() << " files frame_NNNNNN.pts)\n";
  }
  if (cocoSize) {
    out << "coco: " << args.coco.string() << " (" << set.frameCount() << " images "
        << cocoSize->width << "x" << cocoSize->height << ", scheme " << scheme->name() << ")\n";
  }
  return out.str();
}

}  // namespace clm3d
