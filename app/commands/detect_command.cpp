// clm3d detect: face detectors measured on annotated photos (core/detect/detector_evaluation):
// faces found, wrong faces picked, no face, time per image; with --calibrate the box calibration
// measured on the photos; with --model the start error of the mean shape placed in the box.
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/detect/detector_evaluation.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/model/model_file.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct DetectArgs {
  fs::path images, truthDir, model, out, poses;
  std::string yawBands = "0,30,60,90";
  std::vector<std::string> detectors;
  std::vector<fs::path> calibrations;
  bool calibrate = false;
  std::string calibrateTo = "eyes";
  bool startError = false;
  bool quiet = false;
  bool json = false;
  DetectorEvaluationSettings settings;
};

void runDetect(const DetectArgs& args) {
  if (args.startError && args.model.empty()) {
    throw CLI::ValidationError("--start-error", "needs --model M (its mean shape is placed)");
  }
  if (!args.calibrations.empty() && !args.startError) {
    throw CLI::ValidationError("--calibration", "goes with --start-error");
  }
  DetectorEvaluationSettings settings = args.settings;
  if (args.calibrateTo == "mean-shape") {
    if (args.model.empty()) {
      throw CLI::ValidationError("--calibrate-to", "mean-shape needs --model M");
    }
    settings.calibrationTarget = CalibrationTarget::MeanShape;
  }
  std::vector<DetectorKind> kinds;
  for (const std::string& name : args.detectors) {
    if (name == "all") {
      kinds.push_back(DetectorKind::Cascade);
      if (FaceDetector::available(DetectorKind::DlibHog)) kinds.push_back(DetectorKind::DlibHog);
    } else {
      kinds.push_back(parseDetectorKind(name));
    }
  }
  const std::vector<fs::path> images = listImages(args.images);
  const std::vector<fs::path> truths = findTruthFiles(images, args.truthDir);
  std::vector<CalibrationSet> sets;
  std::optional<ClmModel> model;
  if (!args.model.empty()) {
    model = loadModel(args.model);
    sets.push_back(CalibrationSet{});
    for (const fs::path& file : args.calibrations) sets.push_back(readCalibrationSet(file));
  }
  ProgressCallback progress;
  if (!args.quiet) {
    progress = [](double, std::string_view stage) { std::cerr << stage << '\n'; };
  }
  DetectorEvaluationReport report =
      evaluateDetectors(images, truths, kinds, settings, model ? &*model : nullptr, sets, progress);
  if (!args.startError) {
    for (DetectorEvaluation& e : report.detectors) e.startErrors.clear();
  }
  if (!args.poses.empty()) {
    const std::vector<double> edges = parseBandEdges(args.yawBands);
    const std::vector<std::string> labels = yawBandLabels(edges);
    const std::map<std::string, double> poses = readPoseCsv(args.poses);
    std::vector<int> bands;
    for (const fs::path& image : images) {
      const auto it = poses.find(image.stem().string());
      bands.push_back(it == poses.end() ? -1 : yawBandOf(it->second, edges));
    }
    addDetectionBands(report, bands, labels, "yaw from " + args.poses.string());
  }
  const std::string json = formatDetectorEvaluationJson(report, args.calibrate);
  std::cout << (args.json ? json : formatDetectorEvaluationText(report, args.calibrate));
  if (!args.out.empty()) {
    writeTextAtomically(args.out, json);
    (args.json ? std::cerr : std::cout) << "report: " << args.out.string() << '\n';
  }
}

}  // namespace

void addDetectCommand(CLI::App& root) {
  auto args = std::make_shared<DetectArgs>();
  CLI::App* command = root.add_subcommand(
      "detect",
      "Measure face detectors on annotated photos: annotated faces found, wrong faces picked, no "
      "face, time per image; the box calibration (--calibrate) and the start error (--model "
      "--start-error)");
  command
      ->add_option("--images", args->images,
                   "Folder of images, or a list file with one image path per line")
      ->required();
  command->add_option("--truth-dir", args->truthDir,
                      "Folder of the truth STEM.pts (.ljson, .csv; 68 or 25 points, or another "
                      "scheme such as AFLW's 21, whose visible points' box the face's box must "
                      "hold the centre of); default: beside each image");
  command->add_option("--poses", args->poses,
                      "CSV with columns image,yaw_deg (e.g. AFLW's index.csv): also count per "
                      "|yaw| band");
  command
      ->add_option("--yaw-bands", args->yawBands,
                   "With --poses: edges of the |yaw| bands in degrees, ascending")
      ->capture_default_str();
  args->detectors = {"all"};
  command
      ->add_option("--detector", args->detectors,
                   "cascade, dlib or all (repeat to compare; default all available)")
      ->capture_default_str();
  command
      ->add_option("--min-face", args->settings.detector.minFaceSize,
                   "smallest face box searched, pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  command
      ->add_option("--max-side", args->settings.detector.maxImageSide,
                   "search images reduced to this larger side (0 = full size)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  command
      ->add_option("--border", args->settings.detector.borderShare,
                   "search each image inside a grey border of this share of its larger side")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  command
      ->add_option("--min-neighbours", args->settings.detector.minNeighbours,
                   "cascade: raw detections a box needs")
      ->capture_default_str()
      ->check(CLI::Range(1, 50));
  command
      ->add_option("--profile-min-neighbours", args->settings.detector.profileMinNeighbours,
                   "cascade: raw detections a profile box needs")
      ->capture_default_str()
      ->check(CLI::Range(1, 50));
  command
      ->add_option("--profile-cascade", args->settings.detector.profileCascade,
                   "cascade: the profile cascade file (relative to /usr/share/opencv4 or "
                   "absolute)")
      ->capture_default_str();
  command
      ->add_option("--second-profile-cascade", args->settings.detector.secondProfileCascade,
                   "cascade: a second profile cascade run beside the first (empty: none)")
      ->capture_default_str();
  CLI::Option* noProfiles = command->add_flag("!--no-profiles", args->settings.detector.profiles,
                                              "cascade: frontal cascade only");
  command
      ->add_flag("--profiles-everywhere", args->settings.detector.profilesEverywhere,
                 "cascade: run the profile cascade over the whole image even where the frontal "
                 "cascade found faces (default: only around them)")
      ->excludes(noProfiles);
  command->add_flag("!--no-dlib-fallback", args->settings.detector.dlibFallback,
                    "cascade: no dlib HOG search where the cascades find no face (default: "
                    "dlib searches there when the build has it)");
  command->add_flag("!--no-dlib-agreement", args->settings.detector.dlibAgreement,
                    "cascade: rank its boxes by score alone (default, when the build has dlib: "
                    "faces dlib's HOG also finds first, then the largest)");
  command
      ->add_option("--dlib-threshold", args->settings.detector.dlibThreshold,
                   "dlib: added to its detection threshold (negative finds more faces and more "
                   "false ones)")
      ->capture_default_str();
  command->add_flag("--calibrate", args->calibrate,
                    "report the box calibration measured on the photos (medians)");
  command
      ->add_option("--calibrate-to", args->calibrateTo,
                   "eyes: the truth's eye centres; mean-shape: the model's mean shape fitted to "
                   "the truth (what stateFromBox places)")
      ->capture_default_str()
      ->check(CLI::IsMember({"eyes", "mean-shape"}));
  command->add_option("--model", args->model,
                      "Model whose mean shape --start-error places; with --calibrate it also "
                      "gives each truth's yaw and frontal eye distance");
  command->add_flag("--start-error", args->startError,
                    "report the error of stateFromBox's start in the annotated face's box "
                    "(thesis points 1-18 and 22 / true eye distance)");
  command->add_option("--calibration", args->calibrations,
                      "--start-error also with the calibration of this `detect --calibrate "
                      "--out` report (repeatable)");
  command
      ->add_option("--frontal-yaw", args->settings.frontalYawDeg,
                   "--calibrate with --model: frontal boxes count on faces within this |yaw|")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 90.0));
  command
      ->add_option("--fov", args->settings.verticalFovDeg,
                   "vertical field of view of the camera, degrees (with --model)")
      ->capture_default_str()
      ->check(CLI::Range(5.0, 150.0));
  command->add_option("--out", args->out, "write the report as JSON");
  command->add_flag("--json", args->json, "print the report as JSON");
  command->add_flag("--quiet", args->quiet, "no progress line per image on stderr");
  command->callback([args] { runDetect(*args); });
}

}  // namespace clm3d::cli
