// trainFromManifest: the dataset stage's loaders followed by trainModel.
#include "core/dataset/manifest.hpp"
#include "core/dataset/training_photos.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/train/trainer.hpp"

namespace clm3d {

ClmModel trainFromManifest(const std::filesystem::path& manifestPath,
                           const TrainSettings& requested, const std::string& toolVersion,
                           const ProgressCallback& progress, const CancelToken* cancel,
                           TrainingDetails* details) {
  requested.validate();
  const DatasetManifest manifest = loadManifest(manifestPath);
  TrainSettings settings = requested;
  settings.augmentation =
      requested.augmentationFromManifest ? manifest.augmentation : AugmentationSettings::off();
  const auto loadingProgress = [&](double fraction, std::string_view) {
    if (progress) progress(0.25 * fraction, "loading");
  };
  const std::vector<TexturedSubject> subjects =
      loadTexturedSubjects(manifest, settings.threads, loadingProgress, cancel);
  const auto shapeProgress = [&](double fraction, std::string_view) {
    if (progress) progress(0.25 + 0.05 * fraction, "loading");
  };
  std::vector<LandmarkSet> shapeOnly =
      sampleShapeOnlyLandmarks(manifest, settings.seed, shapeProgress, cancel);

  TrainingInput input;
  input.schemeJson = schemeJsonFor(manifest.scheme);
  for (const TexturedSubject& subject : subjects) {
    input.subjects.push_back({subject.id, &subject.mesh, &subject.landmarks});
  }
  input.shapeOnly = std::move(shapeOnly);
  input.photos = loadTrainingPhotos(manifest);
  input.datasetName = manifest.name + " (" + manifest.file.string() + ")";
  input.toolVersion = toolVersion;
  const auto trainingProgress = [&](double fraction, std::string_view stage) {
    if (progress) progress(0.3 + 0.7 * fraction, stage);
  };
  return trainModel(input, settings, trainingProgress, cancel, details);
}

}  // namespace clm3d
