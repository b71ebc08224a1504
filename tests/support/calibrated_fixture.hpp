// The fit fixture's model (tests/support/fit_fixture.hpp) with its views calibrated
// (core/train/view_calibration.hpp) on renders of the fixture heads at yaws -40..40, written as
// annotated photos that the experts did not learn from (placed as a source's cap would leave
// them out). Header-only; link clm3d::train, clm3d::fit, clm3d::synth, clm3d::render, clm3d::viz.
#pragma once

#include <string>
#include <vector>

#include "core/scheme/landmark_file.hpp"
#include "core/train/view_calibration.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d::test {

struct CalibratedFixture {
  ClmModel model;
  std::vector<ViewCalibrationRow> rows;
};

inline CalibratedFixture calibrateFitTestModel() {
  CalibratedFixture fixture{fitTestModel(), {}};
  const TempDir dir;
  const Scheme scheme = Scheme::byNameOrPath("thesis25");
  std::vector<TrainingPhoto> photos;
  std::vector<PhotoPlacement> placements;
  for (int head = 0; head < kHeldOutHead; ++head) {
    for (const double yaw : {-40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 40.0}) {
      const double pitch = head % 2 == 0 ? 5.0 : -5.0;
      const FitScene scene = makeFitScene(fixture.model, pitch, yaw + head, head, 60.0);
      TrainingPhoto photo;
      photo.id = "head" + std::to_string(head) + "_" + std::to_string(static_cast<int>(yaw));
      photo.image = dir / (photo.id + ".png");
      writeImage(photo.image, scene.image);
      photo.points = LandmarkSet(scheme.size(), 2);
      for (int i = 0; i < scheme.size(); ++i) {
        photo.points.set(i, Eigen::Vector2d(scene.truthPoints.col(i)));
      }
      photo.trusted = scene.visible;
      photo.refiner = false;
      photos.push_back(photo);
      PhotoPlacement placed;
      placed.id = photo.id;
      placed.pitchDeg = pitch;
      placed.yawDeg = yaw + head;
      placed.capped = 1;  // left out of the experts' training
      placements.push_back(placed);
    }
  }
  ViewCalibrationSettings settings;
  settings.facesPerView = 16;
  settings.minPerClass = 4;
  // 40-44 searches a view: every fourth face's measure the checks, at least 8 of each class teach.
  settings.minCheckPerClass = 8;
  settings.checkCalibrationEvery = 4;
  settings.threads = 2;
  fixture.rows = calibrateViews(fixture.model, photos, placements, settings);
  return fixture;
}

// Calibrated once per test process.
inline const CalibratedFixture& calibratedFitTestModel() {
  static const CalibratedFixture fixture = calibrateFitTestModel();
  return fixture;
}

}  // namespace clm3d::test
