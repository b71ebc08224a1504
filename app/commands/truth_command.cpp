// clm3d truth: builds a ground truth for a video the way the studio's track page does, from a
// tracker output (or an earlier ground truth, or nothing), hand-placed keyframes read from landmark
// files, and linear interpolation between keyframes; writes the ground-truth CSV and optionally
// one .pts per frame. All of it is core/track/ground_truth.hpp (docs/ground-truth.md).
#include <charconv>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/error.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/ground_truth.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct TruthArgs {
  fs::path in;
  fs::path out;
  fs::path pts;
  int frames = -1;
  std::vector<std::string> keyframes;  // FRAME=FILE
  std::vector<int> clear;
  bool interpolate = false;
};

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

void runTruth(const TruthArgs& args) {
  if (args.in.empty() && args.frames < 0) {
    throw InputError(
        "truth: give --in (a tracks or ground-truth CSV) or --frames (to start empty)");
  }
  GroundTruthSet set = args.in.empty() ? GroundTruthSet::fromTrack(TrackTable{}, args.frames)
                                       : loadGroundTruth(args.in);
  if (args.frames >= 0) {
    if (args.frames < set.frameCount()) {
      throwInputError(args.in, "has " + std::to_string(set.frameCount()) +
                                   " frames, more than --frames " + std::to_string(args.frames));
    }
    set.padTo(args.frames);
  }
  for (const int frame : args.clear) set.clearKeyframe(frame);
  for (const auto& spec : args.keyframes) setKeyframeFromFile(set, spec);
  const int filled = args.interpolate ? set.interpolateKeyframes() : 0;

  saveGroundTruth(args.out, set, args.pts);
  std::cout << "ground truth: " << args.out.string() << " (" << set.frameCount() << " frames, "
            << set.keyframeCount() << " keyframes, " << set.table.landmarkCount << " landmarks)\n";
  if (args.interpolate) std::cout << "interpolated: " << filled << " frames\n";
  if (!args.pts.empty()) {
    std::cout << "pts: " << args.pts.string() << " (" << set.frameCount()
              << " files frame_NNNNNN.pts)\n";
  }
}

}  // namespace

void addTruthCommand(CLI::App& root) {
  auto args = std::make_shared<TruthArgs>();
  CLI::App* command = root.add_subcommand(
      "truth",
      "Build a ground truth from a tracker output and hand-placed keyframes, interpolating "
      "between keyframes; writes the ground-truth CSV and optionally one .pts per frame");
  command->add_option("--in", args->in,
                      "Start from this tracks CSV or ground-truth CSV (keyframes are kept)");
  command
      ->add_option("--frames", args->frames,
                   "Frames of the video: pads the table with empty frames up to this count "
                   "(without --in, starts from an empty ground truth)")
      ->check(CLI::Range(0, kMaxGroundTruthFrames));
  command->add_option("--keyframe", args->keyframes,
                      "FRAME=FILE: the hand-placed points of a frame from a landmark file "
                      "(.pts, .ljson, .csv), marked as a keyframe (repeatable)");
  command->add_option("--clear-keyframe", args->clear,
                      "FRAME: no longer a keyframe; its points stay (repeatable)");
  command->add_flag("--interpolate", args->interpolate,
                    "Fill every frame between two keyframes linearly");
  command->add_option("--out", args->out, "Ground-truth CSV to write (may be the --in file)")
      ->required();
  command->add_option("--pts", args->pts, "Also write DIR/frame_000042.pts for every frame");
  command->callback([args] { runTruth(*args); });
}

}  // namespace clm3d::cli
