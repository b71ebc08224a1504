// What the frame view draws on each landmark from what the tracker wrote for the frame (tracks
// CSV visible_k and conf_k, core/track/track_table.hpp): hidden landmarks hollow, landmarks whose
// own confidence is below the tracker's threshold ringed. A landmark a person has moved is the
// person's, so the fit's confidence no longer speaks for it and it is not ringed.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/track/track_table.hpp"
#include "ui/track/frame_view.hpp"

namespace clm3d::ui {

// One mark per column of `shown` (the points on screen): hidden where tracked.visibility says so;
// low confidence where tracked.landmarkConfidence is below `threshold` and the shown point is
// still where the tracker put it (within half a pixel). Without a tracked row, no marks.
std::vector<LandmarkMark> landmarkMarks(const TrackRow* tracked, const Eigen::Matrix2Xd& shown,
                                        double threshold);

}  // namespace clm3d::ui
