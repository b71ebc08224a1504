#include "core/train/view_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <utility>

#include "core/common/error.hpp"
#include "core/common/job_progress.hpp"
#include "core/common/logistic_curve.hpp"
#include "core/common/parallel_for.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/detect/initialisation.hpp"
#include "core/detect/start_search.hpp"
#include "core/fit/fitter.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/face_box.hpp"
#include "core/refine/descent_check.hpp"
#include "core/refine/view_check.hpp"

namespace clm3d {
namespace {

// The view a view's calibration is shared with: a mirrored view's source (the same experts,
// mirrored), else itself.
int pooledView(const ClmModel& model, int view) {
  const ViewModel& v = model.views[static_cast<std::size_t>(view)];
  return v.mirrored ? model.nearestView(v.pitchDeg, -v.yawDeg) : view;
}

// One search of a calibration face: the view it ended in (pooled), its confidence, and whether it
// is right.
struct Search {
  int view = -1;
  double score = 0.0;
  bool right = false;
  Eigen::VectorXf features;  // what the view's check reads (empty: none)
};

// `count` of `list`, spread evenly over it (the first when count >= its size: all).
std::vector<int> spread(const std::vector<int>& list, int count) {
  if (static_cast<int>(list.size()) <= count) return list;
  std::vector<int> picked;
  for (int k = 0; k < count; ++k) {
    picked.push_back(
        list[static_cast<std::size_t>(k) * list.size() / static_cast<std::size_t>(count)]);
  }
  return picked;
}

// The searches of one face: from near its truth, moved away, turned a view away.
std::vector<Search> searchFace(const ClmModel& model, const std::vector<ViewCheck>& layouts,
                               const TrainingPhoto& photo, const ViewCalibrationSettings& settings,
                               std::uint64_t key) {
  const cv::Mat image = cv::imread(photo.image.string(), cv::IMREAD_GRAYSCALE);
  const int n = model.shape.pointCount();
  if (image.empty() || photo.points.size() != n) return {};
  // The trusted points (a trusted point is present); the others NaN, and zero for the fit.
  Eigen::Matrix2Xd trusted =
      Eigen::Matrix2Xd::Constant(2, n, std::numeric_limits<double>::quiet_NaN());
  Eigen::Matrix2Xd truth = Eigen::Matrix2Xd::Zero(2, n);
  std::vector<bool> present(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    if (!photo.trusted[static_cast<std::size_t>(i)] || !photo.points.has(i)) continue;
    truth.col(i) = photo.points.point(i).head<2>();
    trusted.col(i) = truth.col(i);
    present[static_cast<std::size_t>(i)] = true;
  }
  const double box = faceBoxSize(trusted);
  if (!(box > 0.0)) return {};
  const Camera camera = Camera::fromVerticalFov(image.cols, image.rows, kDefaultVerticalFovDeg);
  FitSettings fit;
  fit.optimiser = "rlms";  // the experts' response is what is calibrated
  Fitter fitter(model, camera, fit);
  FitState truthState;
  try {
    truthState = stateFromPoints(model, camera, truth, present);
  } catch (const InputError&) {
    return {};
  }
  SplitMixRandom random(key);
  std::vector<std::pair<FitState, int>> starts;  // (start, view hint)
  {
    const Eigen::Vector2d shift(random.symmetric(0.05), random.symmetric(0.05));
    FitState near = shiftedStart(model, fitter, truthState, shift);
    near.pose.scale *= 1.0 + random.symmetric(0.05);
    near.pose.yaw += radians(random.symmetric(5.0));
    starts.emplace_back(near, -1);
  }
  {
    const double angle = 2.0 * std::numbers::pi * random.unit();
    starts.emplace_back(
        shiftedStart(model, fitter, truthState,
                     settings.shiftEyes * Eigen::Vector2d(std::cos(angle), std::sin(angle))),
        -1);
  }
  {
    const int view =
        model.nearestView(degrees(truthState.pose.pitch), degrees(truthState.pose.yaw));
    const std::array<int, 2> sides = neighbouringViews(model, view);
    std::size_t side = random.unit() < 0.5 ? 0 : 1;
    if (sides[side] < 0) side = 1 - side;
    if (sides[side] >= 0) {
      FitState turned = truthState;
      turned.pose.yaw += radians(side == 0 ? -settings.turnDeg : settings.turnDeg);
      starts.emplace_back(turned,
                          model.nearestView(degrees(turned.pose.pitch), degrees(turned.pose.yaw)));
    }
  }
  std::vector<Search> searches;
  for (const auto& [start, view] : starts) {
    FitResult result;
    try {
      result = fitter.fit(image, start, view);
    } catch (const InputError&) {
      continue;  // a start off the image
    }
    if (!std::isfinite(result.searchScore) || result.view < 0) continue;
    double error = 0.0;
    int counted = 0;
    for (int i = 0; i < n; ++i) {
      if (!present[static_cast<std::size_t>(i)]) continue;
      error += (result.points.col(i) - truth.col(i)).norm();
      ++counted;
    }
    if (counted == 0 || !std::isfinite(error)) continue;
    const int pooled = pooledView(model, result.view);
    searches.push_back(
        {pooled, result.searchScore, error / counted / box < settings.rightBelow,
         viewCheckFeatures(model, result.view, layouts[static_cast<std::size_t>(pooled)], image,
                           result.points)});
  }
  return searches;
}

// The ROC's area of labelled scores (ties count half; 0.5 without both labels).
double separation(const std::vector<double>& s, const std::vector<bool>& right) {
  double pairs = 0.0, above = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!right[i]) continue;
    for (std::size_t j = 0; j < s.size(); ++j) {
      if (right[j]) continue;
      pairs += 1.0;
      above += s[i] > s[j] ? 1.0 : (s[i] == s[j] ? 0.5 : 0.0);
    }
  }
  return pairs > 0.0 ? above / pairs : 0.5;
}

// The check of view `view` from its searches (`found`, per job; every checkCalibrationEvery-th
// job's searches fit the curve and measure the check, the others teach it), or an empty one when
// a class has too few searches. Fills the row's held-out ROC areas.
ViewCheck learnViewCheck(const ViewCheck& layout, int view,
                         const std::vector<std::vector<Search>>& found,
                         const ViewCalibrationSettings& settings, ViewCalibrationRow& row) {
  const int every = std::max(2, settings.checkCalibrationEvery);
  std::vector<const Search*> samples;
  std::vector<int> learn, calibrate;
  for (std::size_t j = 0; j < found.size(); ++j) {
    for (const Search& search : found[j]) {
      if (search.view != view || search.features.size() == 0) continue;
      (static_cast<int>(j) % every == every - 1 ? calibrate : learn)
          .push_back(static_cast<int>(samples.size()));
      samples.push_back(&search);
    }
  }
  const auto counts = [&](const std::vector<int>& list) {
    int right = 0;
    for (const int s : list) right += samples[static_cast<std::size_t>(s)]->right ? 1 : 0;
    return std::pair{right, static_cast<int>(list.size()) - right};
  };
  const auto [learnRight, learnWrong] = counts(learn);
  const auto [heldRight, heldWrong] = counts(calibrate);
  if (std::min(learnRight, learnWrong) < settings.minCheckPerClass ||
      std::min(heldRight, heldWrong) < settings.minCheckPerClass / 4) {
    return {};
  }
  Eigen::MatrixXf features(samples.front()->features.size(),
                           static_cast<Eigen::Index>(samples.size()));
  std::vector<unsigned char> right(samples.size());
  for (std::size_t s = 0; s < samples.size(); ++s) {
    features.col(static_cast<Eigen::Index>(s)) = samples[s]->features;
    right[s] = samples[s]->right ? 1 : 0;
  }
  ViewCheck check = layout;
  LogisticFitSettings curve;
  curve.balanced = true;
  check.classifier = learnLinearCheck(features, right, learn, calibrate, settings.checkRidge,
                                      layout.classifier.window, curve);
  std::vector<double> checkScores, responses;
  std::vector<bool> labels;
  for (const int s : calibrate) {
    const Search& search = *samples[static_cast<std::size_t>(s)];
    checkScores.push_back(checkProbability(check.classifier, search.features));
    responses.push_back(search.score);
    labels.push_back(search.right);
  }
  row.checkSeparation = separation(checkScores, labels);
  row.heldOutResponseSeparation = separation(responses, labels);
  row.checked = static_cast<int>(calibrate.size());
  return check;
}

}  // namespace

std::vector<ViewCalibrationRow> calibrateViews(ClmModel& model,
                                               const std::vector<TrainingPhoto>& photos,
                                               const std::vector<PhotoPlacement>& placements,
                                               const ViewCalibrationSettings& settings,
                                               const ProgressCallback& progress,
                                               const CancelToken* cancel) {
  const auto viewCount = static_cast<int>(model.views.size());
  if (viewCount == 0 || !model.views.front().scales.front().hasExperts() ||
      placements.size() != photos.size()) {
    return {};
  }
  std::vector<ViewCalibrationRow> rows(static_cast<std::size_t>(viewCount));
  for (int v = 0; v < viewCount; ++v) rows[static_cast<std::size_t>(v)].view = v;

  // Where the refiner's faces sit, and which faces each view is calibrated on.
  int refinerCopies = 0;
  std::vector<std::vector<int>> heldOut(static_cast<std::size_t>(viewCount));
  std::vector<std::vector<int>> learnt(static_cast<std::size_t>(viewCount));
  for (std::size_t k = 0; k < photos.size(); ++k) {
    const PhotoPlacement& placed = placements[k];
    if (!placed.skipped.empty()) continue;
    const int view = pooledView(model, model.nearestView(placed.pitchDeg, placed.yawDeg));
    if (photos[k].refiner && !model.refiner.empty()) {
      const int mirror = pooledView(model, model.nearestView(placed.pitchDeg, -placed.yawDeg));
      ++rows[static_cast<std::size_t>(view)].refinerFaces;
      ++rows[static_cast<std::size_t>(mirror)].refinerFaces;
      refinerCopies += 2;
    }
    auto& list = placed.samples == 0 && placed.capped > 0 ? heldOut : learnt;
    list[static_cast<std::size_t>(view)].push_back(static_cast<int>(k));
  }
  std::vector<std::pair<int, std::uint64_t>> jobs;  // (photo, key)
  for (int v = 0; v < viewCount; ++v) {
    const auto slot = static_cast<std::size_t>(v);
    const std::vector<int> kept = spread(heldOut[slot], settings.facesPerView);
    const std::vector<int> more =
        spread(learnt[slot], settings.facesPerView - static_cast<int>(kept.size()));
    rows[slot].heldOut = static_cast<int>(kept.size());
    rows[slot].learnt = static_cast<int>(more.size());
    for (const std::vector<int>* list : {&kept, &more}) {
      for (const int k : *list)
        jobs.emplace_back(k, mixKey(settings.seed, static_cast<std::uint64_t>(k)));
    }
  }

  // The layout of each view's check (landmarks, mean shape), on the non-mirrored views.
  std::vector<ViewCheck> layouts(static_cast<std::size_t>(viewCount));
  for (int v = 0; v < viewCount; ++v) {
    if (pooledView(model, v) == v) layouts[static_cast<std::size_t>(v)] = viewCheckLayout(model, v);
  }

  std::vector<std::vector<Search>> found(jobs.size());
  JobProgress done(progress, static_cast<int>(jobs.size()), "calibration");
  parallelFor(static_cast<int>(jobs.size()), settings.threads, [&](int j) {
    if (cancel) cancel->throwIfCancelled();
    const auto [k, key] = jobs[static_cast<std::size_t>(j)];
    found[static_cast<std::size_t>(j)] =
        searchFace(model, layouts, photos[static_cast<std::size_t>(k)], settings, key);
    done.finished();
  });

  // The curves: per pooled view, else per yaw, else over all views.
  std::vector<std::vector<double>> scores(static_cast<std::size_t>(viewCount));
  std::vector<std::vector<bool>> labels(static_cast<std::size_t>(viewCount));
  std::vector<double> allScores;
  std::vector<bool> allLabels;
  for (const std::vector<Search>& list : found) {
    for (const Search& s : list) {
      scores[static_cast<std::size_t>(s.view)].push_back(s.score);
      labels[static_cast<std::size_t>(s.view)].push_back(s.right);
      allScores.push_back(s.score);
      allLabels.push_back(s.right);
    }
  }
  const auto enough = [&](const std::vector<bool>& list) {
    const auto right = static_cast<int>(std::count(list.begin(), list.end(), true));
    return right >= settings.minPerClass &&
           static_cast<int>(list.size()) - right >= settings.minPerClass;
  };
  if (!enough(allLabels)) return {};
  LogisticFitSettings fitting;
  fitting.balanced = true;
  for (int v = 0; v < viewCount; ++v) {
    const auto slot = static_cast<std::size_t>(v);
    ViewCalibrationRow& row = rows[slot];
    row.right = static_cast<int>(std::count(labels[slot].begin(), labels[slot].end(), true));
    row.wrong = static_cast<int>(labels[slot].size()) - row.right;
    if (pooledView(model, v) != v) continue;
    row.separation = separation(scores[slot], labels[slot]);
    if (enough(labels[slot])) {
      row.curve = fitLogisticCurve(scores[slot], labels[slot], fitting);
      continue;
    }
    row.pooled = true;
    std::vector<double> sameYawScores;
    std::vector<bool> sameYawLabels;
    for (int u = 0; u < viewCount; ++u) {
      const auto other = static_cast<std::size_t>(u);
      if (model.views[other].yawDeg != model.views[slot].yawDeg) continue;
      sameYawScores.insert(sameYawScores.end(), scores[other].begin(), scores[other].end());
      sameYawLabels.insert(sameYawLabels.end(), labels[other].begin(), labels[other].end());
    }
    row.curve = enough(sameYawLabels) ? fitLogisticCurve(sameYawScores, sameYawLabels, fitting)
                                      : fitLogisticCurve(allScores, allLabels, fitting);
  }
  std::vector<ViewCheck> checks(static_cast<std::size_t>(viewCount));
  for (int v = 0; v < viewCount; ++v) {
    const auto slot = static_cast<std::size_t>(v);
    if (pooledView(model, v) == v)
      checks[slot] = learnViewCheck(layouts[slot], v, found, settings, rows[slot]);
  }
  for (int v = 0; v < viewCount; ++v) {
    const auto slot = static_cast<std::size_t>(v);
    const auto sourceSlot = static_cast<std::size_t>(pooledView(model, v));
    const ViewCalibrationRow& source = rows[sourceSlot];
    model.views[slot].calibration = source.curve;
    model.views[slot].check = checks[sourceSlot];
    if (!model.refiner.empty()) {
      model.views[slot].refined = source.refinerFaces >= settings.refinerShare * refinerCopies;
    }
  }
  std::vector<ViewCalibrationRow> report;
  for (int v = 0; v < viewCount; ++v) {
    if (pooledView(model, v) == v) report.push_back(rows[static_cast<std::size_t>(v)]);
  }
  return report;
}

std::string formatViewCalibration(const ClmModel& model,
                                  const std::vector<ViewCalibrationRow>& rows) {
  std::ostringstream out;
  out << "view calibration (searches from near the truth, moved and turned starts; right: error "
         "under 0.08 of the face box; ROC area: how well the response tells them apart):\n"
      << "  pitch   yaw  faces (held out)  right  wrong  ROC area  p(0.4)  p(0.5)  p(0.6)  "
         "refiner  check: searches  ROC area (response's)\n";
  out << std::fixed;
  for (const ViewCalibrationRow& row : rows) {
    const ViewModel& view = model.views[static_cast<std::size_t>(row.view)];
    out << std::setprecision(0) << "  " << std::setw(5) << view.pitchDeg << std::setw(6)
        << std::showpos << view.yawDeg << std::noshowpos << std::setw(7) << row.heldOut + row.learnt
        << " (" << std::setw(3) << row.heldOut << ")    " << std::setw(5) << row.right
        << std::setw(7) << row.wrong << std::setprecision(2) << std::setw(10) << row.separation;
    for (const double score : {0.4, 0.5, 0.6}) out << std::setw(8) << row.curve(score);
    out << "  " << std::setw(7) << (view.refined ? "yes" : "no");
    if (row.checked > 0) {
      out << std::setw(17) << row.checked << std::setw(10) << row.checkSeparation << " ("
          << row.heldOutResponseSeparation << ")";
    } else {
      out << "  none (too few searches)";
    }
    out << (row.pooled ? "  (curve pooled)" : "") << '\n';
  }
  return out.str();
}

}  // namespace clm3d
