// The project's one worker pool, in the manner of OpenCV's parallel_for_: runs body(i) for every
// i in [0, count) on a few threads, each index once, and hands the first exception back to the
// caller. Training's renders, photos and patch experts all run through it.
#pragma once

#include <functional>

namespace clm3d {

// `threads` workers (0 = one per core; never more than `count`, at least 1) take indices in
// increasing order. The first exception a body throws stops the workers from taking new indices
// (bodies already running finish) and is rethrown once every worker has joined. The bodies must
// be safe to run concurrently; results that must not depend on the thread count belong in slots
// indexed by i.
void parallelFor(int count, int threads, const std::function<void(int)>& body);

// The worker count parallelFor would use.
int workerCount(int count, int threads);

}  // namespace clm3d
