#include "core/eval/calibrated_training.hpp"

#include <algorithm>

#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/detect/detector_evaluation.hpp"

namespace clm3d {
namespace fs = std::filesystem;

namespace {

// Training takes most of the time: the real-face model trains in about 200 s on 2 cores and its
// 1,227 calibration photos are fitted in about 90 s.
constexpr double kTrainingShare = 0.75;

// Every image a `photos` source gives the point refiner, as absolute, normal paths.
std::vector<fs::path> refinerPhotos(const DatasetManifest& manifest) {
  std::vector<fs::path> out;
  for (const PhotoSource& source : manifest.photos) {
    if (!source.refiner) continue;
    std::vector<fs::path> images = listImages(source.folder.empty() ? source.list : source.folder);
    if (source.limit > 0 && static_cast<int>(images.size()) > source.limit)
      images.resize(static_cast<std::size_t>(source.limit));
    for (const fs::path& image : images) out.push_back(fs::absolute(image).lexically_normal());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

CalibrationPhotoFiles calibrationPhotoFiles(const DatasetManifest& manifest) {
  CalibrationPhotoFiles files;
  if (!manifest.calibrationPhotos) return files;
  const CalibrationPhotos& photos = *manifest.calibrationPhotos;
  const fs::path source = photos.folder.empty() ? photos.list : photos.folder;
  const std::vector<fs::path> all = listImages(source);
  for (std::size_t i = static_cast<std::size_t>(photos.offset); i < all.size();
       i += static_cast<std::size_t>(photos.every)) {
    files.images.push_back(all[i]);
  }
  if (files.images.empty()) {
    throwInputError(source, "gives no calibration photo at offset " +
                                std::to_string(photos.offset) + " (of " +
                                std::to_string(all.size()) + " images)");
  }
  const std::vector<fs::path> refiner = refinerPhotos(manifest);
  for (const fs::path& image : files.images) {
    if (std::binary_search(refiner.begin(), refiner.end(),
                           fs::absolute(image).lexically_normal())) {
      throwInputError(manifest.file,
                      "calibration_photos: " + image.string() +
                          " also trains the point refiner and its check (a photos source with "
                          "\"refiner\": true); calibrate on photos the check did not learn from");
    }
  }
  files.truths = findTruthFiles(files.images, {});
  return files;
}

CalibratedTraining trainAndCalibrate(const fs::path& manifestPath, const TrainSettings& settings,
                                     const std::string& toolVersion,
                                     const ProgressCallback& progress, const CancelToken* cancel) {
  const DatasetManifest manifest = loadManifest(manifestPath);
  const CalibrationPhotoFiles photos = calibrationPhotoFiles(manifest);
  const bool calibrate = !photos.images.empty();
  const double trainingShare = calibrate ? kTrainingShare : 1.0;

  CalibratedTraining out;
  out.model = trainFromManifest(
      manifestPath, settings, toolVersion,
      [&](double fraction, std::string_view stage) {
        if (progress) progress(trainingShare * fraction, stage);
      },
      cancel, &out.details);
  if (!calibrate) return out;
  if (out.model.refiner.check.empty()) {
    out.calibrationSkipped =
        "the trained model has no point check to calibrate (a model trained "
        "with 20 or more photos for the refiner has one)";
    return out;
  }
  out.calibrationSettings.rightBelow = manifest.calibrationPhotos->rightBelow;
  out.calibrationSettings.minEach = manifest.calibrationPhotos->minEach;
  out.calibrationSettings.imageMinFits = manifest.calibrationPhotos->imageMinFits;
  out.calibrationSettings.threads = settings.threads;
  try {
    PhotoFitCalibration calibration = calibratePhotoFits(
        out.model, photos.images, photos.truths, out.calibrationSettings,
        [&](double fraction, std::string_view) {
          if (progress)
            progress(trainingShare + (1.0 - trainingShare) * fraction, "photo-fit calibration");
        },
        cancel);
    const CalibrationPhotos& source = *manifest.calibrationPhotos;
    applyPhotoFitCalibration(out.model, calibration,
                             source.folder.empty() ? source.list : source.folder);
    out.calibration = std::move(calibration);
  } catch (const InputError& e) {
    // The training is kept: a calibration that cannot be learnt leaves the check's own scale.
    out.calibrationSkipped = e.what();
  }
  return out;
}

}  // namespace clm3d
