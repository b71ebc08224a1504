// The trainer: builds a whole ClmModel (shape model + per-view texture models, settings and
// provenance) from textured subjects and shape-only landmark sets, or from a dataset manifest.
// Safe to run on a worker thread: reports progress, stops on the cancel token (throws Cancelled)
// and never prints.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/dataset/training_photos.hpp"
#include "core/model/clm_model.hpp"
#include "core/train/photo_samples.hpp"
#include "core/train/texture_training.hpp"
#include "core/train/train_settings.hpp"
#include "core/train/view_calibration.hpp"

namespace clm3d {

struct TrainingInput {
  std::string schemeJson;  // the scheme's JSON text (see schemeJsonFor)
  std::vector<TrainingSubject> subjects;
  std::vector<LandmarkSet> shapeOnly;  // extra shapes for the shape model (no texture)
  std::vector<TrainingPhoto> photos;   // annotated photos for the texture models and experts
  std::string datasetName;             // provenance
  std::string toolVersion;             // provenance
};

// What a training run did beside the model, for its report.
struct TrainingDetails {
  std::vector<PhotoPlacement> placements;       // per photo: where it went, or why it was skipped
  std::vector<ViewCalibrationRow> calibration;  // per calibrated view (none without photos)
};

// The time now as a model's provenance records it: ISO 8601 UTC, e.g. 2024-05-01T12:00:00Z.
std::string utcNow();

// The JSON text of a scheme given as "thesis25", "ibug68" or a path to a scheme file.
std::string schemeJsonFor(const std::string& nameOrPath);

// Shape model from every subject's landmarks plus the shape-only sets; texture models from
// renders of the subjects. Progress stages: "shape", "rendering", "pca". settings.singleView
// makes the 2D baseline (one frontal view, 2D shape model).
// With photos, progress stages "photos" and, after the refiner, "calibration": the views put on one
// scale (core/train/view_calibration.hpp). `details` (optional) gets where each photo went and
// the views' calibration.
ClmModel trainModel(const TrainingInput& input, const TrainSettings& settings,
                    const ProgressCallback& progress = {}, const CancelToken* cancel = nullptr,
                    TrainingDetails* details = nullptr);

// Loads the manifest's subjects and shape samples (stage "loading") and trains on them.
ClmModel trainFromManifest(const std::filesystem::path& manifest, const TrainSettings& settings,
                           const std::string& toolVersion, const ProgressCallback& progress = {},
                           const CancelToken* cancel = nullptr, TrainingDetails* details = nullptr);

}  // namespace clm3d
