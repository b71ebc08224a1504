#include "core/track/batch_fit.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <numbers>
#include <opencv2/core.hpp>
#include <sstream>
#include <system_error>

#include "core/common/atomic_file.hpp"
#include "core/common/csv_cell.hpp"
#include "core/common/error.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/detect/initialisation.hpp"
#include "core/detect/start_search.hpp"
#include "core/refine/refined_fit.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/detail/unrefined_landmarks.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

ImageFitOutcome failed(const fs::path& image, ImageFitStatus status, std::string message) {
  ImageFitOutcome outcome;
  outcome.image = image;
  outcome.status = status;
  outcome.message = std::move(message);
  return outcome;
}

// The start moved in the image plane by `share` of its projected eye distance, in a direction
// drawn from `key`.
FitState offsetStart(const ClmModel& model, const Fitter& fitter, const FitState& start,
                     double share, std::uint64_t key) {
  SplitMixRandom random(key);
  const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
  return shiftedStart(model, fitter, start,
                      share * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
}

}  // namespace

ImageFitSettings imageFitSettings(const FaceSearchSettings& search) {
  ImageFitSettings settings;
  static_cast<FaceSearchSettings&>(settings) = search;
  return settings;
}

FitState stateFromPointsFile(const ClmModel& model, const Camera& camera, const fs::path& path) {
  const Scheme scheme = model.scheme();
  const LandmarkSet given = readLandmarks(path, &scheme);
  Eigen::Matrix2Xd points(2, given.size());
  std::vector<bool> present(static_cast<std::size_t>(given.size()));
  for (int i = 0; i < given.size(); ++i) {
    present[static_cast<std::size_t>(i)] = given.has(i);
    points.col(i) =
        given.has(i) ? Eigen::Vector2d(given.point(i).head<2>()) : Eigen::Vector2d::Zero();
  }
  try {
    return stateFromPoints(model, camera, points, present);
  } catch (const InputError& e) {
    throw InputError(fileMessage(path, e.what()));
  }
}

const char* toString(ImageFitStatus status) {
  switch (status) {
    case ImageFitStatus::Ok:
      return "ok";
    case ImageFitStatus::Rejected:
      return "rejected";
    case ImageFitStatus::NoFace:
      return "no-face";
    case ImageFitStatus::Error:
      return "error";
  }
  return "error";
}

ImageFitter::ImageFitter(const ClmModel& model, const ImageFitSettings& settings)
    : model_(&model), settings_(settings) {
  settings_.fit.validate(model);
}

ImageFitter::~ImageFitter() = default;

FaceDetector& ImageFitter::detector() {
  if (!detector_) detector_ = std::make_unique<FaceDetector>(settings_.detector);
  return *detector_;
}

Fitter& ImageFitter::fitterFor(const cv::Mat& image) {
  if (!fitter_ || fitter_->camera().width != image.cols || fitter_->camera().height != image.rows) {
    fitter_.reset();
    const Camera camera =
        Camera::fromVerticalFov(image.cols, image.rows, stillImageFovDeg(settings_));
    fitter_ = std::make_unique<Fitter>(*model_, camera, settings_.fit);
  }
  return *fitter_;
}

ImageFitOutcome ImageFitter::fitFile(const fs::path& image, const fs::path& startPoints,
                                     const fs::path& output) {
  // Set-up failures are not the image's fault: they propagate (see the header).
  if (startPoints.empty()) detector();
  ImageFitOutcome outcome;
  outcome.image = image;
  try {
    lastImage_ = cv::Mat();
    lastImage_ = readImage(image);
    Fitter& fitter = fitterFor(lastImage_);
    std::vector<FaceBox> faces;
    if (startPoints.empty()) {
      const auto begin = std::chrono::steady_clock::now();
      faces = detector().detect(lastImage_);
      outcome.detectMilliseconds = millisecondsSince(begin);
    }
    // Tilted faces are searched only where the check can tell a right fit from a wrong one.
    const bool checked = settings_.refine && !model_->refiner.check.empty();
    if (startPoints.empty() && faces.empty() && (!checked || settings_.tiltSteps == 0)) {
      outcome.status = ImageFitStatus::NoFace;
      outcome.message = fileMessage(image, "no face found");
      return outcome;
    }
    const auto placed = [&](FitState start) {
      if (settings_.startOffset <= 0.0) return start;
      return offsetStart(
          *model_, fitter, start, settings_.startOffset,
          mixKey(settings_.startOffsetSeed, std::hash<std::string>{}(image.stem().string())));
    };
    const auto begin = std::chrono::steady_clock::now();
    // Every search's fit is refined and judged as a photo's fit: by a model calibrated on photo
    // fits (`clm3d calibrate`, training's calibration_photos), through the curve of the fit's view
    // with its image term, so that the start grid, the faces, the tilted copies, the wider search
    // and the neighbouring views compare fits on the one calibrated probability, which compares
    // views; without curves, on the check's.
    FitFinisher finish;
    if (settings_.refine) {
      finish = [this](FitResult& fit) {
        refineFit(*model_, lastImage_, fit);
        judgeAsPhotoFit(*model_, fit, lastImage_);
      };
    }
    const auto passes = [this](const FitResult& result) {
      return photoFitProbability(*model_, result, lastImage_) >= settings_.minProbability;
    };
    FitResult fit;
    double turnedMilliseconds = 0.0;  // detection in turned copies, inside the search
    if (startPoints.empty()) {
      FaceSearch search;
      search.maxFaces = settings_.facesTried;
      search.starts = settings_.startSearch;
      search.profileSteps = settings_.profileStartSteps;
      search.accepted = passes;
      search.placed = placed;
      search.finish = finish;
      search.tiltSteps = checked ? settings_.tiltSteps : 0;
      search.tiltStepDeg = settings_.tiltStepDeg;
      search.widerBelow = checked ? settings_.widerSearchBelow : 0.0;
      search.wider = settings_.widerSearch;
      search.viewsBelow = settings_.viewSearchBelow;
      search.viewsOfAll = settings_.viewSearchAll;
      search.turnedPlacements = checked && settings_.turnedPlacements;
      search.viewMargin = settings_.viewSearchMargin;
      std::optional<FitResult> found = fitFromDetections(fitter, *model_, lastImage_, detector(),
                                                         faces, search, &turnedMilliseconds);
      outcome.detectMilliseconds += turnedMilliseconds;
      if (!found) {
        outcome.status = ImageFitStatus::NoFace;
        outcome.message = fileMessage(image, "no face found, upright or tilted");
        return outcome;
      }
      fit = std::move(*found);
    } else {
      fit = fitter.fit(lastImage_,
                       placed(stateFromPointsFile(*model_, fitter.camera(), startPoints)));
      if (finish) finish(fit);
    }
    const bool doubted =
        settings_.refineRunsBelow <= 0.0 || fit.probability < settings_.refineRunsBelow;
    if (settings_.refine && settings_.refineRuns > 1 && !model_->refiner.empty() && doubted) {
      // The starts were compared by a refinement from one start each; the kept fit's points are
      // refined again from the search's own, now from several starts.
      fit.points = fitter.project(fit.state);
      refineFit(*model_, lastImage_, fit,
                RefinerStarts{settings_.refineRuns - 1, settings_.refineSpread});
    }
    // A start from marked points brought its outline with it; a box brought none.
    if (startPoints.empty()) placeUnrefinedLandmarks(*model_, fitter.camera(), fit);
    judgeAsPhotoFit(*model_, fit, lastImage_);
    outcome.fitMilliseconds = millisecondsSince(begin) - turnedMilliseconds;
    if (fit.view >= 0 && fit.view < static_cast<int>(model_->views.size())) {
      const ViewModel& view = model_->views[static_cast<std::size_t>(fit.view)];
      outcome.viewPitchDeg = view.pitchDeg;
      outcome.viewYawDeg = view.yawDeg;
    }
    const bool rejected = !passes(fit);
    if (rejected) {
      std::ostringstream reason;
      reason << std::fixed << std::setprecision(2)
             << "the model rejects the fit: its probability of being right (" << fit.probability
             << ", by the " << toString(fit.probabilitySource) << ") is below "
             << settings_.minProbability << ": the points are probably not on a face";
      outcome.message = fileMessage(image, reason.str());
    }
    if (!output.empty() && (!rejected || settings_.keepRejected)) {
      const Scheme scheme = model_->scheme();
      LandmarkSet points(scheme.size(), 2);
      for (int i = 0; i < scheme.size(); ++i) points.set(i, Eigen::Vector2d(fit.points.col(i)));
      writeLandmarks(output, points, scheme);
      outcome.output = output;
    }
    outcome.fit = std::move(fit);
    outcome.status = rejected ? ImageFitStatus::Rejected : ImageFitStatus::Ok;
  } catch (const InputError& e) {
    // Messages of the image, points and output files already name their file; others (a fit on
    // an image too small for the model) are given the image's name.
    std::string message = e.what();
    bool named = false;
    for (const fs::path* file : {&image, &startPoints, &output}) {
      named = named || (!file->empty() && message.find(file->string()) != std::string::npos);
    }
    return failed(image, ImageFitStatus::Error, named ? message : fileMessage(image, message));
  } catch (const cv::Exception& e) {
    return failed(image, ImageFitStatus::Error, fileMessage(image, e.what()));
  }
  return outcome;
}

std::string formatBatchFitSummary(const std::vector<ImageFitOutcome>& outcomes) {
  std::ostringstream out;
  out << "image,status,fit_ms,detect_ms,confidence,search_confidence,view_pitch,view_yaw,"
         "iterations,converged,probability_source,view_probability,error\n";
  for (const ImageFitOutcome& o : outcomes) {
    out << csvCell(o.image.string()) << ',' << toString(o.status) << ','
        << fixedCell(o.fitMilliseconds, 3) << ',' << fixedCell(o.detectMilliseconds, 3) << ',';
    if (o.fit) {
      out << fixedCell(o.fit->probability, 6) << ',' << fixedCell(o.fit->searchScore, 6) << ','
          << fixedCell(o.viewPitchDeg, 1) << ',' << fixedCell(o.viewYawDeg, 1) << ','
          << o.fit->iterations << ',' << (o.fit->converged ? 1 : 0) << ','
          << csvCell(toString(o.fit->probabilitySource)) << ','
          << fixedCell(o.fit->viewProbability, 6) << ',';
    } else {
      out << ",,,,,,,,";
    }
    out << csvCell(o.message) << '\n';
  }
  return out.str();
}

void prepareOutputFolder(const std::vector<fs::path>& inputs, const fs::path& outDir,
                         const fs::path& initDir) {
  std::error_code error;
  // Points written into the images' own folder would replace the mark-ups beside them (LFPW keeps
  // STEM.pts next to STEM.jpg), and into the start folder the start points: refuse both.
  for (const fs::path& image : inputs) {
    const fs::path folder = image.parent_path().empty() ? fs::path(".") : image.parent_path();
    if (fs::equivalent(folder, outDir, error)) {
      throwInputError(outDir, "is the folder of the images (" + image.filename().string() +
                                  "): the points would overwrite files beside them; choose "
                                  "another output folder");
    }
  }
  if (!initDir.empty() && fs::equivalent(initDir, outDir, error)) {
    throwInputError(outDir, "is the folder of the start points; choose another output folder");
  }
  error.clear();
  fs::create_directories(outDir, error);
  if (error) throwInputError(outDir, "cannot create the folder: " + error.message());
}

ImageFitOutcome fitBatchImage(ImageFitter& fitter, const fs::path& image, const fs::path& initDir,
                              const fs::path& output) {
  if (initDir.empty()) return fitter.fitFile(image, {}, output);
  const std::string stem = image.stem().string();
  const auto start = findLandmarkFile(initDir, stem);
  return start ? fitter.fitFile(image, *start, output)
               : failed(image, ImageFitStatus::Error,
                        fileMessage(image, "no start points " + stem + ".pts, .ljson or .csv in " +
                                               initDir.string()));
}

BatchFitSummary fitImages(const ClmModel& model, const BatchFitJob& job,
                          const ImageFitSettings& settings, const ProgressCallback& progress,
                          const CancelToken* cancel, const ImageFitCallback& onImage) {
  prepareOutputFolder(job.images, job.outDir, job.initDir);
  BatchFitSummary summary;
  summary.summaryCsv = job.outDir / "summary.csv";
  ImageFitter fitter(model, settings);
  std::map<std::string, fs::path> stems;  // stem -> the first image with it
  const std::size_t total = job.images.size();
  const auto writeSummary = [&] {
    writeTextAtomically(summary.summaryCsv, formatBatchFitSummary(summary.outcomes));
  };
  if (progress) progress(0.0, "fit 0/" + std::to_string(total));
  for (std::size_t i = 0; i < total; ++i) {
    if (cancel && cancel->cancelled()) {
      writeSummary();
      throw Cancelled();
    }
    const fs::path& image = job.images[i];
    const std::string stem = image.stem().string();
    ImageFitOutcome outcome;
    if (const auto [first, inserted] = stems.emplace(stem, image); !inserted) {
      outcome = failed(
          image, ImageFitStatus::Error,
          fileMessage(image, "has the same stem as " + first->second.string() +
                                 ", whose points are written to " + stem + job.pointsExtension));
    } else {
      outcome =
          fitBatchImage(fitter, image, job.initDir, job.outDir / (stem + job.pointsExtension));
    }
    switch (outcome.status) {
      case ImageFitStatus::Ok:
        ++summary.ok;
        break;
      case ImageFitStatus::Rejected:
        ++summary.rejected;
        break;
      case ImageFitStatus::NoFace:
        ++summary.noFace;
        break;
      case ImageFitStatus::Error:
        ++summary.errors;
        break;
    }
    summary.outcomes.push_back(std::move(outcome));
    const ImageFitOutcome& done = summary.outcomes.back();
    if (onImage) onImage(i, done);
    if (progress) {
      std::string stage = "fit " + std::to_string(i + 1) + "/" + std::to_string(total) + " " +
                          image.filename().string() + " ";
      stage += done.status == ImageFitStatus::Ok ? fixedCell(done.fitMilliseconds, 1) + " ms"
               : done.status == ImageFitStatus::Rejected ? std::string("rejected")
               : done.status == ImageFitStatus::NoFace   ? std::string("no face")
                                                         : std::string("error");
      progress(static_cast<double>(i + 1) / static_cast<double>(total), stage);
    }
  }
  writeSummary();
  return summary;
}

}  // namespace clm3d
