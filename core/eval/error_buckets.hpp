// The error of thesis eq. 5.1 broken down by a per-frame quantity of the ground truth, e.g. the
// head's |yaw| in 15-degree steps (the thesis's figures 5.6 and 5.11 read errors against the
// rotation): every bucket gets the full summary of its frames (mean, median, convergence, points
// within the threshold, regions), computed by landmark_error's one implementation. The frames'
// values come from EvalOptions::keyColumn (FrameError::key).
#pragma once

#include <string>
#include <vector>

#include "core/eval/landmark_error.hpp"

namespace clm3d {

// Either explicit edges (increasing, at least two) or a width (> 0) from which edges are laid on
// multiples of the width covering every frame's value.
struct BucketSpec {
  std::string column;  // the truth column (trackColumnValue), e.g. "yaw"
  bool absolute = false;
  std::vector<double> edges;
  double width = 0.0;
};

struct ErrorBucket {
  double low = 0.0;  // frames with low <= value < high (the last bucket includes its high edge)
  double high = 0.0;
  ErrorSummary summary;  // of the bucket's frames (motion figures NaN)
};

struct BucketedErrors {
  std::string column;
  bool absolute = false;
  std::vector<double> edges;
  // Per evaluation (tracker), one per bucket.
  std::vector<std::vector<ErrorBucket>> buckets;
  // Per evaluation: truth frames whose value is outside the edges or missing (not in any bucket).
  std::vector<int> outside;
  // Where the values came from when not only from the column (e.g. "yaw of the truth; 12 frames
  // without one: of model M fitted to the truth's points"); empty otherwise.
  std::string source;
};

// The bucket of a value: k for edges[k] <= value < edges[k+1], the last bucket including its high
// edge; -1 for a NaN value or one outside the edges. The one band rule of clm3d eval's buckets and
// eval-points' yaw bands (yawBandOf).
int bucketIndexOf(double value, const std::vector<double>& edges);

// The edges of spec over the evaluations' frame keys. Throws InputError for edges that do not
// increase, fewer than two of them, a width that is not positive, both or neither given, or (for a
// width) no frame with a finite value.
std::vector<double> bucketEdges(const BucketSpec& spec,
                                const std::vector<SequenceEvaluation>& evaluations);

// Buckets every evaluation's frames by FrameError::key (the evaluations must have been made with
// EvalOptions::keyColumn = spec.column and keyAbsolute = spec.absolute).
BucketedErrors bucketErrors(const std::vector<SequenceEvaluation>& evaluations,
                            const BucketSpec& spec, const Scheme& scheme,
                            const EvalOptions& options = {});

// "|yaw|" for an absolute column, else the name.
std::string bucketColumnTitle(const BucketedErrors& buckets);

}  // namespace clm3d
