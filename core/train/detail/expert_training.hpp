// Trains one discriminative patch expert (core/model/patch_expert.hpp) from regions around the
// true landmark position: patches at the true position and its 8 neighbours against displaced
// patches up to the region's radius. A ridge regression of the normalised patch onto a Gaussian
// of the displacement (1 pixel SD) gives the filter; a logistic fit of its scores (true position
// against displacements of 2 pixels or more, the two classes weighted equally) gives gain and
// bias. Closed form and deterministic, so training time is predictable and models reproducible.
// With more than one unit, that expert is grown into a neural field (patch_expert.hpp) by
// mini-batch Adam on the same windows against the Gaussian targets, seeded and single-threaded, so
// still deterministic; it is kept only where it beats the linear expert on held-out regions.
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "core/model/patch_expert.hpp"

namespace clm3d {

struct ExpertTrainingSettings {
  int patchSize = 20;
  int radius = 6;               // regions are patchSize + 2 radius pixels square
  int negativesPerRegion = 16;  // displaced patches drawn per region (2..radius pixels away)
  double ridge = 0.1;           // ridge weight relative to the mean diagonal of the data's Gram
  std::uint64_t seed = 1;       // the draw of the displacements
  int units = 1;                // 1: a linear filter with a logistic output; more: a neural field
  int epochs = 8;               // neural field: passes over the training windows
  float learningRate = 1e-3f;   // neural field: Adam's initial step (decays to a tenth)
};

// `regions`: one column per training region, (patchSize + 2 radius)^2 raw grey values each,
// row-major, centred on the landmark (core/fit/response_map.hpp sampleRegion). Throws Error if
// there are no regions or their size does not match. An expert trained on fewer than a handful of
// regions is valid but weak; the caller decides whether to train one.
PatchExpert trainPatchExpert(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                             const ExpertTrainingSettings& settings);

// The expert `general` (one unit: a linear filter with a logistic output) moved towards `regions`
// of one person: the filter minimises the same regression's squared error on the regions'
// windows plus priorRegions x (windows per region) x |w - w_general|^2, i.e. the general filter
// is a Gaussian prior worth `priorRegions` regions (maximum a posteriori adaptation, as a
// speaker-adapted GMM keeps its universal model's means with a relevance factor): few regions
// leave it nearly as it was, many outweigh it. The logistic gain and bias are fitted afresh to the
// new filter's scores on the regions. settings.ridge is not used (the prior takes its place).
// Throws Error for a general expert of more than one unit or of another patch size, and for
// regions trainPatchExpert would refuse.
PatchExpert adaptPatchExpert(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                             const ExpertTrainingSettings& settings, const PatchExpert& general,
                             double priorRegions);

}  // namespace clm3d
