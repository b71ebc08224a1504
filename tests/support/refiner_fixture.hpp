// A point refiner with a check for the fit fixture's model (tests/support/fit_fixture.hpp), as a
// model trained with photos has one: learnt by the trainer's photo path (trainPhotoRefiner) from
// 24 renders of the fixture's four procedural heads saved as annotated photos. Tests of what the
// check decides (a rejected fit, a tilted face, a frame judged on the check) use it; it is trained
// once per test program (about 10 s).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/model/descent_refiner.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/train/refiner_training.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d::test {

// Writes the scene as DIR/NAME.png with its true points in NAME.pts; returns it as a photo.
inline TrainingPhoto savePhoto(const std::filesystem::path& dir, const std::string& name,
                               const FitScene& scene) {
  TrainingPhoto photo;
  photo.id = name + ".png";
  photo.image = dir / photo.id;
  writeImage(photo.image, scene.image);
  photo.points = LandmarkSet(static_cast<int>(scene.truthPoints.cols()), 2);
  for (int i = 0; i < photo.points.size(); ++i) {
    photo.points.set(i, Eigen::Vector2d(scene.truthPoints.col(i)));
  }
  photo.trusted.assign(static_cast<std::size_t>(photo.points.size()), true);
  writeLandmarks(dir / (name + ".pts"), photo.points, Scheme::thesis25());
  return photo;
}

// The refiner (three stages, with its check) learnt from the four heads at six small poses each.
inline const DescentRefiner& photoRefiner() {
  static const DescentRefiner refiner = [] {
    const TempDir dir;
    std::vector<TrainingPhoto> photos;
    for (int head = 0; head < 4; ++head) {
      for (const auto& [pitch, yaw] : {std::pair{0.0, -8.0},
                                       {5.0, 0.0},
                                       {-5.0, 6.0},
                                       {0.0, 12.0},
                                       {3.0, -3.0},
                                       {-3.0, -12.0}}) {
        photos.push_back(savePhoto(
            dir.path(), "h" + std::to_string(head) + "-" + std::to_string(static_cast<int>(yaw)),
            makeFitScene(fitTestModel(), pitch, yaw, head)));
      }
    }
    TrainSettings settings;
    settings.refinerStages = 3;
    settings.refinerStarts = 12;
    settings.threads = 2;
    return trainPhotoRefiner(photos, Scheme::thesis25(), settings);
  }();
  return refiner;
}

}  // namespace clm3d::test
