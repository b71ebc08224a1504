#include "core/detect/detector_evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"
#include "core/fit/shape_projector.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/scheme/scheme_map.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

double median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Nearest-rank percentile (p in 0..100).
double percentile(std::vector<double> v, double p) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(v.size())));
  return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return kNaN;
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double sd(const std::vector<double>& v) {
  if (v.size() < 2) return kNaN;
  const double m = mean(v);
  double sum = 0.0;
  for (double x : v) sum += (x - m) * (x - m);
  return std::sqrt(sum / static_cast<double>(v.size() - 1));
}

struct Samples {
  std::vector<double> ratio, x, y, yaw;
  void add(double r, double ox, double oy, double absYaw) {
    ratio.push_back(r);
    x.push_back(ox);
    y.push_back(oy);
    if (std::isfinite(absYaw)) yaw.push_back(absYaw);
  }
  CalibrationEstimate estimate(bool profile) const {
    CalibrationEstimate e;
    e.faces = static_cast<int>(ratio.size());
    if (ratio.empty()) return e;
    e.median.iodPerWidth = median(ratio);
    e.median.eyeOffsetX = median(x);
    e.median.eyeOffsetY = median(y);
    e.median.yawDeg = profile && !yaw.empty() ? median(yaw) : 0.0;
    e.sdIodPerWidth = sd(ratio);
    e.sdEyeOffsetX = sd(x);
    e.sdEyeOffsetY = sd(y);
    return e;
  }
};

// What a model says about a truth face: its yaw and the eye distance it would have if frontal at
// its depth (as box_calibration_test.cpp measures the real photos).
// With CalibrationTarget::MeanShape, iodFrontal and eyeMid are the mean shape's.
struct TruthPose {
  double yawDeg = kNaN;
  double iodFrontal = kNaN;
  Eigen::Vector2d eyeMid = Eigen::Vector2d::Zero();
};

TruthPose truthPose(const ClmModel& model, const Camera& camera, const TruthFace& truth,
                    const DetectorEvaluationSettings& settings) {
  const int n = model.shape.pointCount();
  const bool meanShape = settings.calibrationTarget == CalibrationTarget::MeanShape;
  Eigen::Matrix2Xd points = Eigen::Matrix2Xd::Zero(2, n);
  std::vector<bool> present(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    if (!truth.points.has(i)) continue;
    points.col(i) = truth.points.point(i).head<2>();
    present[static_cast<std::size_t>(i)] =
        !meanShape || std::find(settings.startPoints.begin(), settings.startPoints.end(), i) !=
                          settings.startPoints.end();
  }
  PointsFitSettings fit;
  // The mean shape: a prior weight so large that the shape coefficients stay 0 and the scale 1,
  // leaving pose and depth to the points.
  if (meanShape) fit.pointSigmaPixels = 1e5;
  FitState state = stateFromPoints(model, camera, points, present, fit);
  if (meanShape) {
    state.shape.setZero();
    state.pose.scale = 1.0;
  }
  const auto [a, b] = model.scheme().normalisationPair();
  const Eigen::Matrix3Xd eye = state.pose.toEye(Eigen::Matrix3Xd(model.shape.shape(state.shape)));
  const double depth = -0.5 * (eye(2, a) + eye(2, b));
  TruthPose pose;
  pose.yawDeg = degrees(state.pose.yaw);
  pose.iodFrontal = camera.focalX() * (eye.col(a) - eye.col(b)).norm() / depth;
  const Eigen::Matrix2Xd projected = projectShape(model.shape, camera, state);
  pose.eyeMid = 0.5 * (projected.col(a) + projected.col(b));
  return pose;
}

double startError(const ClmModel& model, const Camera& camera, const FaceBox& box,
                  const BoxCalibration& calibration, const TruthFace& truth,
                  const std::vector<int>& scored) {
  const Eigen::Matrix2Xd placed =
      projectState(model, camera, stateFromBox(model, camera, box, calibration));
  double sum = 0.0;
  int count = 0;
  for (const int i : scored) {
    if (i >= placed.cols() || !truth.points.has(i)) continue;
    sum += (placed.col(i) - truth.points.point(i).head<2>()).norm();
    ++count;
  }
  return count > 0 ? sum / count / truth.iod : kNaN;
}

json number(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

json calibrationJson(const CalibrationEstimate& e, bool profile) {
  json j = {{"faces", e.faces},
            {"iod_per_width", number(e.faces ? e.median.iodPerWidth : kNaN)},
            {"eye_offset_x", number(e.faces ? e.median.eyeOffsetX : kNaN)},
            {"eye_offset_y", number(e.faces ? e.median.eyeOffsetY : kNaN)},
            {"sd_iod_per_width", number(e.sdIodPerWidth)},
            {"sd_eye_offset_x", number(e.sdEyeOffsetX)},
            {"sd_eye_offset_y", number(e.sdEyeOffsetY)}};
  if (profile) j["yaw_deg"] = number(e.faces ? e.median.yawDeg : kNaN);
  return j;
}

}  // namespace

Eigen::Vector2d TruthFace::anchor() const {
  if (hasEyes()) return eyeMid;
  return {visibleBox.x + 0.5 * visibleBox.width, visibleBox.y + 0.5 * visibleBox.height};
}

TruthFace readTruthFace(const fs::path& path) {
  LandmarkSet raw = readLandmarks(path);
  TruthFace face;
  // AFLW writes an invisible point as "-1 -1" (1-based), read as (-2, -2): such a point is missing.
  if (path.extension() == ".pts" && raw.size() != 68 && raw.size() != 25) {
    for (int i = 0; i < raw.size(); ++i) {
      if (raw.has(i) && raw.point(i).x() == -2.0 && raw.point(i).y() == -2.0) raw.setMissing(i);
    }
  }
  double minX = std::numeric_limits<double>::infinity(), minY = minX;
  double maxX = -minX, maxY = -minX;
  for (int i = 0; i < raw.size(); ++i) {
    if (!raw.has(i)) continue;
    const Eigen::Vector3d p = raw.point(i);
    minX = std::min(minX, p.x());
    maxX = std::max(maxX, p.x());
    minY = std::min(minY, p.y());
    maxY = std::max(maxY, p.y());
  }
  if (raw.presentCount() < 2 || !(maxX > minX) || !(maxY > minY)) {
    throwInputError(path, "has fewer than 2 present points spanning a box; a truth needs a face");
  }
  face.visibleBox = cv::Rect2d(minX, minY, maxX - minX, maxY - minY);
  // thesis25 points: the file's own, or through a built-in scheme map (iBUG 68, AFLW 21, whose
  // faces may have an eye hidden); another scheme gives the box alone.
  const bool complete = raw.size() == 68 || raw.size() == 25;
  if (raw.size() == 25) {
    face.points = raw;
  } else if (const SchemeMap* map = schemeMapFor(raw.size(), Scheme::thesis25())) {
    face.points = map->apply(raw);
  } else {
    return face;
  }
  // Only a complete mark-up anchors the face at its eyes (another scheme keeps its box's centre,
  // so that detect's "found" means the same with or without a map).
  if (!complete) return face;
  const auto [a, b] = Scheme::thesis25().normalisationPair();
  if (!face.points.has(a) || !face.points.has(b)) {
    throwInputError(path, "an eye centre is missing (iBUG 37-42 and 43-48 are needed)");
  }
  const Eigen::Vector2d left = face.points.point(a).head<2>();
  const Eigen::Vector2d right = face.points.point(b).head<2>();
  face.eyeMid = 0.5 * (left + right);
  face.iod = (left - right).norm();
  if (!(face.iod > 0.0)) throwInputError(path, "the eye centres coincide");
  return face;
}

BoxCalibration CalibrationSet::get(DetectorKind detector, bool profile) const {
  const auto it = overrides.find({detector, profile});
  return it != overrides.end() ? it->second : boxCalibration(detector, profile);
}

namespace {

constexpr double kHuge = std::numeric_limits<double>::max();

// A report's number that is null when nothing was measured (see number() above): nullopt then.
std::optional<double> optionalNumber(JsonFields& fields, std::string_view key) {
  const JsonValue* value = fields.find(key);
  if (value == nullptr || value->is_null()) return std::nullopt;
  return fields.number(key, -kHuge, kHuge);
}

// One detector's frontal or profile calibration, when it measured faces.
std::optional<BoxCalibration> readCalibration(JsonFields& calibration, DetectorKind kind,
                                              bool profile) {
  const char* key = profile ? "profile" : "frontal";
  if (!calibration.has(key)) return std::nullopt;
  JsonFields c = calibration.object(key);
  c.allow({"sd_iod_per_width", "sd_eye_offset_x", "sd_eye_offset_y"});
  if (profile) c.allow({"yaw_deg"});
  const long long faces = c.integer("faces", 0, std::numeric_limits<int>::max());
  const std::optional<double> iodPerWidth = optionalNumber(c, "iod_per_width");
  const std::optional<double> offsetX = optionalNumber(c, "eye_offset_x");
  const std::optional<double> offsetY = optionalNumber(c, "eye_offset_y");
  const std::optional<double> yaw = profile ? optionalNumber(c, "yaw_deg") : std::nullopt;
  c.rejectUnknown();
  if (faces <= 0 || !iodPerWidth) return std::nullopt;
  if (!(*iodPerWidth > 0.0)) c.fail(c.name("iod_per_width"), "must be > 0");
  if (!offsetX) c.fail(c.name("eye_offset_x"), "missing (required with iod_per_width)");
  if (!offsetY) c.fail(c.name("eye_offset_y"), "missing (required with iod_per_width)");
  BoxCalibration b = boxCalibration(kind, profile);
  b.iodPerWidth = *iodPerWidth;
  b.eyeOffsetX = *offsetX;
  b.eyeOffsetY = *offsetY;
  if (yaw) b.yawDeg = *yaw;
  return b;
}

}  // namespace

CalibrationSet readCalibrationSet(const fs::path& path) {
  const std::string source = path.string();
  const JsonValue root = parseJsonText(readTextFile(path), source);
  if (!root.is_object() || !root.contains("detectors")) {
    throwInputError(path, "not a `clm3d detect` report (no \"detectors\" list)");
  }
  JsonFields report(root, source);
  if (report.has("settings")) {
    // Written with the report; only checked here (the calibrations do not depend on them).
    JsonFields settings = report.object("settings");
    settings.allow({"min_face_size", "max_image_side", "cascade_profiles",
                    "cascade_profiles_everywhere", "cascade_dlib_fallback",
                    "cascade_dlib_agreement", "dlib_threshold", "frontal_yaw_deg",
                    "calibration_target", "vertical_fov_deg", "with_model", "band_source"});
    settings.rejectUnknown();
  }
  const JsonValue& detectors = report.array("detectors");
  report.rejectUnknown();
  CalibrationSet set;
  set.label = path.filename().string();
  for (std::size_t i = 0; i < detectors.size(); ++i) {
    JsonFields d(detectors[i], source, report.name("detectors") + "[" + std::to_string(i) + "]");
    d.allow({"images", "found", "no_face", "wrong_face", "median_ms", "p90_ms", "start_error",
             "bands"});
    const std::string name = d.requiredString("detector");
    DetectorKind kind{};
    try {
      kind = parseDetectorKind(name);
    } catch (const InputError& e) {
      d.fail(d.name("detector"), e.what());
    }
    if (d.has("calibration")) {
      JsonFields calibration = d.object("calibration");
      for (const bool profile : {false, true}) {
        if (const auto b = readCalibration(calibration, kind, profile)) {
          set.overrides[{kind, profile}] = *b;
        }
      }
      calibration.rejectUnknown();
    }
    d.rejectUnknown();
  }
  if (set.overrides.empty()) throwInputError(path, "holds no measured calibration");
  return set;
}

std::vector<fs::path> findTruthFiles(const std::vector<fs::path>& images,
                                     const fs::path& truthDir) {
  if (!truthDir.empty() && !fs::is_directory(truthDir)) {
    throwInputError(truthDir, "no such folder (--truth-dir)");
  }
  std::vector<fs::path> truths;
  truths.reserve(images.size());
  for (const fs::path& image : images) {
    const fs::path folder = truthDir.empty() ? image.parent_path() : truthDir;
    const auto found = findLandmarkFile(folder, image.stem().string());
    if (!found) {
      throwInputError(image, "no truth landmark file " + (folder / image.stem()).string() +
                                 ".pts (.ljson, .csv)");
    }
    truths.push_back(*found);
  }
  return truths;
}

DetectorEvaluationReport evaluateDetectors(
    const std::vector<fs::path>& images, const std::vector<fs::path>& truths,
    const std::vector<DetectorKind>& kinds, const DetectorEvaluationSettings& settings,
    const ClmModel* model, const std::vector<CalibrationSet>& calibrations,
    const ProgressCallback& progress, const CancelToken* cancel) {
  if (images.size() != truths.size()) {
    throw InputError("detector evaluation: " + std::to_string(images.size()) + " images but " +
                     std::to_string(truths.size()) + " truth files");
  }
  if (kinds.empty()) throw InputError("detector evaluation: no detector given");
  if (model && model->shape.pointCount() != Scheme::thesis25().size()) {
    throw InputError("detector evaluation: the model's scheme '" + model->scheme().name() +
                     "' is not thesis25, whose points the truth is compared on");
  }
  settings.detector.validate();
  std::vector<CalibrationSet> sets = calibrations;
  if (model && sets.empty()) sets.push_back(CalibrationSet{});

  DetectorEvaluationReport report;
  report.settings = settings;
  report.withModel = model != nullptr;
  std::vector<FaceDetector> detectors;
  for (const DetectorKind kind : kinds) {
    detectors.emplace_back(kind, settings.detector);
    report.detectors.emplace_back();
    report.detectors.back().detector = kind;
  }
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (cancel) cancel->throwIfCancelled();
    const cv::Mat image = readImage(images[i]);
    const TruthFace truth = readTruthFace(truths[i]);
    const Camera camera = Camera::fromVerticalFov(image.cols, image.rows, settings.verticalFovDeg);
    // The mean shape fitted to the truth's points gives the pose, eye midpoint and frontal eye
    // distance even where the truth has one eye hidden (a profile, which is left out of the
    // calibration when its visible points do not settle a pose); the eye target needs both eyes.
    bool posed =
        model && (truth.hasEyes() || settings.calibrationTarget == CalibrationTarget::MeanShape);
    TruthPose pose;
    if (posed) {
      try {
        pose = truthPose(*model, camera, truth, settings);
      } catch (const InputError& e) {
        if (truth.hasEyes()) throwInputError(truths[i], e.what());
        posed = false;
      }
    }
    const bool toMeanShape = posed && settings.calibrationTarget == CalibrationTarget::MeanShape;
    const Eigen::Vector2d calibrationEyeMid = toMeanShape ? pose.eyeMid : truth.eyeMid;
    std::string line;
    for (std::size_t d = 0; d < detectors.size(); ++d) {
      ImageDetection result;
      result.image = images[i];
      result.iod = posed ? pose.iodFrontal : truth.iod;
      result.yawDeg = pose.yawDeg;
      const auto begin = std::chrono::steady_clock::now();
      const std::vector<FaceBox> boxes = detectors[d].detect(image);
      result.milliseconds =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
              .count();
      result.boxes = static_cast<int>(boxes.size());
      result.firstProfile = !boxes.empty() && boxes.front().profile;
      double nearest = std::numeric_limits<double>::infinity();
      int nearestIndex = -1;
      for (std::size_t b = 0; b < boxes.size(); ++b) {
        const cv::Rect2d& r = boxes[b].box;
        const Eigen::Vector2d centre(r.x + 0.5 * r.width, r.y + 0.5 * r.height);
        const double distance = (centre - truth.anchor()).norm();
        if (distance < nearest) {
          nearest = distance;
          nearestIndex = static_cast<int>(b);
        }
      }
      const Eigen::Vector2d anchor = truth.anchor();
      if (nearestIndex >= 0 && boxes[static_cast<std::size_t>(nearestIndex)].box.contains(
                                   cv::Point2d(anchor.x(), anchor.y()))) {
        result.annotated = nearestIndex;
        result.box = boxes[static_cast<std::size_t>(nearestIndex)];
        const cv::Rect2d& r = result.box.box;
        result.offsetX = (calibrationEyeMid.x() - (r.x + 0.5 * r.width)) / r.width *
                         (result.box.mirrored ? -1.0 : 1.0);
        result.offsetY = (calibrationEyeMid.y() - (r.y + 0.5 * r.height)) / r.width;
        if (model && truth.hasEyes()) {
          for (const CalibrationSet& set : sets) {
            result.startErrors.push_back(startError(
                *model, camera, result.box, set.get(result.box.detector, result.box.profile), truth,
                settings.startPoints));
          }
        }
      }
      std::ostringstream note;
      note << ' ' << detectorKindName(detectors[d].kind()) << ' '
           << (result.found() ? (result.wrongFace() ? "found-not-first" : "found")
                              : (result.noFace() ? "no-face" : "wrong-face"))
           << ' ' << std::fixed << std::setprecision(0) << result.milliseconds << " ms";
      line += note.str();
      report.detectors[d].images.push_back(std::move(result));
    }
    if (progress) {
      progress(static_cast<double>(i + 1) / static_cast<double>(images.size()),
               "detect " + std::to_string(i + 1) + "/" + std::to_string(images.size()) + " " +
                   images[i].filename().string() + ":" + line);
    }
  }

  for (DetectorEvaluation& evaluation : report.detectors) {
    std::vector<double> times;
    Samples frontal, profile;
    std::vector<std::vector<double>> errors(sets.size());
    for (const ImageDetection& r : evaluation.images) {
      times.push_back(r.milliseconds);
      evaluation.found += r.found() ? 1 : 0;
      evaluation.noFace += r.noFace() ? 1 : 0;
      evaluation.wrongFace += r.wrongFace() ? 1 : 0;
      if (!r.found()) continue;
      for (std::size_t s = 0; s < r.startErrors.size(); ++s) {
        if (std::isfinite(r.startErrors[s])) errors[s].push_back(r.startErrors[s]);
      }
      if (!(std::isfinite(r.iod) && r.iod > 0.0)) continue;
      const double w = r.box.box.width;
      if (r.box.profile) {
        profile.add(r.iod / w, r.offsetX, r.offsetY, std::abs(r.yawDeg));
      } else if (!std::isfinite(r.yawDeg) || std::abs(r.yawDeg) <= settings.frontalYawDeg) {
        frontal.add(r.iod / w, r.offsetX, r.offsetY, kNaN);
      }
    }
    evaluation.medianMilliseconds = median(times);
    evaluation.p90Milliseconds = percentile(times, 90.0);
    evaluation.frontal = frontal.estimate(false);
    evaluation.profile = profile.estimate(true);
    for (std::size_t s = 0; s < sets.size(); ++s) {
      StartErrorSummary summary;
      summary.calibration = sets[s].label;
      summary.faces = static_cast<int>(errors[s].size());
      summary.mean = mean(errors[s]);
      summary.median = median(errors[s]);
      evaluation.startErrors.push_back(summary);
    }
  }
  return report;
}

void addDetectionBands(DetectorEvaluationReport& report, const std::vector<int>& bandOfImage,
                       const std::vector<std::string>& labels, const std::string& source) {
  report.bandSource = source;
  for (DetectorEvaluation& evaluation : report.detectors) {
    if (bandOfImage.size() != evaluation.images.size()) {
      throw InputError("detection bands: " + std::to_string(bandOfImage.size()) +
                       " band indices for " + std::to_string(evaluation.images.size()) + " images");
    }
    evaluation.bands.assign(labels.size(), DetectionBand{});
    std::vector<std::vector<double>> times(labels.size());
    for (std::size_t b = 0; b < labels.size(); ++b) evaluation.bands[b].label = labels[b];
    for (std::size_t i = 0; i < evaluation.images.size(); ++i) {
      ImageDetection& image = evaluation.images[i];
      image.band = bandOfImage[i];
      if (image.band < 0) continue;
      if (image.band >= static_cast<int>(labels.size())) {
        throw InputError("detection bands: band " + std::to_string(image.band) + " of " +
                         image.image.string() + " is not one of the " +
                         std::to_string(labels.size()) + " bands");
      }
      DetectionBand& band = evaluation.bands[static_cast<std::size_t>(image.band)];
      ++band.images;
      band.found += image.found() ? 1 : 0;
      band.noFace += image.noFace() ? 1 : 0;
      band.wrongFace += image.wrongFace() ? 1 : 0;
      band.profileFirst += image.firstProfile ? 1 : 0;
      times[static_cast<std::size_t>(image.band)].push_back(image.milliseconds);
    }
    for (std::size_t b = 0; b < labels.size(); ++b) {
      evaluation.bands[b].medianMilliseconds = median(times[b]);
    }
  }
}

std::string formatDetectorEvaluationText(const DetectorEvaluationReport& report,
                                         bool withCalibration) {
  std::ostringstream out;
  const FaceDetectorSettings& s = report.settings.detector;
  out << "detector settings: minFaceSize " << s.minFaceSize << ", maxImageSide " << s.maxImageSide
      << (s.maxImageSide > 0 ? "" : " (off)") << ", cascade profiles "
      << (!s.profiles            ? "off"
          : s.profilesEverywhere ? "on, everywhere"
                                 : "on, around frontal faces")
      << ", cascade with dlib: fallback "
      << (s.dlibFallback && FaceDetector::available(DetectorKind::DlibHog) ? "on" : "off")
      << ", agreement "
      << (s.dlibAgreement && FaceDetector::available(DetectorKind::DlibHog) ? "on" : "off") << '\n';
  out << "detector | images | found | no face | wrong face | median ms | p90 ms\n";
  out << std::fixed;
  for (const DetectorEvaluation& e : report.detectors) {
    out << detectorKindName(e.detector) << " | " << e.images.size() << " | " << e.found << " | "
        << e.noFace << " | " << e.wrongFace << " | " << std::setprecision(1) << e.medianMilliseconds
        << " | " << e.p90Milliseconds << '\n';
  }
  bool anyBands = false;
  for (const DetectorEvaluation& e : report.detectors) anyBands |= !e.bands.empty();
  if (anyBands) {
    out << "by |yaw| band (" << report.bandSource << "):\n";
    out << "detector | |yaw| | images | found | no face | wrong face | profile box first | median "
           "ms\n";
    for (const DetectorEvaluation& e : report.detectors) {
      for (const DetectionBand& b : e.bands) {
        out << detectorKindName(e.detector) << " | " << b.label << " | " << b.images << " | "
            << b.found << " | " << b.noFace << " | " << b.wrongFace << " | " << b.profileFirst
            << " | " << std::setprecision(1) << b.medianMilliseconds << '\n';
      }
    }
  }
  if (withCalibration) {
    out << "box calibration (medians; frontal boxes on faces within " << std::setprecision(0)
        << report.settings.frontalYawDeg << " degrees"
        << (!report.withModel ? " of any yaw, image eye distance: give --model for the yaw"
            : report.settings.calibrationTarget == CalibrationTarget::MeanShape
                ? ", to the model's mean shape fitted to the truth"
                : ", frontal eye distance from the model's pose of the truth")
        << "):\n";
    out << "detector | boxes | faces | iodPerWidth | eyeOffsetX | eyeOffsetY | yawDeg | sd ratio "
           "/ x / y\n";
    for (const DetectorEvaluation& e : report.detectors) {
      for (const bool profile : {false, true}) {
        const CalibrationEstimate& c = profile ? e.profile : e.frontal;
        out << detectorKindName(e.detector) << " | " << (profile ? "profile" : "frontal") << " | "
            << c.faces;
        if (c.faces > 0) {
          out << std::setprecision(3) << " | " << c.median.iodPerWidth << " | "
              << c.median.eyeOffsetX << " | " << c.median.eyeOffsetY << " | "
              << std::setprecision(0) << c.median.yawDeg << " | " << std::setprecision(3)
              << c.sdIodPerWidth << " / " << c.sdEyeOffsetX << " / " << c.sdEyeOffsetY;
        }
        out << '\n';
      }
    }
  }
  bool anyStart = false;
  for (const DetectorEvaluation& e : report.detectors) anyStart |= !e.startErrors.empty();
  if (anyStart) {
    out << "start error of stateFromBox in the annotated face's box (mean point distance / true "
           "eye distance):\n";
    out << "detector | calibration | faces | mean | median\n";
    for (const DetectorEvaluation& e : report.detectors) {
      for (const StartErrorSummary& summary : e.startErrors) {
        out << detectorKindName(e.detector) << " | " << summary.calibration << " | "
            << summary.faces << " | " << std::setprecision(3) << summary.mean << " | "
            << summary.median << "\n";
      }
    }
  }
  return out.str();
}

std::string formatDetectorEvaluationJson(const DetectorEvaluationReport& report,
                                         bool withCalibration) {
  const FaceDetectorSettings& s = report.settings.detector;
  json j;
  j["settings"] = {
      {"min_face_size", s.minFaceSize},
      {"max_image_side", s.maxImageSide},
      {"cascade_profiles", s.profiles},
      {"cascade_profiles_everywhere", s.profilesEverywhere},
      {"cascade_dlib_fallback", s.dlibFallback && FaceDetector::available(DetectorKind::DlibHog)},
      {"cascade_dlib_agreement", s.dlibAgreement && FaceDetector::available(DetectorKind::DlibHog)},
      {"dlib_threshold", s.dlibThreshold},
      {"frontal_yaw_deg", report.settings.frontalYawDeg},
      {"calibration_target",
       report.settings.calibrationTarget == CalibrationTarget::MeanShape ? "mean-shape" : "eyes"},
      {"vertical_fov_deg", report.settings.verticalFovDeg},
      {"with_model", report.withModel}};
  if (!report.bandSource.empty()) j["settings"]["band_source"] = report.bandSource;
  j["detectors"] = json::array();
  for (const DetectorEvaluation& e : report.detectors) {
    json d = {{"detector", detectorKindName(e.detector)},
              {"images", e.images.size()},
              {"found", e.found},
              {"no_face", e.noFace},
              {"wrong_face", e.wrongFace},
              {"median_ms", number(e.medianMilliseconds)},
              {"p90_ms", number(e.p90Milliseconds)}};
    if (withCalibration) {
      d["calibration"] = {{"frontal", calibrationJson(e.frontal, false)},
                          {"profile", calibrationJson(e.profile, true)}};
    }
    if (!e.bands.empty()) {
      d["bands"] = json::array();
      for (const DetectionBand& b : e.bands) {
        d["bands"].push_back({{"band", b.label},
                              {"images", b.images},
                              {"found", b.found},
                              {"no_face", b.noFace},
                              {"wrong_face", b.wrongFace},
                              {"profile_first", b.profileFirst},
                              {"median_ms", number(b.medianMilliseconds)}});
      }
    }
    if (!e.startErrors.empty()) {
      d["start_error"] = json::array();
      for (const StartErrorSummary& se : e.startErrors) {
        d["start_error"].push_back({{"calibration", se.calibration},
                                    {"faces", se.faces},
                                    {"mean", number(se.mean)},
                                    {"median", number(se.median)}});
      }
    }
    j["detectors"].push_back(d);
  }
  return j.dump(2) + "\n";
}

}  // namespace clm3d
