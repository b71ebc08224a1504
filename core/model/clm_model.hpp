// A trained clm3d model: the scheme it was trained for, the shape model, every view's texture
// models (per scale), training settings and provenance. What `clm3d train` writes, `clm3d info`
// summarises and the fitter loads (file format: model_file.hpp, docs/model-file.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/model/descent_refiner.hpp"
#include "core/model/shape_model.hpp"
#include "core/model/texture_model.hpp"

namespace clm3d {

struct ModelProvenance {
  std::string dataset;      // the manifest the model was trained from
  std::string created;      // ISO 8601 UTC, e.g. 2024-05-01T12:00:00Z
  std::string toolVersion;  // clm3d version that trained it
  std::uint64_t seed = 0;   // training random seed
  std::string notes;
};

// Where an adapted model came from (`clm3d adapt`, core/train/model_adaptation.hpp): the general
// model, the video and the corrected frames it learnt from. Empty for a model trained from a
// dataset.
struct ModelAdaptation {
  std::string model;        // the general model's file, as given
  std::string modelCrc32;   // CRC-32 of that file's bytes, 8 lower-case hex digits
  std::string video;        // the video of the corrected frames
  std::string truth;        // the ground truth they were read from
  std::vector<int> frames;  // the corrected frames it learnt from, 0-based, ascending

  bool empty() const { return model.empty() && video.empty() && truth.empty() && frames.empty(); }
};

struct ClmModel {
  std::string schemeJson;  // the scheme file text (Scheme::fromJson(schemeJson, ...))
  ShapeModel shape;
  std::vector<ViewModel> views;  // 15 for the multi-view model; 1 (frontal) for the baseline
  bool singleView = false;
  double patchRatio = 0.24;  // patchSize / inter-ocular distance (pixels) at the finest scale
  std::string settingsJson;  // the training settings, as JSON (an object, or empty)
  ModelProvenance provenance;
  ModelAdaptation adaptation;  // format 8; empty unless the model was adapted to a video
  // Refinement of the fitted 2D points, learnt from annotated photos; empty when the model was
  // trained without photos (or asked not to train one).
  DescentRefiner refiner;

  // The scheme, parsed from schemeJson (throws InputError if it does not parse).
  Scheme scheme() const;
  // Throws Error describing the first inconsistency: "field views[3].scales[1].pca: ..." (sizes
  // vs scheme, visible vs landmarks, PCA dimensions, orthonormality, non-finite values...).
  void validate() const;
  // The stored (not mirrored) view of |yaw| `absYawDeg` at the pitch nearest 0: whose check
  // layout reads the photo fits of every view of that |yaw| (PhotoFitCurve's image term); -1 when
  // there is none.
  int photoFitLayoutView(double absYawDeg) const;
  // The view whose centre is nearest to (pitch, yaw) in degrees; -1 if there are no views.
  int nearestView(double pitchDeg, double yawDeg) const;
};

}  // namespace clm3d
