#include "core/eval/detect_request.hpp"

#include <map>
#include <optional>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/model/model_file.hpp"

namespace clm3d {
namespace detect_request_detail {

namespace fs = std::filesystem;
using R = DetectRequest;
using D = FaceDetectorSettings;

// An option of the detector's own settings.
template <typename Make, typename Field>
Option<R> detector(Make make, OptionSpec spec, Field D::*field) {
  return make(std::move(spec), [field](R& r) -> Field& { return r.settings.detector.*field; });
}

std::vector<Option<R>> makeOptions() {
  const auto path = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(commandOption(name, help), field);
  };
  const auto integer = [](OptionSpec spec, auto field) {
    return integerOption<R>(std::move(spec), field);
  };
  const auto real = [](OptionSpec spec, auto field) {
    return realOption<R>(std::move(spec), field);
  };
  const auto text = [](OptionSpec spec, auto field) {
    return textOption<R>(std::move(spec), field);
  };
  const auto noFlag = [](OptionSpec spec, auto field) {
    return flagOption<R>(std::move(spec), field, true);
  };
  const auto flag = [](OptionSpec spec, auto field) {
    return flagOption<R>(std::move(spec), field);
  };
  return {
      textOption<R>(
          requiredOption("images", "Folder of images, or a list file with one image path per line"),
          &R::images),
      path("truth-dir",
           "Folder of the truth STEM.pts (.ljson, .csv; 68 or 25 points, or another scheme such "
           "as AFLW's 21, whose visible points' box the face's box must hold the centre of); "
           "default: beside each image",
           &R::truthDir),
      path("poses",
           "CSV with columns image,yaw_deg (e.g. AFLW's index.csv): also count per |yaw| band",
           &R::poses),
      textOption<R>(commandOption("yaw-bands",
                                  "With --poses: edges of the |yaw| bands in degrees, ascending"),
                    &R::yawBands),
      textListOption<R>(commandOption("detector",
                                      "cascade, dlib or all (repeat to compare; "
                                      "default all available)"),
                        &R::detectors),
      detector(integer, commandOption("min-face", "smallest face box searched, pixels", 8, 4096),
               &D::minFaceSize),
      detector(
          integer,
          commandOption("max-side", "search images reduced to this larger side (0 = full size)", 0,
                        100000),
          &D::maxImageSide),
      detector(real,
               commandOption("border",
                             "search each image inside a grey border of this share of its larger "
                             "side",
                             0.0, 1.0),
               &D::borderShare),
      detector(integer,
               commandOption("min-neighbours", "cascade: raw detections a box needs", 1, 50),
               &D::minNeighbours),
      detector(integer,
               commandOption("profile-min-neighbours",
                             "cascade: raw detections a profile box needs", 1, 50),
               &D::profileMinNeighbours),
      detector(text,
               commandOption("profile-cascade",
                             "cascade: the profile cascade file (relative to /usr/share/opencv4 "
                             "or absolute)"),
               &D::profileCascade),
      detector(text,
               commandOption("second-profile-cascade",
                             "cascade: a second profile cascade run beside the first (empty: "
                             "none)"),
               &D::secondProfileCascade),
      detector(noFlag, commandOption("no-profiles", "cascade: frontal cascade only"), &D::profiles),
      detector(flag,
               commandOption("profiles-everywhere",
                             "cascade: run the profile cascade over the whole image even where "
                             "the frontal cascade found faces (default: only around them)"),
               &D::profilesEverywhere),
      detector(noFlag,
               commandOption("no-dlib-fallback",
                             "cascade: no dlib HOG search where the cascades find no face "
                             "(default: dlib searches there when the build has it)"),
               &D::dlibFallback),
      detector(noFlag,
               commandOption("no-dlib-agreement",
                             "cascade: rank its boxes by score alone (default, when the build has "
                             "dlib: faces dlib's HOG also finds first, then the largest)"),
               &D::dlibAgreement),
      detector(real,
               commandOption("dlib-threshold",
                             "dlib: added to its detection threshold (negative finds more faces "
                             "and more false ones)",
                             -100.0, 100.0),
               &D::dlibThreshold),
      flagOption<R>(
          commandOption("calibrate", "report the box calibration measured on the photos (medians)"),
          &R::calibrate),
      textChoiceOption<R>(commandOption("calibrate-to",
                                        "eyes: the truth's eye centres; mean-shape: the model's "
                                        "mean shape fitted to the truth (what stateFromBox "
                                        "places)"),
                          &R::calibrateTo, {"eyes", "mean-shape"}),
      path("model",
           "Model whose mean shape --start-error places; with --calibrate it also gives each "
           "truth's yaw and frontal eye distance",
           &R::model),
      flagOption<R>(commandOption("start-error",
                                  "report the error of stateFromBox's start in the annotated "
                                  "face's box (thesis points 1-18 and 22 / true eye distance)"),
                    &R::startError),
      textListOption<R>(commandOption("calibration",
                                      "--start-error also with the calibration of this `detect "
                                      "--calibrate --out` report (repeatable)"),
                        &R::calibrations),
      realOption<R>(commandOption("frontal-yaw",
                                  "--calibrate with --model: frontal boxes count on faces within "
                                  "this |yaw|",
                                  0.0, 90.0),
                    [](R& r) -> double& { return r.settings.frontalYawDeg; }),
      realOption<R>(
          commandOption("fov", "vertical field of view of the camera, degrees (with --model)", 5.0,
                        150.0),
          [](R& r) -> double& { return r.settings.verticalFovDeg; }),
      path("out", "write the report as JSON", &R::out),
      flagOption<R>(commandOption("json", "print the report as JSON"), &R::json),
      flagOption<R>(commandOption("quiet", "no progress line per image on stderr"), &R::quiet),
  };
}

std::vector<DetectorKind> detectorKinds(const std::vector<std::string>& names) {
  std::vector<DetectorKind> kinds;
  for (const std::string& name : names) {
    if (name == "all") {
      kinds.push_back(DetectorKind::Cascade);
      if (FaceDetector::available(DetectorKind::DlibHog)) kinds.push_back(DetectorKind::DlibHog);
    } else {
      kinds.push_back(parseDetectorKind(name));
    }
  }
  return kinds;
}

}  // namespace detect_request_detail

const std::vector<Option<DetectRequest>>& detectOptions() {
  static const std::vector<Option<DetectRequest>> table = detect_request_detail::makeOptions();
  return table;
}

CommandReport runDetect(const DetectRequest& args, const ProgressCallback& progress) {
  if (!args.settings.detector.profiles && args.settings.detector.profilesEverywhere) {
    throw UsageError("--profiles-everywhere", "excludes --no-profiles");
  }
  if (args.startError && args.model.empty()) {
    throw UsageError("--start-error", "needs --model M (its mean shape is placed)");
  }
  if (!args.calibrations.empty() && !args.startError) {
    throw UsageError("--calibration", "goes with --start-error");
  }
  DetectorEvaluationSettings settings = args.settings;
  if (args.calibrateTo == "mean-shape") {
    if (args.model.empty()) throw UsageError("--calibrate-to", "mean-shape needs --model M");
    settings.calibrationTarget = CalibrationTarget::MeanShape;
  }
  const std::vector<DetectorKind> kinds = detect_request_detail::detectorKinds(args.detectors);
  const std::vector<std::filesystem::path> images = listImages(args.images);
  const std::vector<std::filesystem::path> truths = findTruthFiles(images, args.truthDir);
  std::vector<CalibrationSet> sets;
  std::optional<ClmModel> model;
  if (!args.model.empty()) {
    model = loadModel(args.model);
    sets.push_back(CalibrationSet{});
    for (const std::filesystem::path& file : args.calibrations)
      sets.push_back(readCalibrationSet(file));
  }
  DetectorEvaluationReport report =
      evaluateDetectors(images, truths, kinds, settings, model ? &*model : nullptr, sets,
                        args.quiet ? ProgressCallback{} : progress);
  if (!args.startError) {
    for (DetectorEvaluation& e : report.detectors) e.startErrors.clear();
  }
  if (!args.poses.empty()) {
    const std::vector<double> edges = parseBandEdges(args.yawBands);
    const std::vector<std::string> labels = yawBandLabels(edges);
    const std::map<std::string, double> poses = readPoseCsv(args.poses);
    std::vector<int> bands;
    for (const std::filesystem::path& image : images) {
      const auto it = poses.find(image.stem().string());
      bands.push_back(it == poses.end() ? -1 : yawBandOf(it->second, edges));
    }
    addDetectionBands(report, bands, labels, "yaw from " + args.poses.string());
  }
  const std::string json = formatDetectorEvaluationJson(report, args.calibrate);
  CommandReport output(args.json ? json : formatDetectorEvaluationText(report, args.calibrate));
  output.notesToStderr = args.json;
  if (!args.out.empty()) {
    writeTextAtomically(args.out, json);
    output.notes = "report: " + args.out.string() + '\n';
  }
  return output;
}

}  // namespace clm3d
