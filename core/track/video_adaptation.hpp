// A model adapted to one video from its corrected frames (issue 29): the ground truth's keyframes
// (frames a person corrected, core/track/ground_truth.hpp) read from the video and handed to
// core/train/model_adaptation, and the adapted model told where it came from (the general model's
// file and checksum, the video, the truth, the frames). What `clm3d adapt` (adapt_request) and the
// studio's Adapt action run; safe on a worker thread.
#pragma once

#include <filesystem>
#include <vector>

#include "core/common/progress.hpp"
#include "core/model/clm_model.hpp"
#include "core/track/ground_truth.hpp"
#include "core/train/model_adaptation.hpp"

namespace clm3d {

// The frames of `truth` that are keyframes with points, in frame order.
std::vector<int> correctedFrames(const GroundTruthSet& truth);

// Adapts `general` (loaded from `generalPath`, whose bytes give the recorded checksum) to the
// corrected frames of `truth` (read from `truthPath`, named in errors and the provenance) in
// `video`. Progress stages "reading frames", then adaptModel's. InputError naming the file: a
// truth whose landmark count is not the model's, one without corrected frames, a video that cannot
// be read or is shorter than a corrected frame; adaptModel's errors; Cancelled when cancelled.
ClmModel adaptToVideo(const ClmModel& general, const std::filesystem::path& generalPath,
                      const std::filesystem::path& video, const GroundTruthSet& truth,
                      const std::filesystem::path& truthPath, const AdaptSettings& settings,
                      AdaptationSummary* summary = nullptr, const ProgressCallback& progress = {},
                      const CancelToken* cancel = nullptr);

}  // namespace clm3d
