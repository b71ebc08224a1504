#include "core/eval/photo_fit_calibration.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

#include "core/common/error.hpp"
#include "core/common/logistic_curve.hpp"
#include "core/common/parallel_for.hpp"
#include "core/eval/detail/photo_fit_judge.hpp"
#include "core/eval/detail/scored_truth.hpp"
#include "core/eval/point_set_error.hpp"
#include "core/refine/descent_check.hpp"
#include "core/refine/view_check.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace {

// One photo's fit as the calibration sees it.
struct JudgedFit {
  bool judged = false;  // the check gave the probability
  double viewYawDeg = 0.0;
  double logOdds = 0.0;
  bool right = false;
  Eigen::VectorXf features;  // photoFitFeatures at the fit's points (empty: not read)
};

// The error over the truth's face box of `points` (every scheme landmark, image pixels), as
// `clm3d eval-points` scores it (scorePointSet over the truth's present points).
double boxError(const Eigen::Matrix2Xd& points, const ScoredTruth& truth, const Scheme& scheme) {
  LandmarkSet prediction(scheme.size(), 2);
  for (int i = 0; i < scheme.size() && i < points.cols(); ++i) {
    if (points.col(i).allFinite()) prediction.set(i, Eigen::Vector2d(points.col(i)));
  }
  return scorePointSet(truth.points, truth.boxSize, prediction, scheme, {}).boxError;
}

// Curves from `fits` (those `use` selects), per |yaw| with enough of both kinds; with an image
// term where at least `imageMinFits` of them have features (0: never).
std::vector<PhotoFitCurve> learnCurves(const std::vector<JudgedFit>& fits,
                                       const std::function<bool(std::size_t)>& use, int minEach,
                                       int imageMinFits) {
  std::map<double, std::vector<const JudgedFit*>> byYaw;
  for (std::size_t i = 0; i < fits.size(); ++i) {
    if (fits[i].judged && use(i)) byYaw[fits[i].viewYawDeg].push_back(&fits[i]);
  }
  std::vector<PhotoFitCurve> curves;
  for (const auto& [yaw, group] : byYaw) {
    const auto right =
        std::count_if(group.begin(), group.end(), [](const JudgedFit* fit) { return fit->right; });
    const auto wrong = static_cast<long>(group.size()) - right;
    if (right < minEach || wrong < minEach) continue;
    // The fits whose features were read, all of one length (one layout per |yaw|).
    std::vector<const JudgedFit*> read;
    for (const JudgedFit* fit : group) {
      if (fit->features.size() > 0 &&
          (read.empty() || fit->features.size() == read.front()->features.size()))
        read.push_back(fit);
    }
    const auto readRight =
        std::count_if(read.begin(), read.end(), [](const JudgedFit* fit) { return fit->right; });
    if (imageMinFits > 0 && static_cast<int>(read.size()) >= imageMinFits && readRight >= minEach &&
        static_cast<long>(read.size()) - readRight >= minEach) {
      PhotoFitSample sample;
      sample.features.resize(static_cast<Eigen::Index>(read.size()), read.front()->features.size());
      for (std::size_t j = 0; j < read.size(); ++j) {
        sample.features.row(static_cast<Eigen::Index>(j)) = read[j]->features.transpose();
        sample.logOdds.push_back(read[j]->logOdds);
        sample.right.push_back(read[j]->right);
      }
      curves.push_back(learnPhotoFitJudge(yaw, sample));
      continue;
    }
    std::vector<double> scores;
    std::vector<bool> labels;
    for (const JudgedFit* fit : group) {
      scores.push_back(fit->logOdds);
      labels.push_back(fit->right);
    }
    const LogisticCurve curve = fitLogisticCurve(scores, labels);
    curves.push_back({yaw, curve.slope, curve.offset, {}, {}});
  }
  return curves;
}

// The probability `curves` give a fit (its check's, when none applies).
double judged(const std::vector<PhotoFitCurve>& curves, const JudgedFit& fit) {
  const PhotoFitCurve* curve = nearestPhotoFitCurve(curves, fit.viewYawDeg);
  const double own = LogisticCurve{}(fit.logOdds);
  return curve == nullptr ? own : photoFitProbability(*curve, own, fit.features);
}

}  // namespace

ImageFitSettings searchedAsCalibrated(ImageFitSettings fit) {
  fit.startSearch.onlyBelow = 0.9999;
  fit.widerSearchBelow = 0.97;
  fit.refineRunsBelow = 0.9999;
  return fit;
}

PhotoFitCalibration calibratePhotoFits(const ClmModel& model,
                                       const std::vector<std::filesystem::path>& images,
                                       const std::vector<std::filesystem::path>& truths,
                                       const PhotoFitCalibrationSettings& settings,
                                       const ProgressCallback& progress,
                                       const CancelToken* cancel) {
  if (model.refiner.check.empty())
    throw InputError("calibrate: the model has no point check to calibrate (train it with photos)");
  if (images.size() != truths.size())
    throw InputError("calibrate: one truth file per image is needed");
  ClmModel uncalibrated = model;  // the pipeline as the check alone judges it
  uncalibrated.refiner.check.photoFitCurves.clear();
  const Scheme scheme = model.scheme();
  std::vector<ScoredTruth> scored;
  scored.reserve(truths.size());
  for (const std::filesystem::path& truth : truths)
    scored.push_back(readScoredTruth(truth, scheme));

  const int count = static_cast<int>(images.size());
  const int workers = workerCount(count, settings.threads);
  std::vector<JudgedFit> fits(images.size());
  std::vector<unsigned char> fitted(images.size(), 0);
  std::atomic<int> done{0};
  // One ImageFitter per worker (it is not thread-safe), each taking every workers-th photo.
  parallelFor(
      workers, workers,
      [&](int worker) {
        ImageFitter fitter(uncalibrated, settings.fit);
        for (int i = worker; i < count; i += workers) {
          if (cancel != nullptr && cancel->cancelled()) return;
          const ImageFitOutcome outcome = fitter.fitFile(images[static_cast<std::size_t>(i)]);
          const auto slot = static_cast<std::size_t>(i);
          if (outcome.fit) {
            fitted[slot] = 1;
            const FitResult& fit = *outcome.fit;
            const double error = boxError(fit.points, scored[slot], scheme);
            if (fit.probabilitySource == ProbabilitySource::Check && std::isfinite(error) &&
                fit.view >= 0 && fit.view < static_cast<int>(model.views.size())) {
              JudgedFit& judgedFit = fits[slot];
              judgedFit = {true,
                           std::abs(model.views[static_cast<std::size_t>(fit.view)].yawDeg),
                           logOdds(fit.probability),
                           error <= settings.rightBelow,
                           {}};
              // The image term reads the photo as the fitter did (readImage, the same pixels).
              if (settings.imageMinFits > 0) {
                judgedFit.features =
                    photoFitFeatures(model, fit.view, readImage(images[slot]), fit.points);
              }
            }
          }
          const int finished = ++done;
          if (progress && worker == 0)
            progress(static_cast<double>(finished) / count, "photo fits");
        }
      },
      cancel);
  if (cancel != nullptr && cancel->cancelled()) throw Cancelled();
  if (progress) progress(1.0, "photo fits");  // worker 0 reports, and may finish first

  PhotoFitCalibration out;
  out.photos = count;
  for (std::size_t i = 0; i < fits.size(); ++i) {
    out.judged += fits[i].judged ? 1 : 0;
    out.noFace += fitted[i] ? 0 : 1;
  }
  out.curves = learnCurves(
      fits, [](std::size_t) { return true; }, settings.minEach, settings.imageMinFits);
  if (out.curves.empty())
    throw InputError("calibrate: no view's |yaw| had " + std::to_string(settings.minEach) +
                     " right and " + std::to_string(settings.minEach) +
                     " wrong fits to learn a curve from (" + std::to_string(out.judged) +
                     " fits judged by the check): give more photos, at more poses");
  // Held out: each half judged by the curves of the other.
  std::array<std::vector<PhotoFitCurve>, 2> halves;
  for (std::size_t half = 0; half < 2; ++half) {
    halves[half] = learnCurves(
        fits, [half](std::size_t i) { return i % 2 != half; }, settings.minEach,
        settings.imageMinFits);
  }
  const double threshold = settings.fit.minProbability;
  std::map<double, PhotoFitCalibrationRow> rows;
  for (std::size_t i = 0; i < fits.size(); ++i) {
    const JudgedFit& fit = fits[i];
    if (!fit.judged) continue;
    PhotoFitCalibrationRow& row = rows[fit.viewYawDeg];
    row.viewYawDeg = fit.viewYawDeg;
    const double before = LogisticCurve{}(fit.logOdds);
    const double heldOut = judged(halves[i % 2], fit);
    (fit.right ? row.right : row.wrong) += 1;
    if (fit.right) {
      row.rightKeptBefore += before >= threshold ? 1 : 0;
      row.rightKeptHeldOut += heldOut >= threshold ? 1 : 0;
    } else {
      row.wrongAcceptedBefore += before >= threshold ? 1 : 0;
      row.wrongAcceptedHeldOut += heldOut >= threshold ? 1 : 0;
    }
  }
  for (auto& [yaw, row] : rows) {
    row.curve = std::any_of(out.curves.begin(), out.curves.end(),
                            [&](const PhotoFitCurve& curve) { return curve.viewYawDeg == yaw; });
    out.rows.push_back(row);
  }
  return out;
}

void applyPhotoFitCalibration(ClmModel& model, const PhotoFitCalibration& calibration,
                              const std::filesystem::path& source) {
  model.refiner.check.photoFitCurves = calibration.curves;
  model.provenance.notes += "; the point check calibrated on the photo pipeline's fits of " +
                            std::to_string(calibration.photos) + " annotated photos (" +
                            source.string() + ")";
}

std::string formatPhotoFitCalibration(const PhotoFitCalibration& calibration,
                                      const PhotoFitCalibrationSettings& settings) {
  std::ostringstream out;
  out << calibration.photos << " photos (" << calibration.judged << " fits judged by the check, "
      << calibration.noFace << " without a fit); a fit is right within " << settings.rightBelow
      << " of the face box\n";
  out << "at probability >= " << settings.fit.minProbability
      << ": right fits kept and wrong ones accepted, by the check alone -> by the curves learnt "
         "from the other half of the photos\n";
  out << "| view |yaw| | fits | right | wrong | curve | right kept | wrong accepted |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const PhotoFitCalibrationRow& row : calibration.rows) {
    out << "| " << row.viewYawDeg << " | " << row.right + row.wrong << " | " << row.right << " | "
        << row.wrong << " | " << (row.curve ? "own" : "nearest") << " | " << row.rightKeptBefore
        << " -> " << row.rightKeptHeldOut << " | " << row.wrongAcceptedBefore << " -> "
        << row.wrongAcceptedHeldOut << " |\n";
  }
  out << std::setprecision(4);
  for (const PhotoFitCurve& curve : calibration.curves) {
    out << "curve |yaw| " << curve.viewYawDeg << ": p = 1 / (1 + exp(-(" << curve.slope
        << " * log-odds of the check + " << curve.offset << ")))\n";
  }
  return out.str();
}

}  // namespace clm3d
