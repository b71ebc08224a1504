// clm3d synth: renders a synthetic test sequence (thesis section 5.2) of a textured scan or a
// procedural head turning a fixed number of degrees per frame, and writes the video, the exact
// ground truth, the per-frame landmark visibility and a description of how it was made. All work is
// done by core (eval/synthetic_sequence, dataset/training_subjects for the head). Ctrl-C cancels
// cleanly. With --photo, the sequence is an annotated photo moving in the image plane instead
// (core/eval/photo_sequence), or with --yaw-range its face profiled and turned in 3D
// (core/profile/turned_photo_sequence).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/scan_options.hpp"
#include "core/common/error.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/eval/photo_pair_sequence.hpp"
#include "core/eval/photo_sequence.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/profile/dense_face.hpp"
#include "core/profile/turned_photo_sequence.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/synth/synth_head.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct SynthArgs {
  fs::path out;
  fs::path mesh;
  fs::path landmarks;
  std::optional<std::uint64_t> headSeed;
  std::string expression;
  int textureSize = 1024;
  double faceStep = SynthOptions{}.faceStepDegrees;
  std::string up = "+y";
  std::string front = "+z";
  double scale = 1.0;
  std::string yawRange = "0:60";
  std::string pitchRange = "0";
  double roll = 0.0;
  double step = 1.0;
  bool sweep = false;
  std::string size = "640x480";
  double faceSize = SequenceSettings{}.interOcularPixels;
  double fov = kDefaultVerticalFovDeg;
  double fps = SequenceSettings{}.fps;
  int supersample = SequenceSettings{}.supersample;
  std::vector<double> lightDir{0.3, 0.4, 1.0};
  double ambient = Lighting{}.ambient;
  double diffuse = Lighting{}.diffuse;
  fs::path background;
  std::string format = "avi";
  fs::path photo;
  int frames = PhotoSequenceSettings{}.frames;
  std::uint64_t seed = PhotoSequenceSettings{}.seed;
  double photoRoll = PhotoSequenceSettings{}.rotationDeg;
  std::string photoZoom = "0.85:1.15";  // PhotoSequenceSettings' 1 +- 0.15
  fs::path beside;                      // --beside: a second photo in the right half
  fs::path besideLandmarks;             // its points
  fs::path denseModel;
  fs::path denseVertices;
  int denseModes = IctDenseSettings{}.identityModes;
  std::optional<std::uint64_t> denseHeadSeed;
  fs::path contactSheet;
  int sheetFrames = 11;
  const CLI::Option* sizeOption = nullptr;
  const CLI::Option* yawOption = nullptr;
  const CLI::Option* pitchOption = nullptr;
  std::vector<const CLI::Option*>
      movingPhotoOptions;  // --frames, --seed, --photo-roll, --photo-zoom
};

// "A:B" or "A" (= "A:A"), degrees; nullopt if malformed.
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

CLI::Validator rangeValidator(double limit) {
  return CLI::Validator(
      [limit](std::string& text) -> std::string {
        const auto range = parseRange(text);
        if (!range) return "expected FROM:TO in degrees (e.g. 0:60 or -30:30), got '" + text + "'";
        if (std::abs(range->first) > limit || std::abs(range->second) > limit) {
          std::ostringstream message;
          message << "angles must be within -" << limit << ".." << limit << " degrees, got '"
                  << text << "'";
          return message.str();
        }
        return {};
      },
      "FROM:TO");
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

CLI::Validator sizeValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto size = parseSize(text);
        if (!size) return "expected WIDTHxHEIGHT, e.g. 640x480, got '" + text + "'";
        const auto [width, height] = *size;
        if (width < 16 || height < 16 || width > 8192 || height > 8192) {
          return "each side must be 16..8192 pixels, got '" + text + "'";
        }
        if (width % 2 != 0 || height % 2 != 0) {
          return "width and height must be even (video codecs need it), got '" + text + "'";
        }
        return {};
      },
      "WxH");
}

struct Subject {
  TexturedMesh mesh;
  LandmarkSet landmarks;
  SequenceSubject description;
  std::string name;
};

// A scan in model coordinates, loaded by core exactly as the trainer loads a manifest's scan
// (core/dataset: file units times --scale to mm, landmarks in the thesis25 scheme with 68-point
// files converted, levelled on the eyes, landmark 1 at the origin).
Subject loadScan(const SynthArgs& args) {
  const ScanSource source =
      scanFromOptions(args.mesh, args.landmarks, args.up, args.front, args.scale);
  TexturedSubject scan = loadScanSubject(source, Scheme::thesis25());
  Subject subject;
  subject.mesh = std::move(scan.mesh);
  subject.landmarks = std::move(scan.landmarks);
  subject.description.mesh = args.mesh.string();
  subject.description.landmarks = args.landmarks.string();
  subject.description.scale = args.scale;
  subject.name = args.mesh.filename().string();
  return subject;
}

// A procedural head, generated by core as a manifest's procedural entry is.
Subject makeHead(const SynthArgs& args) {
  const std::string expression = args.expression.empty() ? "neutral" : args.expression;
  ProceduralSource source;
  source.textureSize = args.textureSize;
  source.faceStepDegrees = args.faceStep;
  TexturedSubject head = makeProceduralSubject(*args.headSeed, expression, source);
  Subject subject;
  subject.mesh = std::move(head.mesh);
  subject.landmarks = std::move(head.landmarks);
  subject.description.headSeed = args.headSeed;
  subject.description.expression = expression;
  subject.description.faceStepDegrees = source.faceStepDegrees;
  subject.description.textureSize = source.textureSize;
  subject.name = "procedural head " + std::to_string(*args.headSeed) + " (" + expression + ")";
  return subject;
}

SequenceSettings toSettings(const SynthArgs& args) {
  SequenceSettings settings;
  const auto yaw = parseRange(args.yawRange);
  const auto pitch = parseRange(args.pitchRange);
  const auto size = parseSize(args.size);
  if (!size) throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, e.g. 640x480");
  settings.yawFromDeg = yaw->first;
  settings.yawToDeg = yaw->second;
  settings.pitchFromDeg = pitch->first;
  settings.pitchToDeg = pitch->second;
  settings.rollDeg = args.roll;
  settings.stepDeg = args.step;
  settings.order = args.sweep ? SequenceOrder::Sweep : SequenceOrder::Range;
  settings.width = size->first;
  settings.height = size->second;
  settings.interOcularPixels = args.faceSize;
  settings.verticalFovDeg = args.fov;
  settings.fps = args.fps;
  settings.supersample = args.supersample;
  settings.lighting.direction =
      Eigen::Vector3d(args.lightDir[0], args.lightDir[1], args.lightDir[2]);
  settings.lighting.ambient = args.ambient;
  settings.lighting.diffuse = args.diffuse;
  settings.backgroundImage = args.background;
  settings.validate();
  return settings;
}

// Progress lines on stderr at every 10% (CliProgress), for sequences of 30 frames or more.
constexpr int kProgressFrames = 30;

// --photo with --yaw-range: the photo's face profiled and turned in 3D.
void runTurnedPhotoSynth(const SynthArgs& args) {
  for (const CLI::Option* option : args.movingPhotoOptions) {
    if (option->count() > 0) {
      throw CLI::ValidationError(option->get_name(),
                                 "moves the photo in the image plane; with --yaw-range the face "
                                 "turns in 3D instead, leave it out");
    }
  }
  if (args.sizeOption != nullptr && args.sizeOption->count() > 0) {
    throw CLI::ValidationError("--size", "a turned photo keeps the photo's size");
  }
  if (!args.beside.empty()) {
    throw CLI::ValidationError("--beside",
                               "pairs photos moving in the image plane; a turned "
                               "photo is one face");
  }
  if (args.denseHeadSeed && !args.denseModel.empty()) {
    throw CLI::ValidationError("--dense-head-seed",
                               "give --dense-model or --dense-head-seed, not both");
  }
  if (!args.denseHeadSeed && (args.denseModel.empty() || args.denseVertices.empty())) {
    throw CLI::ValidationError(
        "--dense-model/--dense-vertices",
        "turning a photo needs the dense face: --dense-model (ICT-FaceKit archive or folder) and "
        "--dense-vertices (its thesis25 vertex table, tests/fixtures/ict-facekit/"
        "thesis25_vertices.json), or --dense-head-seed N (a procedural head's own mesh)");
  }
  TurnedPhotoSettings settings;
  const auto yaw = parseRange(args.yawRange);
  settings.yawFromDeg = yaw->first;
  settings.yawToDeg = yaw->second;
  settings.keepPhotoPitch = args.pitchOption == nullptr || args.pitchOption->count() == 0;
  if (!settings.keepPhotoPitch) {
    const auto pitch = parseRange(args.pitchRange);
    settings.pitchFromDeg = pitch->first;
    settings.pitchToDeg = pitch->second;
  }
  settings.stepDeg = args.step;
  settings.order = args.sweep ? SequenceOrder::Sweep : SequenceOrder::Range;
  settings.verticalFovDeg = args.fov;
  settings.fps = args.fps;
  settings.profile.supersample = args.supersample;
  settings.sheetFrames = args.contactSheet.empty() ? 0 : args.sheetFrames;
  settings.validate();
  if (!args.denseHeadSeed && !fs::exists(args.denseModel)) {
    throwInputError(args.denseModel, "file not found");
  }
  const cv::Mat photo = readImage(args.photo);
  const LandmarkSet points = readLandmarks(args.landmarks, &Scheme::thesis25());
  if (points.presentCount() < 4) {
    throwInputError(args.landmarks, "has " + std::to_string(points.presentCount()) +
                                        " thesis25 points; a profile needs at least 4");
  }

  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  InterruptScope interrupt;
  DenseFace face;
  std::string denseName;
  if (args.denseHeadSeed) {
    // A procedural head's own mesh, no modes: for trying the mode out without the ICT model
    // (the photo should then be of that head).
    ProceduralSource source;
    source.textureSize = args.textureSize;
    source.faceStepDegrees = args.faceStep;
    const TexturedSubject head = makeProceduralSubject(*args.denseHeadSeed, "neutral", source);
    face = denseFaceFromMesh(head.mesh, head.landmarks);
    denseName = "procedural head " + std::to_string(*args.denseHeadSeed);
  } else {
    const std::vector<int> vertices =
        readLandmarkVertexTable(args.denseVertices, "thesis25", Scheme::thesis25().size());
    IctDenseSettings dense;
    dense.identityModes = args.denseModes;
    try {
      face = denseFaceFromIct(
          loadIctMeshModel(args.denseModel, vertices, args.denseVertices, {}, &interrupt.token()),
          dense);
    } catch (const Cancelled&) {
      throw Error("cancelled, no sequence written");
    }
    denseName = args.denseModel.string();
  }
  const double loadSeconds = elapsed();
  const int frames = static_cast<int>(sequenceAngles([&] {
                                        SequenceSettings angles;
                                        angles.yawFromDeg = settings.yawFromDeg;
                                        angles.yawToDeg = settings.yawToDeg;
                                        angles.pitchFromDeg =
                                            settings.keepPhotoPitch ? 0.0 : settings.pitchFromDeg;
                                        angles.pitchToDeg =
                                            settings.keepPhotoPitch ? 0.0 : settings.pitchToDeg;
                                        angles.stepDeg = settings.stepDeg;
                                        angles.order = settings.order;
                                        return angles;
                                      }())
                                          .size());
  CliProgress progress(CliProgress::Style::Tenths, frames < kProgressFrames, "synth");
  const SequenceFiles files = SequenceFiles::inFolder(args.out, "." + args.format);
  TurnedPhotoSummary summary;
  try {
    summary = writeTurnedPhotoSequence(face, photo, points, settings,
                                       {args.photo.string(), args.landmarks.string(), denseName},
                                       files, progress.callback(), &interrupt.token());
  } catch (const Cancelled&) {
    throw Error("cancelled, no sequence written");
  }
  interrupt.release();
  if (!args.contactSheet.empty()) writeImage(args.contactSheet, summary.contactSheet);
  const PhotoProfile& profile = summary.profile;
  std::cout << std::fixed << std::setprecision(1) << "synth: " << summary.frames << " frames "
            << summary.frameSize.width << "x" << summary.frameSize.height << " of "
            << args.photo.string() << " turned, yaw " << settings.yawFromDeg << ".."
            << settings.yawToDeg << ", step " << settings.stepDeg
            << " deg; profile: " << profile.pointsFitted << " points fitted, rms "
            << std::setprecision(2) << profile.rmsPixels << " px, photo pose yaw "
            << std::setprecision(1) << degrees(profile.pose.yaw) << " pitch "
            << degrees(profile.pose.pitch) << " roll " << degrees(profile.pose.roll) << ", "
            << std::setprecision(0) << 100.0 * profile.mirroredShare << "% of triangles mirrored, "
            << 100.0 * profile.backgroundShare << "% on the background; " << summary.hiddenPoints
            << " hidden landmark-frames -> " << files.video.string()
            << " (+ truth.csv, truth-visibility.csv, sequence.json) in " << std::setprecision(1)
            << elapsed() << " s (dense face " << loadSeconds << " s)\n";
}

// --photo with --beside: two photos side by side, each moving on its own trajectory.
void runPhotoPairSynth(const SynthArgs& args, const PhotoSequenceSettings& settings,
                       const cv::Mat& left, const LandmarkSet& leftPoints) {
  if (args.beside.empty() || args.besideLandmarks.empty()) {
    throw CLI::ValidationError("--beside",
                               "a second photo needs both --beside and "
                               "--beside-landmarks");
  }
  const cv::Mat right = readImage(args.beside);
  const LandmarkSet rightPoints = readPhotoPoints(args.besideLandmarks);
  const auto start = std::chrono::steady_clock::now();
  InterruptScope interrupt;
  CliProgress progress(CliProgress::Style::Tenths, settings.frames < kProgressFrames, "synth");
  const SequenceFiles files = SequenceFiles::inFolder(args.out, "." + args.format);
  PhotoPairSummary summary;
  try {
    summary = writePhotoPairSequence(left, leftPoints, right, rightPoints, settings,
                                     {args.photo.string(), args.landmarks.string()},
                                     {args.beside.string(), args.besideLandmarks.string()}, files,
                                     progress.callback(), &interrupt.token());
  } catch (const Cancelled&) {
    throw Error("cancelled, no sequence written");
  }
  interrupt.release();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "synth: " << summary.frames << " frames " << summary.frameSize.width << "x"
            << summary.frameSize.height << " of " << args.photo.string() << " (seed "
            << settings.seed << ") beside " << args.beside.string() << " (seed "
            << settings.seed + 1 << ") -> " << files.video.string()
            << " (+ truth.csv with a face column, sequence.json) in " << std::fixed
            << std::setprecision(1) << seconds << " s\n";
}

// --photo: the photo moving in the image plane, its landmarks moved with it.
void runPhotoSynth(const SynthArgs& args) {
  if (!args.mesh.empty() || args.headSeed) {
    throw CLI::ValidationError("--photo", "give --photo, --mesh or --head-seed, only one");
  }
  if (args.landmarks.empty()) {
    throw CLI::ValidationError("--photo", "a photo needs its points: --landmarks F.pts");
  }
  if (!args.expression.empty()) {
    throw CLI::ValidationError("--expression", "applies to procedural heads (--head-seed) only");
  }
  if (args.yawOption != nullptr && args.yawOption->count() > 0) {
    runTurnedPhotoSynth(args);
    return;
  }
  if (args.pitchOption != nullptr && args.pitchOption->count() > 0) {
    throw CLI::ValidationError("--pitch-range", "with --photo, give --yaw-range too");
  }
  PhotoSequenceSettings settings;
  settings.frames = args.frames;
  settings.seed = args.seed;
  settings.fps = args.fps;
  settings.rotationDeg = args.photoRoll;
  const auto zoom = parseRange(args.photoZoom);
  if (!zoom || !(zoom->first > 0.0) || zoom->second < zoom->first) {
    throw CLI::ValidationError("--photo-zoom",
                               "expected SMALLEST:LARGEST relative sizes, e.g. 0.6:1.6");
  }
  settings.scaleCentre = 0.5 * (zoom->first + zoom->second);
  settings.scaleRange = 0.5 * (zoom->second - zoom->first);
  if (args.sizeOption != nullptr && args.sizeOption->count() > 0) {
    const auto size = parseSize(args.size);
    if (!size) throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, e.g. 640x480");
    settings.width = size->first;
    settings.height = size->second;
  }
  settings.validate();
  const cv::Mat photo = readImage(args.photo);
  const LandmarkSet points = readPhotoPoints(args.landmarks);
  if (!args.beside.empty() || !args.besideLandmarks.empty()) {
    runPhotoPairSynth(args, settings, photo, points);
    return;
  }

  const auto start = std::chrono::steady_clock::now();
  InterruptScope interrupt;
  CliProgress progress(CliProgress::Style::Tenths, settings.frames < kProgressFrames, "synth");
  const SequenceFiles files = SequenceFiles::inFolder(args.out, "." + args.format);
  PhotoSequenceSummary summary;
  try {
    summary =
        writePhotoSequence(photo, points, settings, {args.photo.string(), args.landmarks.string()},
                           files, progress.callback(), &interrupt.token());
  } catch (const Cancelled&) {
    throw Error("cancelled, no sequence written");
  }
  interrupt.release();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "synth: " << summary.frames << " frames " << summary.frameSize.width << "x"
            << summary.frameSize.height << " of " << args.photo.string() << " (seed "
            << settings.seed << ", face " << std::fixed << std::setprecision(1) << summary.face.size
            << " px, points " << points.presentCount() << "/" << points.size() << ") -> "
            << files.video.string() << " (+ truth.csv, truth-visibility.csv, sequence.json) in "
            << seconds << " s\n";
}

void runSynth(const SynthArgs& args) {
  if (!args.photo.empty()) {
    runPhotoSynth(args);
    return;
  }
  const bool scan = !args.mesh.empty() || !args.landmarks.empty();
  if (scan && args.headSeed) {
    throw CLI::ValidationError("--head-seed",
                               "give either --mesh and --landmarks (a scan) or --head-seed (a "
                               "procedural head), not both");
  }
  if (!scan && !args.headSeed) {
    throw CLI::ValidationError("--mesh/--head-seed",
                               "give --mesh and --landmarks (a scan), --head-seed N (a "
                               "procedural head) or --photo and --landmarks (a photo)");
  }
  if (scan && (args.mesh.empty() || args.landmarks.empty())) {
    throw CLI::ValidationError("--mesh/--landmarks", "a scan needs both --mesh and --landmarks");
  }
  if (scan && !args.expression.empty()) {
    throw CLI::ValidationError("--expression",
                               "applies to procedural heads (--head-seed) only; a scan has the "
                               "expression it was captured with");
  }
  const SequenceSettings settings = toSettings(args);
  // Inputs that are quick to check, before the slow part (generating or loading the head).
  if (!args.background.empty() && !fs::exists(args.background)) {
    throwInputError(args.background, "file not found");
  }
  const int frames = static_cast<int>(sequenceAngles(settings).size());

  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const Subject subject = scan ? loadScan(args) : makeHead(args);
  const double loadSeconds = elapsed();

  InterruptScope interrupt;
  CliProgress progress(CliProgress::Style::Tenths, frames < kProgressFrames, "synth");
  const SequenceFiles files = SequenceFiles::inFolder(args.out, "." + args.format);
  SequenceSummary summary;
  try {
    summary =
        writeSyntheticSequence(subject.mesh, subject.landmarks, Scheme::thesis25(), settings,
                               subject.description, files, progress.callback(), &interrupt.token());
  } catch (const Cancelled&) {
    throw Error("cancelled, no sequence written");
  }
  interrupt.release();
  const double renderSeconds = elapsed() - loadSeconds;

  std::ostringstream angles;
  angles << "yaw " << settings.yawFromDeg << ".." << settings.yawToDeg;
  if (settings.pitchFromDeg != settings.pitchToDeg) {
    angles << ", pitch " << settings.pitchFromDeg << ".." << settings.pitchToDeg;
  } else if (settings.pitchFromDeg != 0.0) {
    angles << ", pitch " << settings.pitchFromDeg;
  }
  angles << (settings.order == SequenceOrder::Sweep ? " (sweep from and back to frontal)" : "")
         << ", step " << settings.stepDeg << " deg";
  std::cout << "synth: " << summary.frames << " frames " << settings.width << "x" << settings.height
            << " of " << subject.name << ", " << angles.str() << ", face "
            << settings.interOcularPixels << " px, " << summary.hiddenPoints
            << " hidden landmark-frames -> " << files.video.string() << " (+ truth.csv, "
            << "truth-visibility.csv, sequence.json) in " << std::fixed << std::setprecision(1)
            << renderSeconds << " s (" << summary.frames / std::max(renderSeconds, 1e-9)
            << " frames/s)\n";
}

}  // namespace

void addSynthCommand(CLI::App& root) {
  auto args = std::make_shared<SynthArgs>();
  CLI::App* cmd = root.add_subcommand(
      "synth",
      "Render a synthetic test sequence (thesis 5.2): a head turning step degrees per frame, with "
      "exact ground-truth landmarks and their visibility");
  cmd->add_option("--out", args->out,
                  "Output folder: sequence.avi (or .mp4), truth.csv, truth-visibility.csv, "
                  "sequence.json")
      ->required();
  cmd->add_option("--mesh", args->mesh, "Textured scan: OBJ (+MTL, image), PLY, glTF/GLB");
  cmd->add_option("--landmarks", args->landmarks,
                  "The scan's 3D landmarks, or the photo's 2D points (.pts/.ljson/.csv, 25 thesis "
                  "or 68 iBUG points)");
  cmd->add_option("--photo", args->photo,
                  "Use this annotated photo moving in the image plane (translation, scale, "
                  "rotation, brightness, contrast) instead of a head turning");
  args->movingPhotoOptions.push_back(
      cmd->add_option("--frames", args->frames, "With --photo: number of frames")
          ->check(CLI::Range(1, 100000))
          ->capture_default_str());
  args->movingPhotoOptions.push_back(
      cmd->add_option("--seed", args->seed, "With --photo: seed of the random smooth motion")
          ->capture_default_str());
  args->movingPhotoOptions.push_back(
      cmd->add_option("--photo-roll", args->photoRoll,
                      "With --photo: largest in-plane rotation of the face, degrees either way")
          ->check(CLI::Range(0.0, 180.0))
          ->capture_default_str());
  args->movingPhotoOptions.push_back(
      cmd->add_option("--photo-zoom", args->photoZoom,
                      "With --photo: SMALLEST:LARGEST relative size of the face (e.g. 0.6:1.6)")
          ->capture_default_str());
  cmd->add_option("--beside", args->beside,
                  "With --photo: a second annotated photo in the right half, moving on its own "
                  "trajectory (seed + 1); the truth has a face column (0 left, 1 right)");
  cmd->add_option("--beside-landmarks", args->besideLandmarks, "With --beside: its points");
  cmd->add_option("--dense-model", args->denseModel,
                  "With --photo and --yaw-range: the dense face fitted to the photo's points "
                  "(ICT-FaceKit archive or folder)");
  cmd->add_option("--dense-vertices", args->denseVertices,
                  "With --dense-model: its thesis25 landmark vertex table "
                  "(tests/fixtures/ict-facekit/thesis25_vertices.json)");
  cmd->add_option("--dense-head-seed", args->denseHeadSeed,
                  "With --photo and --yaw-range, instead of --dense-model: the procedural head of "
                  "this seed as the dense face (its own mesh, no modes; a photo of that head)");
  cmd->add_option("--contact-sheet", args->contactSheet,
                  "With --photo and --yaw-range: also write a contact sheet (PNG) of the photo and "
                  "--sheet-frames frames with their visible truth points");
  cmd->add_option("--sheet-frames", args->sheetFrames, "Frames on the contact sheet")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->add_option("--dense-modes", args->denseModes,
                  "With --dense-model: identity components fitted (the model has 100)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  cmd->add_option("--up", args->up, "The scan file's up axis")->capture_default_str();
  cmd->add_option("--front", args->front, "The scan file's axis out of the face")
      ->capture_default_str();
  cmd->add_option("--scale", args->scale,
                  "The scan file's units in millimetres (mesh and landmarks are multiplied by it, "
                  "as a manifest's scans[i].scale)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--head-seed", args->headSeed,
                  "Use the procedural head of this seed instead of a scan");
  std::string names;
  for (const auto& name : expressionPresetNames()) names += (names.empty() ? "" : ", ") + name;
  cmd->add_option("--expression", args->expression,
                  "Procedural head's expression: " + names + " (default neutral)");
  cmd->add_option("--texture-size", args->textureSize, "Procedural head's texture size")
      ->check(CLI::Range(256, 8192))
      ->capture_default_str();
  cmd->add_option("--face-step", args->faceStep, "Procedural head's mesh step in degrees")
      ->check(CLI::Range(0.3, 3.0))
      ->capture_default_str();
  args->yawOption =
      cmd->add_option("--yaw-range", args->yawRange,
                      "Yaw FROM:TO in degrees, either direction (positive: nose towards image "
                      "+x); write --yaw-range=-60:0 for a negative start. With --photo: turn the "
                      "photo's face in 3D through a dense face fitted to its points")
          ->check(rangeValidator(180.0))
          ->capture_default_str();
  args->pitchOption =
      cmd->add_option("--pitch-range", args->pitchRange,
                      "Pitch FROM:TO in degrees (positive: nose down), or one fixed value (with "
                      "--photo --yaw-range: default the photo's own pitch)")
          ->check(rangeValidator(90.0))
          ->capture_default_str();
  cmd->add_option("--roll", args->roll, "Fixed roll in degrees")
      ->check(CLI::Range(-180.0, 180.0))
      ->capture_default_str();
  cmd->add_option("--step", args->step,
                  "Degrees per frame (the larger of the yaw and pitch change)")
      ->check(CLI::Range(0.01, 90.0))
      ->capture_default_str();
  cmd->add_flag("--sweep", args->sweep,
                "Go frontal -> FROM -> TO -> frontal instead of FROM -> TO");
  args->sizeOption =
      cmd->add_option("--size", args->size,
                      "Image size WIDTHxHEIGHT (even); with --photo default the photo's size "
                      "(rounded down to even)")
          ->check(sizeValidator())
          ->capture_default_str();
  cmd->add_option("--face-size", args->faceSize,
                  "Distance between the eye centres in the frontal view, pixels")
      ->check(CLI::Range(4.0, 8000.0))
      ->capture_default_str();
  cmd->add_option("--fov", args->fov, "Vertical field of view in degrees")
      ->check(CLI::Range(1.0, 150.0))
      ->capture_default_str();
  cmd->add_option("--fps", args->fps, "Frame rate written into the video")
      ->check(CLI::Range(0.1, 1000.0))
      ->capture_default_str();
  cmd->add_option("--supersample", args->supersample,
                  "Render at N times the size and average down (anti-aliasing)")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  cmd->add_option("--light-dir", args->lightDir,
                  "Direction towards the light, eye space X,Y,Z (as clm3d render)")
      ->expected(3)
      ->delimiter(',')
      ->default_str("0.3,0.4,1");
  cmd->add_option("--ambient", args->ambient, "Ambient light intensity")
      ->check(CLI::Range(0.0, 2.0))
      ->capture_default_str();
  cmd->add_option("--diffuse", args->diffuse, "Directional light intensity")
      ->check(CLI::Range(0.0, 2.0))
      ->capture_default_str();
  cmd->add_option("--background", args->background,
                  "Background image (scaled to cover the frame); default plain grey");
  cmd->add_option("--format", args->format,
                  "Video format: avi or mkv (FFV1, lossless), mp4 (MPEG-4, lossy)")
      ->check(CLI::IsMember({"avi", "mkv", "mp4"}))
      ->capture_default_str();
  cmd->callback([args] { runSynth(*args); });
}

}  // namespace clm3d::cli
