#include "core/detect/start_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"

namespace clm3d {

FitState shiftedStart(const ClmModel& model, const Fitter& fitter, FitState start,
                      const Eigen::Vector2d& shareOfEyes) {
  const Eigen::Matrix2Xd points = fitter.project(start);
  const auto [left, right] = model.scheme().normalisationPair();
  const double eyes = (points.col(left) - points.col(right)).norm();
  // Eye coordinates look down -z with y up: a pixel is -z / focal millimetres at the face's depth.
  const double mmPerPixel = -start.pose.translation.z() / fitter.camera().focalY();
  start.pose.translation.x() += shareOfEyes.x() * eyes * mmPerPixel;
  start.pose.translation.y() -= shareOfEyes.y() * eyes * mmPerPixel;
  return start;
}

FitResult fitFromBestStart(Fitter& fitter, const ClmModel& model, const cv::Mat& image,
                           const FitState& start, const StartSearchSettings& settings,
                           int* searches, const FitFinisher& finish) {
  const auto search = [&](const FitState& from) {
    FitResult fit = fitter.fit(image, from);
    if (finish) finish(fit);
    return fit;
  };
  std::vector<double> sizes{1.0};
  for (const double size : settings.sizes) {
    if (size != 1.0) sizes.push_back(size);
  }
  const int steps = std::max(0, settings.steps);
  FitResult best = search(start);
  int count = 1;
  if (settings.onlyBelow > 0.0 && best.probability >= settings.onlyBelow) {
    if (searches != nullptr) *searches = count;
    return best;
  }
  for (int dy = -steps; dy <= steps; ++dy) {
    for (int dx = -steps; dx <= steps; ++dx) {
      for (const double size : sizes) {
        if (dx == 0 && dy == 0 && size == 1.0) continue;  // searched first
        FitState moved =
            shiftedStart(model, fitter, start, Eigen::Vector2d(dx, dy) * settings.shift);
        moved.pose.scale *= size;
        FitResult fit = search(moved);
        ++count;
        if (fit.probability > best.probability) best = std::move(fit);
      }
    }
  }
  if (searches != nullptr) *searches = count;
  return best;
}

FitResult fitFromBestFace(Fitter& fitter, const ClmModel& model, const cv::Mat& image,
                          const std::vector<FaceBox>& faces, const FaceSearch& search, int* tried,
                          int* searches) {
  if (faces.empty()) throw InputError("face search: no faces to search");
  const std::size_t count =
      std::min(faces.size(), static_cast<std::size_t>(std::max(1, search.maxFaces)));
  std::optional<FitResult> best;
  std::optional<InputError> firstError;  // a face whose start left the image: the next is tried
  // Searches one placement of a face; true when its fit is accepted (then kept as the best).
  const auto accepts = [&](const FaceBox& box, const BoxCalibration& calibration) {
    FitState start = stateFromBox(model, fitter.camera(), box, calibration);
    if (search.placed) start = search.placed(start);
    int made = 0;
    std::optional<FitResult> fit;
    try {
      StartSearchSettings starts = search.starts;
      if (box.profile && search.profileSteps >= 0) starts.steps = search.profileSteps;
      fit = fitFromBestStart(fitter, model, image, start, starts, &made, search.finish);
    } catch (const InputError& e) {
      if (!firstError) firstError = e;
    }
    if (searches != nullptr) *searches += made;
    if (!fit) return false;
    if (!search.accepted || search.accepted(*fit)) {
      best = std::move(fit);  // the first accepted fit, whatever the probability of those before
      return true;
    }
    if (!best || fit->probability > best->probability) best = std::move(fit);
    return false;
  };
  std::size_t face = 0;
  bool found = false;
  while (face < count && !found) {
    const FaceBox& box = faces[face++];
    if (search.placement == BoxPlacement::Calibrated) {
      found = accepts(box, boxCalibration(box.detector, box.profile));
    } else if (const auto turned = turnedFaceCalibration(box)) {
      found = accepts(box, *turned);
    }
  }
  if (tried != nullptr) *tried = static_cast<int>(face);
  if (!best && !firstError) throw InputError("face search: no profile box to place again");
  if (!best) throw *firstError;  // no face could be searched
  return std::move(*best);
}

bool wantsViewSearch(const FitResult& fit, double below, bool all) {
  return fit.probability < below && (all || comparesViews(fit.probabilitySource));
}

std::array<int, 2> neighbouringViews(const ClmModel& model, int view) {
  std::array<int, 2> sides{-1, -1};
  if (view < 0 || view >= static_cast<int>(model.views.size())) return sides;
  const ViewModel& here = model.views[static_cast<std::size_t>(view)];
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    const ViewModel& other = model.views[v];
    if (other.pitchDeg != here.pitchDeg || other.yawDeg == here.yawDeg) continue;
    const std::size_t side = other.yawDeg < here.yawDeg ? 0 : 1;
    const int best = sides[side];
    if (best < 0 ||
        std::abs(other.yawDeg - here.yawDeg) <
            std::abs(model.views[static_cast<std::size_t>(best)].yawDeg - here.yawDeg)) {
      sides[side] = static_cast<int>(v);
    }
  }
  return sides;
}

FitResult searchNeighbouringViews(Fitter& fitter, const ClmModel& model, const cv::Mat& image,
                                  const FitResult& fit, double margin, const FitFinisher& finish,
                                  const std::function<bool(const FitResult&)>& accepted,
                                  int* searches) {
  FitResult best = fit;
  int count = 0;
  for (const int view : neighbouringViews(model, fit.view)) {
    if (view < 0) continue;
    FitState start = fit.state;
    // Half-way to the neighbour's centre: inside its cell, and a step the search can make up.
    start.pose.yaw =
        0.5 * (fit.state.pose.yaw + radians(model.views[static_cast<std::size_t>(view)].yawDeg));
    ++count;
    std::optional<FitResult> turned;
    try {
      turned = fitter.fit(image, start, view);
      if (finish) finish(*turned);
    } catch (const InputError&) {
      // The turned start put the face outside the image: this neighbour is no candidate.
    }
    if (turned && (!accepted || accepted(*turned)) &&
        turned->probability > best.probability + margin) {
      best = std::move(*turned);
    }
  }
  if (searches != nullptr) *searches += count;
  return best;
}

std::vector<double> tiltAngles(int steps, double stepDeg) {
  std::vector<double> angles;
  for (int k = 1; k <= steps; ++k) {
    angles.push_back(-k * stepDeg);
    angles.push_back(k * stepDeg);
  }
  return angles;
}

std::optional<FitResult> fitFromDetections(Fitter& fitter, const ClmModel& model,
                                           const cv::Mat& image, FaceDetector& detector,
                                           const std::vector<FaceBox>& faces,
                                           const FaceSearch& search, double* detectMilliseconds) {
  std::optional<FitResult> best;
  const auto consider = [&](const std::vector<FaceBox>& found, const FaceSearch& how) {
    FitResult fit = fitFromBestFace(fitter, model, image, found, how);
    if (!best || fit.probability > best->probability) best = std::move(fit);
  };
  if (!faces.empty()) consider(faces, search);
  for (const double angle : tiltAngles(search.tiltSteps, search.tiltStepDeg)) {
    if (best && (!search.accepted || search.accepted(*best))) break;
    const auto begin = std::chrono::steady_clock::now();
    const std::vector<FaceBox> turned = detector.detectTurned(image, angle);
    if (detectMilliseconds != nullptr) {
      *detectMilliseconds +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
              .count();
    }
    if (!turned.empty()) consider(turned, search);
  }
  // Still none accepted: the upright profile boxes placed as real turned faces sit
  // (turnedFaceCalibration), last, so that a photo that another box or a tilted copy fits is
  // unchanged.
  if (search.turnedPlacements && best && search.accepted && !search.accepted(*best) &&
      std::any_of(faces.begin(), faces.end(),
                  [](const FaceBox& box) { return turnedFaceCalibration(box).has_value(); })) {
    FaceSearch turned = search;
    turned.placement = BoxPlacement::TurnedFace;
    consider(faces, turned);
  }
  if (best && best->probability < search.widerBelow) {
    FitResult wider =
        fitFromBestStart(fitter, model, image, best->state, search.wider, nullptr, search.finish);
    if (wider.probability > best->probability) best = std::move(wider);
  }
  if (best && wantsViewSearch(*best, search.viewsBelow, search.viewsOfAll)) {
    best = searchNeighbouringViews(fitter, model, image, *best, search.viewMargin, search.finish,
                                   search.accepted);
  }
  return best;
}

}  // namespace clm3d
