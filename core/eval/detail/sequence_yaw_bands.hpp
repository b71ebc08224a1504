// `clm3d eval --yaw-bands`: a tracker's errors per |yaw| band of the head, the pose-aware view of
// a sequence evaluation (docs/evaluation.md, "Yaw bands"). Each truth frame's yaw is that of the
// truth's own pose (the yaw column of a rendered or synthesised sequence) or, where a row has no
// pose (a hand-corrected truth), that of the model fitted to the truth's points; the bands are the
// buckets of error_buckets (one band rule, bucketIndexOf), and each band reports the frames, the
// share the tracker fitted, the error over the truth's face box and over the eye distance.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/eval/eval_report.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

// Evaluates like evaluateTrackFiles with buckets over |yaw| at `edges` (parseBandEdges), then,
// with a model (may be null; kept alive by the caller for the call only), gives every frame whose
// truth row has no yaw the |yaw| of the model fitted to that row's points (fittedYawDeg with
// verticalFovDeg) and buckets again; BucketedErrors::source says how many frames that was.
// InputError as evaluateTrackFiles, or when the model's scheme is not `scheme`.
EvaluationReport evaluateTrackFilesByYaw(const std::vector<std::filesystem::path>& truths,
                                         const std::vector<TrackerFiles>& trackers,
                                         const Scheme& scheme, const EvalOptions& options,
                                         const std::vector<double>& edges, const ClmModel* model,
                                         double verticalFovDeg);

// The report's yaw bands (it must have been made by evaluateTrackFilesByYaw) as band lines
// (formatBandLines: per band and tracker the frames, the frames reported tracked, the errors over
// the face box and the eye distance, points within the threshold) and as Markdown with the
// trackers side by side.
std::string formatSequenceYawBands(const EvaluationReport& report);
std::string formatSequenceYawBandMarkdown(const EvaluationReport& report);
// formatReportJson's document with "yaw_bands": {"source", "edges", "trackers": [{"label",
// "outside", "bands": [{"min_abs_yaw", "max_abs_yaw", "frames", "fitted", "mean_box_error",
// "median_box_error", "mean_error", "points_within_threshold"}]}]} (NaN is null).
std::string formatYawBandReportJson(const EvaluationReport& report);

}  // namespace clm3d
