// The landmarks a training render is framed on. The face size of a render comes from the
// distance between the scheme's normalisation pair (the eye centres); a scan whose eyes are closed
// has them missing. For such a subject the pair is imputed from the other subjects and shape-only
// sets (each aligned onto it by a similarity on their common points), for framing only: the patches
// of the missing points are still not sampled.
#pragma once

#include <utility>
#include <vector>

#include "core/scheme/landmark_set.hpp"

namespace clm3d {

// `all[index]` with the points of `pair` filled in when missing: the mean over the other sets
// that have both points of their positions after a similarity aligning that set onto
// `all[index]` on the points both have (at least 3). Points other than the pair are copied as
// they are. Throws InputError naming `id` when a point of the pair is missing and no other set
// can supply it.
LandmarkSet framingLandmarks(const std::vector<const LandmarkSet*>& all, std::size_t index,
                             std::pair<int, int> pair, const std::string& id);

}  // namespace clm3d
