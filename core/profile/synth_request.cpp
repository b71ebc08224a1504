#include "core/profile/synth_request.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

#include "core/common/error.hpp"
#include "core/dataset/axis_name.hpp"
#include "core/dataset/ict_facekit.hpp"
#include "core/dataset/ict_textured.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/eval/photo_pair_sequence.hpp"
#include "core/profile/detail/turned_photo_sequence.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace synth_request_detail {

namespace fs = std::filesystem;
using R = SynthRequest;

constexpr int kProgressFrames = 30;  // shorter sequences take a second: no progress lines

// "A:B" or "A" (= "A:A"); nullopt if malformed.
std::optional<std::pair<double, double>> parseRange(const std::string& text) {
  const auto number = [](const std::string& s) -> std::optional<double> {
    if (s.empty()) return std::nullopt;
    std::size_t used = 0;
    try {
      const double value = std::stod(s, &used);
      if (used != s.size() || !std::isfinite(value)) return std::nullopt;
      return value;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  };
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) {
    const auto value = number(text);
    if (!value) return std::nullopt;
    return std::make_pair(*value, *value);
  }
  const auto from = number(text.substr(0, colon));
  const auto to = number(text.substr(colon + 1));
  if (!from || !to) return std::nullopt;
  return std::make_pair(*from, *to);
}

std::function<void(std::string_view)> angleRange(double limit) {
  return [limit](std::string_view view) {
    const std::string text(view);
    const auto range = parseRange(text);
    if (!range) {
      throw InputError("expected FROM:TO in degrees (e.g. 0:60 or -30:30), got '" + text + "'");
    }
    if (std::abs(range->first) > limit || std::abs(range->second) > limit) {
      std::ostringstream message;
      message << "angles must be within -" << limit << ".." << limit << " degrees, got '" << text
              << "'";
      throw InputError(message.str());
    }
  };
}

// "640x480" -> (640, 480); nullopt if malformed.
std::optional<std::pair<int, int>> parseSize(const std::string& text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) return std::nullopt;
  try {
    std::size_t usedWidth = 0;
    std::size_t usedHeight = 0;
    const int width = std::stoi(text.substr(0, x), &usedWidth);
    const int height = std::stoi(text.substr(x + 1), &usedHeight);
    if (usedWidth != x || usedHeight != text.size() - x - 1) return std::nullopt;
    return std::make_pair(width, height);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

void checkSize(std::string_view view) {
  const std::string text(view);
  const auto size = parseSize(text);
  if (!size) throw InputError("expected WIDTHxHEIGHT, e.g. 640x480, got '" + text + "'");
  const auto [width, height] = *size;
  if (width < 16 || height < 16 || width > 8192 || height > 8192) {
    throw InputError("each side must be 16..8192 pixels, got '" + text + "'");
  }
  if (width % 2 != 0 || height % 2 != 0) {
    throw InputError("width and height must be even (video codecs need it), got '" + text + "'");
  }
}

std::string expressionNames() {
  std::string names;
  for (const auto& name : expressionPresetNames()) names += (names.empty() ? "" : ", ") + name;
  return names;
}

std::vector<Option<R>> makeOptions() {
  const auto path = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(commandOption(name, help), field);
  };
  return {
      textOption<R>(requiredOption("out",
                                   "Output folder: sequence.avi (or .mp4), truth.csv, "
                                   "truth-visibility.csv, sequence.json"),
                    &R::out),
      path("mesh", "Textured scan: OBJ (+MTL, image), PLY, glTF/GLB", &R::mesh),
      path("landmarks",
           "The scan's 3D landmarks, or the photo's 2D points (.pts/.ljson/.csv, 25 thesis or 68 "
           "iBUG points)",
           &R::landmarks),
      path("photo",
           "Use this annotated photo moving in the image plane (translation, scale, rotation, "
           "brightness, contrast) instead of a head turning",
           &R::photo),
      integerOption<R>(commandOption("frames", "With --photo: number of frames", 1, 100000),
                       &R::frames),
      integerOption<R>(
          commandOption("seed", "With --photo: seed of the random smooth motion", 0, 9e18),
          &R::seed),
      realOption<R>(commandOption("photo-roll",
                                  "With --photo: largest in-plane rotation of the face, degrees "
                                  "either way",
                                  0.0, 180.0),
                    &R::photoRoll),
      textOption<R>(commandOption("photo-zoom",
                                  "With --photo: SMALLEST:LARGEST relative size of "
                                  "the face (e.g. 0.6:1.6)"),
                    &R::photoZoom),
      path("beside",
           "With --photo: a second annotated photo in the right half, moving on its own "
           "trajectory (seed + 1); the truth has a face column (0 left, 1 right)",
           &R::beside),
      path("beside-landmarks", "With --beside: its points", &R::besideLandmarks),
      path("dense-model",
           "With --photo and --yaw-range: the dense face fitted to the photo's points "
           "(ICT-FaceKit archive or folder)",
           &R::denseModel),
      path("dense-vertices",
           "With --dense-model: its thesis25 landmark vertex table "
           "(tests/fixtures/ict-facekit/thesis25_vertices.json)",
           &R::denseVertices),
      optionalIntegerOption<R>(
          commandOption("dense-head-seed",
                        "With --photo and --yaw-range, instead of --dense-model: the procedural "
                        "head of this seed as the dense face (its own mesh, no modes; a photo of "
                        "that head)",
                        0, 9e18),
          &R::denseHeadSeed),
      path("contact-sheet",
           "With --photo and --yaw-range: also write a contact sheet (PNG) of the photo and "
           "--sheet-frames frames with their visible truth points",
           &R::contactSheet),
      integerOption<R>(commandOption("sheet-frames", "Frames on the contact sheet", 1, 64),
                       &R::sheetFrames),
      integerOption<R>(commandOption("dense-modes",
                                     "With --dense-model: identity components fitted (the model "
                                     "has 100)",
                                     0, 100),
                       &R::denseModes),
      textOption<R>(commandOption("up", "The scan file's up axis"), &R::up, checkAxisName),
      textOption<R>(commandOption("front", "The scan file's axis out of the face"), &R::front,
                    checkAxisName),
      realOption<R>(commandOption("scale",
                                  "The scan file's units in millimetres (mesh and landmarks are "
                                  "multiplied by it, as a manifest's scans[i].scale)",
                                  1e-9, 1e9),
                    &R::scale),
      optionalIntegerOption<R>(
          commandOption("head-seed", "Use the procedural head of this seed instead of a scan", 0,
                        9e18),
          &R::headSeed),
      textOption<R>(commandOption("expression", "Procedural head's expression: " +
                                                    expressionNames() + " (default neutral)"),
                    &R::expression),
      integerOption<R>(commandOption("texture-size", "Procedural head's texture size", 256, 8192),
                       &R::textureSize),
      realOption<R>(commandOption("face-step", "Procedural head's mesh step in degrees", 0.3, 3.0),
                    &R::faceStep),
      textOption<R>(commandOption("yaw-range",
                                  "Yaw FROM:TO in degrees, either direction (positive: nose "
                                  "towards image +x); write --yaw-range=-60:0 for a negative "
                                  "start. With --photo: turn the photo's face in 3D through a "
                                  "dense face fitted to its points"),
                    &R::yawRange, angleRange(180.0)),
      textOption<R>(commandOption("pitch-range",
                                  "Pitch FROM:TO in degrees (positive: nose down), or one fixed "
                                  "value (with --photo --yaw-range: default the photo's own "
                                  "pitch)"),
                    &R::pitchRange, angleRange(90.0)),
      realOption<R>(commandOption("roll", "Fixed roll in degrees", -180.0, 180.0), &R::roll),
      realOption<R>(commandOption("step",
                                  "Degrees per frame (the larger of the yaw and pitch "
                                  "change)",
                                  0.01, 90.0),
                    &R::step),
      flagOption<R>(
          commandOption("sweep", "Go frontal -> FROM -> TO -> frontal instead of FROM -> TO"),
          &R::sweep),
      textOption<R>(commandOption("size",
                                  "Image size WIDTHxHEIGHT (even); with --photo default "
                                  "the photo's size (rounded down to even)"),
                    &R::size, checkSize),
      realOption<R>(
          commandOption("face-size", "Distance between the eye centres in the frontal view, pixels",
                        4.0, 8000.0),
          &R::faceSize),
      realOption<R>(commandOption("fov", "Vertical field of view in degrees", 1.0, 150.0), &R::fov),
      realOption<R>(commandOption("fps", "Frame rate written into the video", 0.1, 1000.0),
                    &R::fps),
      integerOption<R>(
          commandOption("supersample",
                        "Render at N times the size and average down (anti-aliasing)", 1, 4),
          &R::supersample),
      realListOption<R>(commandOption("light-dir",
                                      "Direction towards the light, eye space X,Y,Z (as clm3d "
                                      "render)",
                                      -100.0, 100.0),
                        &R::lightDir),
      realOption<R>(commandOption("ambient", "Ambient light intensity", 0.0, 2.0), &R::ambient),
      realOption<R>(commandOption("diffuse", "Directional light intensity", 0.0, 2.0), &R::diffuse),
      path("background", "Background image (scaled to cover the frame); default plain grey",
           &R::background),
      textChoiceOption<R>(commandOption("format",
                                        "Video format: avi or mkv (FFV1, lossless), mp4 "
                                        "(MPEG-4, lossy)"),
                          &R::format, {"avi", "mkv", "mp4"}),
  };
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Reports only for sequences long enough to take a while.
ProgressCallback progressFor(int frames, const ProgressCallback& progress) {
  if (frames >= kProgressFrames && progress) return progress;
  return [](double, std::string_view) {};
}

SequenceFiles filesOf(const R& r) {
  return SequenceFiles::inFolder(r.out, "." + r.format);
}

Lighting lightingOf(const R& r) {
  if (r.lightDir.size() != 3) throw UsageError("--light-dir", "expected 3 values X,Y,Z");
  Lighting lighting;
  lighting.direction = Eigen::Vector3d(r.lightDir[0], r.lightDir[1], r.lightDir[2]);
  lighting.ambient = r.ambient;
  lighting.diffuse = r.diffuse;
  return lighting;
}

struct Subject {
  TexturedSubject subject;
  SequenceSubject description;
  std::string name;
};

// A scan in model coordinates, loaded exactly as the trainer loads a manifest's scan, or a
// procedural head generated as a manifest's procedural entry is.
Subject loadSubject(const R& r, bool scan) {
  Subject s;
  if (scan) {
    s.subject = loadScanSubject(scanFromAxes(r.mesh, r.landmarks, r.up, r.front, r.scale),
                                Scheme::thesis25());
    s.description.mesh = r.mesh.string();
    s.description.landmarks = r.landmarks.string();
    s.description.scale = r.scale;
    s.name = r.mesh.filename().string();
    return s;
  }
  const std::string expression = r.expression.empty() ? "neutral" : r.expression;
  ProceduralSource source;
  source.textureSize = r.textureSize;
  source.faceStepDegrees = r.faceStep;
  s.subject = makeProceduralSubject(*r.headSeed, expression, source);
  s.description.headSeed = r.headSeed;
  s.description.expression = expression;
  s.description.faceStepDegrees = source.faceStepDegrees;
  s.description.textureSize = source.textureSize;
  s.name = "procedural head " + std::to_string(*r.headSeed) + " (" + expression + ")";
  return s;
}

SequenceSettings sequenceSettings(const R& r) {
  SequenceSettings settings;
  const auto yaw = parseRange(r.yawRange);
  const auto pitch = parseRange(r.pitchRange);
  const auto size = parseSize(r.size);
  if (!size) throw UsageError("--size", "expected WIDTHxHEIGHT, e.g. 640x480");
  settings.yawFromDeg = yaw->first;
  settings.yawToDeg = yaw->second;
  settings.pitchFromDeg = pitch->first;
  settings.pitchToDeg = pitch->second;
  settings.rollDeg = r.roll;
  settings.stepDeg = r.step;
  settings.order = r.sweep ? SequenceOrder::Sweep : SequenceOrder::Range;
  settings.width = size->first;
  settings.height = size->second;
  settings.interOcularPixels = r.faceSize;
  settings.verticalFovDeg = r.fov;
  settings.fps = r.fps;
  settings.supersample = r.supersample;
  settings.lighting = lightingOf(r);
  settings.backgroundImage = r.background;
  settings.validate();
  return settings;
}

// A scan or a procedural head turning.
std::string runHeadSynth(const R& r, const ProgressCallback& progress, const CancelToken* cancel) {
  const bool scan = !r.mesh.empty() || !r.landmarks.empty();
  if (scan && r.headSeed) {
    throw UsageError("--head-seed",
                     "give either --mesh and --landmarks (a scan) or --head-seed (a procedural "
                     "head), not both");
  }
  if (!scan && !r.headSeed) {
    throw UsageError("--mesh/--head-seed",
                     "give --mesh and --landmarks (a scan), --head-seed N (a procedural head) or "
                     "--photo and --landmarks (a photo)");
  }
  if (scan && (r.mesh.empty() || r.landmarks.empty())) {
    throw UsageError("--mesh/--landmarks", "a scan needs both --mesh and --landmarks");
  }
  if (scan && !r.expression.empty()) {
    throw UsageError("--expression",
                     "applies to procedural heads (--head-seed) only; a scan has the expression "
                     "it was captured with");
  }
  const SequenceSettings settings = sequenceSettings(r);
  // Inputs that are quick to check, before the slow part (generating or loading the head).
  if (!r.background.empty() && !fs::exists(r.background)) {
    throwInputError(r.background, "file not found");
  }
  const int frames = static_cast<int>(sequenceAngles(settings).size());
  const Subject subject = loadSubject(r, scan);
  const auto start = std::chrono::steady_clock::now();
  const SequenceFiles files = filesOf(r);
  const SequenceSummary summary = writeSyntheticSequence(
      subject.subject.mesh, subject.subject.landmarks, Scheme::thesis25(), settings,
      subject.description, files, progressFor(frames, progress), cancel);
  const double seconds = secondsSince(start);

  std::ostringstream line;
  line << "synth: " << summary.frames << " frames " << settings.width << "x" << settings.height
       << " of " << subject.name << ", yaw " << settings.yawFromDeg << ".." << settings.yawToDeg;
  if (settings.pitchFromDeg != settings.pitchToDeg) {
    line << ", pitch " << settings.pitchFromDeg << ".." << settings.pitchToDeg;
  } else if (settings.pitchFromDeg != 0.0) {
    line << ", pitch " << settings.pitchFromDeg;
  }
  line << (settings.order == SequenceOrder::Sweep ? " (sweep from and back to frontal)" : "")
       << ", step " << settings.stepDeg << " deg, face " << settings.interOcularPixels << " px, "
       << summary.hiddenPoints << " hidden landmark-frames -> " << files.video.string()
       << " (+ truth.csv, truth-visibility.csv, sequence.json) in " << std::fixed
       << std::setprecision(1) << seconds << " s (" << summary.frames / std::max(seconds, 1e-9)
       << " frames/s)\n";
  return line.str();
}

TurnedPhotoSettings turnedPhotoSettings(const R& r) {
  for (const char* moving : {"frames", "seed", "photo-roll", "photo-zoom"}) {
    if (r.given.count(moving) > 0) {
      throw UsageError(std::string("--") + moving,
                       "moves the photo in the image plane; with --yaw-range the face turns in 3D "
                       "instead, leave it out");
    }
  }
  if (r.given.count("size") > 0)
    throw UsageError("--size", "a turned photo keeps the photo's size");
  if (!r.beside.empty()) {
    throw UsageError("--beside",
                     "pairs photos moving in the image plane; a turned photo is one face");
  }
  if (r.denseHeadSeed && !r.denseModel.empty()) {
    throw UsageError("--dense-head-seed", "give --dense-model or --dense-head-seed, not both");
  }
  if (!r.denseHeadSeed && (r.denseModel.empty() || r.denseVertices.empty())) {
    throw UsageError(
        "--dense-model/--dense-vertices",
        "turning a photo needs the dense face: --dense-model (ICT-FaceKit archive or folder) and "
        "--dense-vertices (its thesis25 vertex table, tests/fixtures/ict-facekit/"
        "thesis25_vertices.json), or --dense-head-seed N (a procedural head's own mesh)");
  }
  TurnedPhotoSettings settings;
  const auto yaw = parseRange(r.yawRange);
  settings.yawFromDeg = yaw->first;
  settings.yawToDeg = yaw->second;
  settings.keepPhotoPitch = r.given.count("pitch-range") == 0;
  if (!settings.keepPhotoPitch) {
    const auto pitch = parseRange(r.pitchRange);
    settings.pitchFromDeg = pitch->first;
    settings.pitchToDeg = pitch->second;
  }
  settings.stepDeg = r.step;
  settings.order = r.sweep ? SequenceOrder::Sweep : SequenceOrder::Range;
  settings.verticalFovDeg = r.fov;
  settings.fps = r.fps;
  settings.profile.supersample = r.supersample;
  settings.sheetFrames = r.contactSheet.empty() ? 0 : r.sheetFrames;
  settings.validate();
  return settings;
}

// --photo with --yaw-range: the photo's face profiled and turned in 3D.
std::string runTurnedPhotoSynth(const R& r, const ProgressCallback& progress,
                                const CancelToken* cancel) {
  const TurnedPhotoSettings settings = turnedPhotoSettings(r);
  if (!r.denseHeadSeed && !fs::exists(r.denseModel))
    throwInputError(r.denseModel, "file not found");
  const cv::Mat photo = readImage(r.photo);
  const LandmarkSet points = readLandmarks(r.landmarks, &Scheme::thesis25());
  if (points.presentCount() < 4) {
    throwInputError(r.landmarks, "has " + std::to_string(points.presentCount()) +
                                     " thesis25 points; a profile needs at least 4");
  }
  const auto start = std::chrono::steady_clock::now();
  DenseFace face;
  std::string denseName;
  if (r.denseHeadSeed) {
    // A procedural head's own mesh, no modes: for trying the mode out without the ICT model
    // (the photo should then be of that head).
    ProceduralSource source;
    source.textureSize = r.textureSize;
    source.faceStepDegrees = r.faceStep;
    const TexturedSubject head = makeProceduralSubject(*r.denseHeadSeed, "neutral", source);
    face = denseFaceFromMesh(head.mesh, head.landmarks);
    denseName = "procedural head " + std::to_string(*r.denseHeadSeed);
  } else {
    const std::vector<int> vertices =
        readLandmarkVertexTable(r.denseVertices, "thesis25", Scheme::thesis25().size());
    IctDenseSettings dense;
    dense.identityModes = r.denseModes;
    face = denseFaceFromIct(loadIctMeshModel(r.denseModel, vertices, r.denseVertices, {}, cancel),
                            dense);
    denseName = r.denseModel.string();
  }
  const double loadSeconds = secondsSince(start);
  const SequenceFiles files = filesOf(r);
  const TurnedPhotoSummary summary = writeTurnedPhotoSequence(
      face, photo, points, settings, {r.photo.string(), r.landmarks.string(), denseName}, files,
      progressFor(turnedPhotoFrameCount(settings), progress), cancel);
  if (!r.contactSheet.empty()) writeImage(r.contactSheet, summary.contactSheet);
  const PhotoProfile& profile = summary.profile;
  std::ostringstream line;
  line << std::fixed << std::setprecision(1) << "synth: " << summary.frames << " frames "
       << summary.frameSize.width << "x" << summary.frameSize.height << " of " << r.photo.string()
       << " turned, yaw " << settings.yawFromDeg << ".." << settings.yawToDeg << ", step "
       << settings.stepDeg << " deg; profile: " << profile.pointsFitted << " points fitted, rms "
       << std::setprecision(2) << profile.rmsPixels << " px, photo pose yaw "
       << std::setprecision(1) << degrees(profile.pose.yaw) << " pitch "
       << degrees(profile.pose.pitch) << " roll " << degrees(profile.pose.roll) << ", "
       << std::setprecision(0) << 100.0 * profile.mirroredShare << "% of triangles mirrored, "
       << 100.0 * profile.backgroundShare << "% on the background; " << summary.hiddenPoints
       << " hidden landmark-frames -> " << files.video.string()
       << " (+ truth.csv, truth-visibility.csv, sequence.json) in " << std::setprecision(1)
       << secondsSince(start) << " s (dense face " << loadSeconds << " s)\n";
  return line.str();
}

PhotoSequenceSettings photoSettings(const R& r) {
  PhotoSequenceSettings settings;
  settings.frames = r.frames;
  settings.seed = r.seed;
  settings.fps = r.fps;
  settings.rotationDeg = r.photoRoll;
  const auto zoom = parseRange(r.photoZoom);
  if (!zoom || !(zoom->first > 0.0) || zoom->second < zoom->first) {
    throw UsageError("--photo-zoom", "expected SMALLEST:LARGEST relative sizes, e.g. 0.6:1.6");
  }
  settings.scaleCentre = 0.5 * (zoom->first + zoom->second);
  settings.scaleRange = 0.5 * (zoom->second - zoom->first);
  if (r.given.count("size") > 0) {
    const auto size = parseSize(r.size);
    if (!size) throw UsageError("--size", "expected WIDTHxHEIGHT, e.g. 640x480");
    settings.width = size->first;
    settings.height = size->second;
  }
  settings.validate();
  return settings;
}

// --photo with --beside: two photos side by side, each moving on its own trajectory.
std::string runPhotoPairSynth(const R& r, const PhotoSequenceSettings& settings,
                              const cv::Mat& left, const LandmarkSet& leftPoints,
                              const ProgressCallback& progress, const CancelToken* cancel) {
  if (r.beside.empty() || r.besideLandmarks.empty()) {
    throw UsageError("--beside", "a second photo needs both --beside and --beside-landmarks");
  }
  const cv::Mat right = readImage(r.beside);
  const LandmarkSet rightPoints = readPhotoPoints(r.besideLandmarks);
  const auto start = std::chrono::steady_clock::now();
  const SequenceFiles files = filesOf(r);
  const PhotoPairSummary summary = writePhotoPairSequence(
      left, leftPoints, right, rightPoints, settings, {r.photo.string(), r.landmarks.string()},
      {r.beside.string(), r.besideLandmarks.string()}, files,
      progressFor(settings.frames, progress), cancel);
  std::ostringstream line;
  line << "synth: " << summary.frames << " frames " << summary.frameSize.width << "x"
       << summary.frameSize.height << " of " << r.photo.string() << " (seed " << settings.seed
       << ") beside " << r.beside.string() << " (seed " << settings.seed + 1 << ") -> "
       << files.video.string() << " (+ truth.csv with a face column, sequence.json) in "
       << std::fixed << std::setprecision(1) << secondsSince(start) << " s\n";
  return line.str();
}

// --photo: the photo moving in the image plane, its landmarks moved with it.
std::string runPhotoSynth(const R& r, const ProgressCallback& progress, const CancelToken* cancel) {
  if (!r.mesh.empty() || r.headSeed) {
    throw UsageError("--photo", "give --photo, --mesh or --head-seed, only one");
  }
  if (r.landmarks.empty())
    throw UsageError("--photo", "a photo needs its points: --landmarks F.pts");
  if (!r.expression.empty()) {
    throw UsageError("--expression", "applies to procedural heads (--head-seed) only");
  }
  if (r.given.count("yaw-range") > 0) return runTurnedPhotoSynth(r, progress, cancel);
  if (r.given.count("pitch-range") > 0) {
    throw UsageError("--pitch-range", "with --photo, give --yaw-range too");
  }
  const PhotoSequenceSettings settings = photoSettings(r);
  const cv::Mat photo = readImage(r.photo);
  const LandmarkSet points = readPhotoPoints(r.landmarks);
  if (!r.beside.empty() || !r.besideLandmarks.empty()) {
    return runPhotoPairSynth(r, settings, photo, points, progress, cancel);
  }
  const auto start = std::chrono::steady_clock::now();
  const SequenceFiles files = filesOf(r);
  const PhotoSequenceSummary summary =
      writePhotoSequence(photo, points, settings, {r.photo.string(), r.landmarks.string()}, files,
                         progressFor(settings.frames, progress), cancel);
  std::ostringstream line;
  line << "synth: " << summary.frames << " frames " << summary.frameSize.width << "x"
       << summary.frameSize.height << " of " << r.photo.string() << " (seed " << settings.seed
       << ", face " << std::fixed << std::setprecision(1) << summary.face.size << " px, points "
       << points.presentCount() << "/" << points.size() << ") -> " << files.video.string()
       << " (+ truth.csv, truth-visibility.csv, sequence.json) in " << secondsSince(start)
       << " s\n";
  return line.str();
}

}  // namespace synth_request_detail

const std::vector<Option<SynthRequest>>& synthOptions() {
  static const std::vector<Option<SynthRequest>> table = synth_request_detail::makeOptions();
  return table;
}

std::string runSynthRequest(const SynthRequest& request, const ProgressCallback& progress,
                            const CancelToken* cancel) {
  if (!request.photo.empty()) return synth_request_detail::runPhotoSynth(request, progress, cancel);
  return synth_request_detail::runHeadSynth(request, progress, cancel);
}

}  // namespace clm3d
