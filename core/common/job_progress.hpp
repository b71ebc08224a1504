// Jobs finished on worker threads, reported to a ProgressCallback as a rising share: the count is
// raised and its share reported under one lock, so reports arrive one at a time and in the order
// counted. Raising an atomic counter and reporting after it, as parallel loops did, lets another
// thread's later share be reported first, and a progress bar go back (the demo's render test saw
// it one run in fifteen). The callback must outlive the JobProgress.
#pragma once

#include <mutex>
#include <string>

#include "core/common/progress.hpp"

namespace clm3d {

class JobProgress {
 public:
  // Reports from + (to - from) * finished / jobs under `stage`; an empty callback reports nothing.
  JobProgress(const ProgressCallback& progress, int jobs, std::string stage, double from = 0.0,
              double to = 1.0);

  // One more job finished (any thread). Returns how many have finished.
  int finished();

 private:
  const ProgressCallback& progress_;
  int jobs_;
  std::string stage_;
  double from_;
  double to_;
  std::mutex mutex_;
  int done_ = 0;
};

}  // namespace clm3d
