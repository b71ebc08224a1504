// Training as `clm3d train`, the studio's Train page and `clm3d demo --real` run it: the model
// trained from a dataset manifest (trainFromManifest), then, when the manifest names
// `calibration_photos`, its point check calibrated on the photo pipeline's own fits of them
// (calibratePhotoFits, as `clm3d calibrate` does). Here, after the track stage, because the
// calibration runs the whole still-image pipeline; the train stage cannot.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/dataset/manifest.hpp"
#include "core/eval/photo_fit_calibration.hpp"
#include "core/train/trainer.hpp"

namespace clm3d {

struct CalibratedTraining {
  ClmModel model;
  TrainingDetails details;
  // Set when the manifest names calibration photos and their curves went into the model.
  std::optional<PhotoFitCalibration> calibration;
  PhotoFitCalibrationSettings calibrationSettings;  // what it ran with (for its table)
  // Why the manifest's calibration photos were not used (the trained model has no point check,
  // too few right or wrong fits, an unreadable truth file); the model is then the trained one.
  // Empty otherwise.
  std::string calibrationSkipped;
};

// The calibration photos of a manifest (every `every`-th of the folder or list from `offset`)
// and their truth files beside them. InputError naming the list or an image without a truth
// file; InputError naming the first photo that a `photos` source also gives the point refiner
// (a check calibrated on the photos it learnt from would be too sure of itself).
struct CalibrationPhotoFiles {
  std::vector<std::filesystem::path> images, truths;
};
CalibrationPhotoFiles calibrationPhotoFiles(const DatasetManifest& manifest);

// Trains (progress as trainFromManifest's, then the stage "photo-fit calibration") and
// calibrates. The calibration photos are listed before training, so that a bad list fails at
// once rather than after the training. Cancelled on `cancel`.
CalibratedTraining trainAndCalibrate(const std::filesystem::path& manifest,
                                     const TrainSettings& settings, const std::string& toolVersion,
                                     const ProgressCallback& progress = {},
                                     const CancelToken* cancel = nullptr);

}  // namespace clm3d
