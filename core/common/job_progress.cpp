#include "core/common/job_progress.hpp"

#include <algorithm>
#include <utility>

namespace clm3d {

JobProgress::JobProgress(const ProgressCallback& progress, int jobs, std::string stage, double from,
                         double to)
    : progress_(progress),
      jobs_(std::max(jobs, 1)),
      stage_(std::move(stage)),
      from_(from),
      to_(to) {}

int JobProgress::finished() {
  const std::lock_guard lock(mutex_);
  ++done_;
  if (progress_) progress_(from_ + (to_ - from_) * std::min(done_, jobs_) / jobs_, stage_);
  return done_;
}

}  // namespace clm3d
