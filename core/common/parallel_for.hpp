// The project's one worker pool, in the manner of OpenCV's parallel_for_: runs body(i) for every
// i in [0, count) on a few threads, each index once, and hands the first exception back to the
// caller. Training's renders, photos and patch experts, the dataset's subject loading and the
// procedural head's texture all run through it, so there is one place where threads are started,
// joined, cancelled and checked by ThreadSanitizer (the tsan preset).
#pragma once

#include <functional>

#include "core/common/progress.hpp"

namespace clm3d {

// `threads` workers (0 = one per core; never more than `count`, at least 1) take indices in
// increasing order. The first exception a body throws stops the workers from taking new indices
// (bodies already running finish) and is rethrown once every worker has joined. With `cancel`,
// workers also stop taking indices once it fires, and parallelFor throws Cancelled after joining
// (unless a body threw first). The bodies must be safe to run concurrently; results that must not
// depend on the thread count belong in slots indexed by i. `body` and `cancel` must outlive the
// call (it returns only after every worker has joined).
void parallelFor(int count, int threads, const std::function<void(int)>& body,
                 const CancelToken* cancel = nullptr);

// The worker count parallelFor would use.
int workerCount(int count, int threads);

}  // namespace clm3d
