#include "core/train/trainer.hpp"

#include <chrono>
#include <ctime>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/train/refiner_training.hpp"

namespace clm3d::embedded {
std::string_view thesis25SchemeJson();
std::string_view ibug68SchemeJson();
}  // namespace clm3d::embedded

namespace clm3d {

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string schemeJsonFor(const std::string& nameOrPath) {
  if (nameOrPath == "thesis25") return std::string(embedded::thesis25SchemeJson());
  if (nameOrPath == "ibug68") return std::string(embedded::ibug68SchemeJson());
  return readTextFile(nameOrPath);
}

ClmModel trainModel(const TrainingInput& input, const TrainSettings& settings,
                    const ProgressCallback& progress, const CancelToken* cancel,
                    TrainingDetails* details) {
  settings.validate();
  const Scheme scheme = Scheme::fromJson(input.schemeJson, "training scheme");
  if (cancel) cancel->throwIfCancelled();
  if (progress) progress(0.0, "shape");

  ClmModel model;
  model.schemeJson = input.schemeJson;
  std::vector<LandmarkSet> shapes;
  for (const TrainingSubject& subject : input.subjects) {
    if (subject.landmarks) shapes.push_back(*subject.landmarks);
  }
  shapes.insert(shapes.end(), input.shapeOnly.begin(), input.shapeOnly.end());
  ShapeModelSettings shapeSettings = settings.shape;
  if (settings.singleView) shapeSettings.dims = 2;
  model.shape = buildShapeModel(shapes, scheme, shapeSettings);

  const double photoShare = input.photos.empty() ? 0.0 : 0.1;
  std::vector<PhotoSample> photoSamples;
  std::vector<PhotoPlacement> placements;
  if (!input.photos.empty()) {
    const auto photoProgress = [&](double fraction, std::string_view stage) {
      if (progress) progress(0.02 + photoShare * fraction, stage);
    };
    photoSamples = preparePhotoSamples(input.photos, input.schemeJson, model.shape, settings,
                                       &placements, photoProgress, cancel);
  }
  // With photos, the last 10% is the point refiner's and the views' calibration.
  const double textureEnd = input.photos.empty() ? 1.0 : settings.calibrateViews ? 0.9 : 0.95;
  const auto textureProgress = [&](double fraction, std::string_view stage) {
    if (progress) progress(0.02 + photoShare + (textureEnd - 0.02 - photoShare) * fraction, stage);
  };
  const auto refinerProgress = [&](double fraction, std::string_view stage) {
    if (progress) progress(textureEnd + 0.05 * fraction, stage);
  };
  const auto calibrationProgress = [&](double fraction, std::string_view stage) {
    if (progress) progress(textureEnd + 0.05 + 0.05 * fraction, stage);
  };
  model.views = trainTextureModels(input.subjects, scheme, settings, textureProgress, cancel,
                                   input.shapeOnly, photoSamples);
  if (!input.photos.empty()) {
    model.refiner = trainPhotoRefiner(input.photos, scheme, settings, refinerProgress, cancel);
  }
  if (!input.photos.empty() && settings.calibrateViews) {
    ViewCalibrationSettings calibration;
    calibration.seed = settings.seed;
    calibration.threads = settings.threads;
    std::vector<ViewCalibrationRow> rows =
        calibrateViews(model, input.photos, placements, calibration, calibrationProgress, cancel);
    if (details) details->calibration = std::move(rows);
  }
  if (details) details->placements = std::move(placements);
  model.singleView = settings.singleView;
  model.patchRatio = settings.patchRatio;
  model.settingsJson = settings.toJson();
  model.provenance.dataset = input.datasetName;
  model.provenance.created = utcNow();
  model.provenance.toolVersion = input.toolVersion;
  model.provenance.seed = settings.seed;
  model.provenance.notes = std::to_string(input.subjects.size()) + " textured subjects, " +
                           std::to_string(input.shapeOnly.size()) + " shape-only sets";
  if (!input.photos.empty()) {
    model.provenance.notes += ", " + std::to_string(photoSamples.size()) + " photo samples from " +
                              std::to_string(input.photos.size()) +
                              " annotated photos (the model inherits the photos' licence terms)";
  }
  model.validate();
  return model;
}

}  // namespace clm3d
