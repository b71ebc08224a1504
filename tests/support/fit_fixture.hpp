// A small trained model and rendered scenes with exact truth, for the tests of fitting,
// initialisation and tracking: procedural heads (seeds 1-4) train a 3-view (yaw -30, 0, +30),
// 2-scale model with 12x12 patches once per build (a few seconds; cached on disk), and a
// scene is a render of one of those heads (or a held-out one) at a known pose with its true
// landmark positions and the model state nearest to them. Header-only; link clm3d::fit,
// clm3d::train, clm3d::synth and clm3d::render.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/fit/fit_state.hpp"
#include "core/fit/shape_projector.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/procrustes.hpp"
#include "core/geometry/projection.hpp"
#include "core/model/clm_model.hpp"
#include "core/model/model_file.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/synth/synth_head.hpp"
#include "core/train/trainer.hpp"

namespace clm3d::test {

// Fixture head i (seeds 1, 2, 3, 4 and the held-out 101), generated on first use.
inline const SynthHead& fitTestHead(int i) {
  static std::array<std::optional<SynthHead>, 5> heads;
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  static constexpr std::array<std::uint64_t, 5> kSeeds{1, 2, 3, 4, 101};
  auto& head = heads.at(static_cast<std::size_t>(i));
  if (!head) head = generateHead(kSeeds[static_cast<std::size_t>(i)], {}, SynthOptions{1.5, 512});
  return *head;
}

// fitTestHeads()[i] is fitTestHead(i).
struct FitTestHeads {
  const SynthHead& operator[](int i) const { return fitTestHead(i); }
};
inline FitTestHeads fitTestHeads() {
  return {};
}

// Index of the head that no fixture model was trained on.
inline constexpr int kHeldOutHead = 4;

inline TrainSettings fitTestSettings(bool singleView) {
  TrainSettings settings;
  settings.yawsDeg = {-30, 0, 30};
  settings.pitchesDeg = {0};
  settings.scales = 2;
  settings.patchSize = 12;
  settings.samplesPerView = 3;
  settings.supersample = 1;
  settings.threads = 2;
  settings.seed = 3;
  settings.textureMaxModes = 12;
  settings.singleView = singleView;
  return settings;
}

inline ClmModel trainFitTestModel(bool singleView) {
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  for (int i = 0; i < kHeldOutHead; ++i) {
    const SynthHead& head = fitTestHead(i);
    input.subjects.push_back({"head" + std::to_string(i + 1), &head.mesh, &head.landmarks});
  }
  input.datasetName = "fit-fixture";
  input.toolVersion = "test";
  return trainModel(input, fitTestSettings(singleView));
}

// ctest runs every test in its own process, so a model trained per process would be trained once
// per test (a minute each under ASan). The model is cached in the build folder, shared by every
// test binary of the build (each suite training its own cost the ASan pass several minutes), and
// keyed by the newest of the core libraries and this header: rebuilding any core stage or
// changing the fixture here trains it afresh.
inline std::filesystem::file_time_type fitFixtureStamp(std::error_code& error) {
  namespace fs = std::filesystem;
  fs::file_time_type newest = fs::last_write_time(__FILE__, error);
  if (error) return newest;
  for (fs::recursive_directory_iterator it(fs::path(CLM3D_BINARY_DIR) / "core", error), end;
       !error && it != end; it.increment(error)) {
    const fs::path& file = it->path();
    if (file.extension() != ".a" && file.extension() != ".so") continue;
    newest = std::max(newest, fs::last_write_time(file, error));
  }
  return newest;
}

inline ClmModel cachedFitTestModel(bool singleView) {
  namespace fs = std::filesystem;
  std::error_code error;
  const auto stamp = fitFixtureStamp(error);
  const fs::path cache = fs::path(CLM3D_BINARY_DIR) / "test-cache" /
                         ("fit-fixture-" + std::to_string(stamp.time_since_epoch().count()) +
                          (singleView ? "-2d" : "-3d") + ".clm3d");
  if (!error && fs::exists(cache)) {
    try {
      return loadModel(cache);
    } catch (const std::exception&) {
      // A damaged cache file is retrained below.
    }
  }
  ClmModel model = trainFitTestModel(singleView);
  if (!error) {
    fs::create_directories(cache.parent_path(), error);
    try {
      saveModel(model, cache);  // atomic: a concurrent reader never sees half a file
    } catch (const std::exception&) {
      // Caching is an optimisation only.
    }
  }
  return model;
}

// The 3D multi-view model and the 2D single-view baseline.
inline const ClmModel& fitTestModel() {
  static const ClmModel model = cachedFitTestModel(false);
  return model;
}
inline const ClmModel& fitTestModel2D() {
  static const ClmModel model = cachedFitTestModel(true);
  return model;
}

struct FitScene {
  cv::Mat image;  // BGR, the head over a mid-grey background
  Camera camera;
  Pose pose;                     // the head's true pose
  Eigen::Matrix2Xd truthPoints;  // the head's 25 landmarks projected (pixels)
  std::vector<bool> visible;     // per landmark, from the depth buffer
  FitState truth;                // the model state nearest to the true landmarks
  double interOcular = 0.0;      // pixels between the true points 8 and 11
};

// A render of head `head` at (pitch, yaw, roll) degrees, 320x240, inter-ocular about
// `interOcularPixels`.
inline FitScene makeFitScene(const ClmModel& model, double pitchDeg, double yawDeg, int head = 0,
                             double interOcularPixels = 60.0, double rollDeg = 0.0) {
  const SynthHead& subject = fitTestHead(head);
  FitScene scene;
  scene.camera = Camera::fromVerticalFov(320, 240, 40.0);
  const Eigen::Matrix3Xd truth3 = subject.landmarks.matrix();
  const double iodMm = (truth3.col(7) - truth3.col(10)).norm();
  const double depth = scene.camera.focalY() * iodMm / interOcularPixels;
  scene.pose = Pose::fromDegrees(pitchDeg, yawDeg, rollDeg, {4.0, -3.0, -depth});
  OffscreenRenderer renderer(subject.mesh);
  const RenderResult render = renderer.render(scene.pose, scene.camera);
  scene.image.create(render.bgra.rows, render.bgra.cols, CV_8UC3);
  for (int y = 0; y < render.bgra.rows; ++y) {
    for (int x = 0; x < render.bgra.cols; ++x) {
      const cv::Vec4b s = render.bgra.at<cv::Vec4b>(y, x);
      const double a = s[3] / 255.0;
      for (int c = 0; c < 3; ++c) {
        scene.image.at<cv::Vec3b>(y, x)[c] =
            static_cast<unsigned char>(std::lround(a * s[c] + (1.0 - a) * 128.0));
      }
    }
  }
  scene.truthPoints = projectPoints(truth3, scene.pose, scene.camera);
  for (int i = 0; i < truth3.cols(); ++i) scene.visible.push_back(render.isVisible(truth3.col(i)));
  scene.interOcular = (scene.truthPoints.col(7) - scene.truthPoints.col(10)).norm();

  // Nearest model state: align the mean shape to the head's landmarks (similarity), express the
  // head in the model frame, and project onto the shape modes; the pose composes the alignment.
  const ShapeModel& shape = model.shape;
  const Similarity3 toHead = alignSimilarity(shape.meanShape, truth3);
  const Eigen::Matrix3Xd inModel = toHead.inverse().apply(truth3);
  const Eigen::Matrix3Xd residual = inModel - shape.meanShape;
  Eigen::VectorXd b =
      shape.modes.transpose() * Eigen::Map<const Eigen::VectorXd>(residual.data(), residual.size());
  shape.clamp(b);
  scene.truth.shape = b;
  scene.truth.pose = scene.pose;
  scene.truth.pose.scale = scene.pose.scale * toHead.scale;
  scene.truth.pose.translation =
      scene.pose.translation + scene.pose.scale * (scene.pose.rotation() * toHead.translation);
  return scene;
}

// The truth moved by (dx, dy) pixels, rotated by `degrees` in roll and yaw (yaw kept for the planar
// model), scaled by `scale`, and each shape coefficient moved by `shapeSd` standard deviations.
inline FitState perturbState(const FitScene& scene, const ClmModel& model, double dx, double dy,
                             double degreesOff, double scale, double shapeSd) {
  FitState state = scene.truth;
  const double mmPerPixel = -state.pose.translation.z() / scene.camera.focalY();
  state.pose.translation.x() += dx * mmPerPixel;
  state.pose.translation.y() -= dy * mmPerPixel;
  state.pose.roll += radians(degreesOff);
  if (model.shape.dims == 3) state.pose.yaw += radians(degreesOff);
  state.pose.scale *= scale;
  for (int k = 0; k < state.shape.size(); ++k) {
    state.shape[k] += shapeSd * std::sqrt(model.shape.variances[k]);
  }
  model.shape.clamp(state.shape);
  return state;
}

// Mean distance between corresponding columns, over `use` (empty = all).
inline double meanPointError(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b,
                             const std::vector<bool>& use = {}) {
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < a.cols(); ++i) {
    if (!use.empty() && !use[static_cast<std::size_t>(i)]) continue;
    sum += (a.col(i) - b.col(i)).norm();
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

// Gives `model` a point refiner with a check, as a model trained with photos has (one stage over
// three landmarks; its values are not meant to refine anything): what the "auto" optimiser looks
// for.
inline void giveCheckedRefiner(ClmModel& model) {
  model.refiner.landmarks = {0, 1, 2};
  model.refiner.meanShape = Eigen::Matrix2Xd::Zero(2, 3);
  model.refiner.stages.resize(1);
  model.refiner.check.weights = Eigen::VectorXf::Ones(4);
}

}  // namespace clm3d::test
