// Pictures of a trained model for a person to judge (thesis figures 3.3-3.12): mean patches per
// view and scale, alpha masks, which landmarks each view hides, and the shape modes at +-3 SD.
#pragma once

#include <filesystem>
#include <vector>

#include "core/model/clm_model.hpp"

namespace clm3d {

// Writes into `folder` (created if needed): mean-patches-scale<S>.png (a row per view, a column
// per landmark, hidden landmarks as dark tiles), alpha-scale<S>.png (the same for the alpha
// masks), hidden-landmarks.png (the mean shape seen from each view, hidden points hollow),
// shape-modes.png (the mean shape, frontal and side, at -3, 0, +3 SD of the first 3 modes).
// Returns the files written. Images are written atomically; InputError if one cannot be.
std::vector<std::filesystem::path> writeTrainingReport(const ClmModel& model,
                                                       const std::filesystem::path& folder);

}  // namespace clm3d
