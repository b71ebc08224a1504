#include "core/eval/error_buckets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/error.hpp"

namespace clm3d {

std::vector<double> bucketEdges(const BucketSpec& spec,
                                const std::vector<SequenceEvaluation>& evaluations) {
  const bool haveEdges = !spec.edges.empty();
  const bool haveWidth = spec.width != 0.0;
  if (haveEdges == haveWidth) {
    throw InputError("buckets: give either edges or a width");
  }
  if (haveEdges) {
    if (spec.edges.size() < 2) throw InputError("buckets: at least two edges are needed");
    for (std::size_t k = 0; k < spec.edges.size(); ++k) {
      if (!std::isfinite(spec.edges[k]) || (k > 0 && !(spec.edges[k] > spec.edges[k - 1]))) {
        throw InputError("buckets: the edges must be finite and increasing");
      }
    }
    return spec.edges;
  }
  if (!(spec.width > 0.0) || !std::isfinite(spec.width)) {
    throw InputError("buckets: the width must be positive");
  }
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const auto& evaluation : evaluations) {
    for (const auto& frame : evaluation.frames) {
      if (!std::isfinite(frame.key)) continue;
      low = std::min(low, frame.key);
      high = std::max(high, frame.key);
    }
  }
  if (!(low <= high)) {
    throw InputError("buckets: no frame has a value in column \"" + spec.column + "\"");
  }
  const double first = std::floor(low / spec.width) * spec.width;
  double last = std::ceil(high / spec.width) * spec.width;
  if (last <= first) last = first + spec.width;
  std::vector<double> edges;
  const int count = static_cast<int>(std::lround((last - first) / spec.width));
  for (int k = 0; k <= count; ++k) edges.push_back(first + k * spec.width);
  return edges;
}

int bucketIndexOf(double value, const std::vector<double>& edges) {
  if (edges.size() < 2 || !std::isfinite(value) || value < edges.front() || value > edges.back()) {
    return -1;
  }
  const auto above = std::upper_bound(edges.begin(), edges.end(), value);
  const int index = static_cast<int>(above - edges.begin()) - 1;
  return std::min(index, static_cast<int>(edges.size()) - 2);  // the high edge joins the last
}

BucketedErrors bucketErrors(const std::vector<SequenceEvaluation>& evaluations,
                            const BucketSpec& spec, const Scheme& scheme,
                            const EvalOptions& options) {
  BucketedErrors result;
  result.column = spec.column;
  result.absolute = spec.absolute;
  result.edges = bucketEdges(spec, evaluations);
  const std::size_t bucketCount = result.edges.size() - 1;
  for (const auto& evaluation : evaluations) {
    std::vector<std::vector<FrameError>> members(bucketCount);
    int outside = 0;
    for (const auto& frame : evaluation.frames) {
      const int bucket = bucketIndexOf(frame.key, result.edges);
      if (bucket < 0) {
        ++outside;
        continue;
      }
      members[static_cast<std::size_t>(bucket)].push_back(frame);
    }
    std::vector<ErrorBucket> buckets;
    for (std::size_t b = 0; b < bucketCount; ++b) {
      ErrorBucket bucket;
      bucket.low = result.edges[b];
      bucket.high = result.edges[b + 1];
      bucket.summary = summariseFrames(members[b], scheme, options);
      buckets.push_back(std::move(bucket));
    }
    result.buckets.push_back(std::move(buckets));
    result.outside.push_back(outside);
  }
  return result;
}

std::string bucketColumnTitle(const BucketedErrors& buckets) {
  return buckets.absolute ? "|" + buckets.column + "|" : buckets.column;
}

}  // namespace clm3d
