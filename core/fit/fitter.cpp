#include "core/fit/fitter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/common/error.hpp"
#include "core/fit/response_map.hpp"

namespace clm3d {
namespace {

int modelScales(const ClmModel& model) {
  int scales = 0;
  for (const ViewModel& view : model.views) {
    const int count = static_cast<int>(view.scales.size());
    scales = scales == 0 ? count : std::min(scales, count);
  }
  return scales;
}

// Pixels per model millimetre at the head's centre for the state's pose (before working-image
// scaling): the size that training normalised (core/train frameSample uses the 3D distance).
double pixelsPerMillimetre(const Camera& camera, const Eigen::Ref<const Eigen::VectorXd>& p,
                           double depth) {
  return camera.focalY() * p[kParamScale] / std::max(-depth, 1e-6);
}

}  // namespace

void FitSettings::validate(const ClmModel& model) const {
  const int available = modelScales(model);
  if (scales < 0 || scales > available) {
    throw InputError("fit: --scales must be between 1 and " + std::to_string(available) +
                     " (the model's scales), or 0 for all");
  }
  if (maxIterations < 1) throw InputError("fit: the iteration limit must be at least 1");
  if (!(tolerancePixels > 0.0)) throw InputError("fit: the tolerance must be positive");
  if (!(viewHysteresisDeg >= 0.0)) throw InputError("fit: the view hysteresis must be >= 0");
  if (textureModes < 0) throw InputError("fit: the texture mode limit must be >= 0");
}

Fitter::Fitter(const ClmModel& model, const Camera& camera, const FitSettings& settings)
    : model_(&model),
      camera_(camera),
      settings_(settings),
      selector_(model, settings.viewHysteresisDeg),
      problem_(model.shape, camera) {
  if (model.views.empty()) throw InputError("fit: the model has no views");
  settings_.validate(model);
  settings_.optimiser = resolveOptimiser(settings_.optimiser, model);
  scales_ = settings_.scales > 0 ? settings_.scales : modelScales(model);
  optimiser_ = makeOptimiser(settings_.optimiser, settings_.optimiserSettings);
  if (optimiser_->usesExperts()) {
    for (const ViewModel& view : model.views) {
      for (const PatchModel& patches : view.scales) {
        if (!patches.hasExperts()) {
          throw InputError("fit: optimiser '" + settings_.optimiser +
                           "' needs a model with patch experts (trained by clm3d 0.2 or later, "
                           "model format 2); retrain the model or choose a template optimiser "
                           "(fastncc, gauss-newton, powell, nelder-mead, condensation)");
        }
      }
    }
  }
  problem_.setTextureModeLimit(settings_.textureModes);
  eyes_ = model.scheme().normalisationPair();
  const PatchModel& finest = model.views.front().scales.front();
  targetInterOcular_ = finest.patchSize / model.patchRatio;
}

Fitter::~Fitter() = default;

FitState Fitter::meanState(const Pose& pose) const {
  return FitState{pose, Eigen::VectorXd::Zero(model_->shape.modeCount())};
}

FitTemplates Fitter::templates(const cv::Mat& image, const FitResult& fit) {
  FitTemplates out;
  if (!(fit.region.scale > 0.0) || fit.view < 0 ||
      fit.view >= static_cast<int>(model_->views.size())) {
    return out;
  }
  checkImageSize(image);
  // The finest level of the search's own working image, the problem configured as the search
  // left it, and the templates synthesised at the result's estimate.
  makeWorkingImage(image, fit.region.low, fit.region.high, fit.region.scale, 1, working_);
  problem_.configure(model_->views[static_cast<std::size_t>(fit.view)].scales[0], working_, 0,
                     settings_.alphaMask, fit.region.depth);
  Eigen::VectorXd p = toParams(fit.state);
  problem_.clamp(p);
  problem_.synthesiseTemplates(p);
  out.values.resize(static_cast<std::size_t>(problem_.landmarkCount()));
  for (int k = 0; k < problem_.landmarkCount(); ++k) {
    out.values[static_cast<std::size_t>(k)] = problem_.synthetic(k);
  }
  out.pixelSize = 1.0 / working_.gain.mean();
  return out;
}

void Fitter::checkImageSize(const cv::Mat& image) const {
  if (image.cols != camera_.width || image.rows != camera_.height) {
    throw InputError("fit: the image is " + std::to_string(image.cols) + "x" +
                     std::to_string(image.rows) + " but the camera is " +
                     std::to_string(camera_.width) + "x" + std::to_string(camera_.height));
  }
}

Eigen::Matrix2Xd Fitter::project(const FitState& state) const {
  return projectShape(model_->shape, camera_, state);
}

FitResult Fitter::fit(const cv::Mat& image, const FitState& start, int currentView) {
  checkImageSize(image);
  const int modes = model_->shape.modeCount();
  if (start.shape.size() != 0 && start.shape.size() != modes) {
    throw InputError("fit: the start state has " + std::to_string(start.shape.size()) +
                     " shape coefficients, the model " + std::to_string(modes));
  }
  FitState state = start;
  if (state.shape.size() == 0) state.shape = Eigen::VectorXd::Zero(modes);
  const double depth = state.pose.translation.z();
  if (!(depth < 0.0)) throw InputError("fit: the start pose must be in front of the camera");
  Eigen::VectorXd p = toParams(state);
  problem_.clamp(p);

  // The region around the face, scaled so that the face has the training inter-ocular distance.
  const Eigen::Matrix3Xd shape = model_->shape.shape(p.tail(modes));
  const double interOcularMm = (shape.col(eyes_.first) - shape.col(eyes_.second)).norm();
  const double scale = std::clamp(
      targetInterOcular_ / std::max(interOcularMm * pixelsPerMillimetre(camera_, p, depth), 1e-6),
      1.0 / 64.0, 16.0);
  const Eigen::Matrix2Xd points = project(state);
  const Eigen::Vector2d low = points.rowwise().minCoeff();
  const Eigen::Vector2d high = points.rowwise().maxCoeff();
  const double searchMargin =
      (model_->views.front().scales.front().patchSize * std::ldexp(1.0, scales_ - 1)) / scale;
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(searchMargin) + 0.25 * (high - low);
  if (!low.allFinite() || !high.allFinite() || (high + margin).x() < 0 || (high + margin).y() < 0 ||
      (low - margin).x() > image.cols - 1 || (low - margin).y() > image.rows - 1) {
    throw InputError("fit: the start pose puts the face outside the image");
  }
  makeWorkingImage(image, low - margin, high + margin, scale, scales_, working_);

  optimiser_->beginFit(p);
  int view =
      currentView >= 0 && currentView < static_cast<int>(model_->views.size()) ? currentView : -1;
  FitResult result;
  Eigen::Matrix2Xd before;
  Eigen::Matrix2Xd after;
  for (int level = scales_ - 1; level >= 0; --level) {
    result.converged = false;
    for (int iteration = 0; iteration < settings_.maxIterations; ++iteration) {
      view = selector_.select(degrees(p[kParamPitch]), degrees(p[kParamYaw]), view);
      problem_.configure(model_->views[static_cast<std::size_t>(view)].scales[level], working_,
                         level, settings_.alphaMask, depth);
      if (!optimiser_->usesExperts()) problem_.synthesiseTemplates(p);
      const int m = problem_.landmarkCount();
      before.resize(2, m);
      after.resize(2, m);
      problem_.projector().project(p, before);
      optimiser_->step(problem_, p);
      problem_.clamp(p);
      problem_.projector().project(p, after);
      ++result.iterations;
      double moved = 0.0;
      for (int k = 0; k < m; ++k) moved = std::max(moved, (after.col(k) - before.col(k)).norm());
      if (!(moved > settings_.tolerancePixels)) {
        result.converged = std::isfinite(moved);
        break;
      }
    }
  }

  // The score: the match of templates synthesised at the final estimate, at the finest scale.
  view = selector_.select(degrees(p[kParamPitch]), degrees(p[kParamYaw]), view);
  const PatchModel& finest = model_->views[static_cast<std::size_t>(view)].scales[0];
  problem_.configure(finest, working_, 0, settings_.alphaMask, depth);
  // The templates at the final estimate: the template optimisers' score matches them; with
  // experts they are only drawn, and templates() makes them if asked.
  if (!optimiser_->usesExperts()) problem_.synthesiseTemplates(p);
  Eigen::VectorXd perLandmark(problem_.landmarkCount());
  result.searchScore = optimiser_->usesExperts()
                           ? expertResponses(problem_.image(), problem_.projector(), finest.experts,
                                             finest.patchSize, p, perLandmark)
                           : problem_.landmarkNcc(p, perLandmark);
  result.region = SearchRegion{low - margin, high + margin, scale, depth};

  fromParams(p, state);
  result.state = state;
  result.points = project(state);
  result.view = view;
  const FitProbability probability =
      searchProbability(*model_, view, optimiser_->usesExperts(), result.searchScore);
  result.probability = probability.probability;
  result.probabilitySource = probability.source;
  result.modelled.assign(static_cast<std::size_t>(model_->shape.pointCount()), false);
  result.landmarkConfidence.assign(static_cast<std::size_t>(model_->shape.pointCount()),
                                   std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < finest.landmarks.size(); ++k) {
    const auto landmark = static_cast<std::size_t>(finest.landmarks[k]);
    result.modelled[landmark] = true;
    if (std::cmp_less(k, perLandmark.size())) {
      result.landmarkConfidence[landmark] = perLandmark[static_cast<Eigen::Index>(k)];
    }
  }
  return result;
}

}  // namespace clm3d
