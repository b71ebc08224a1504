// Draws the points of a compared track (a ground truth, another model's track) over a frame, as
// hollow magenta diamonds that stay readable on top of the track's own filled landmarks, so two
// tracks of one video can be reviewed overlaid. Plain OpenCV drawing, no widget.
#pragma once

#include <opencv2/core.hpp>

#include "core/track/track_table.hpp"

namespace clm3d::ui {

// The frame with `frame`'s points of `compared` drawn on a copy; the frame itself (not copied)
// when the table has no row with points for that frame.
cv::Mat withComparedPoints(const cv::Mat& image, const TrackTable& compared, int frame);

// The compared table's row for `frame` (rows need not be in frame order), or nullptr.
const TrackRow* comparedRow(const TrackTable& compared, int frame);

}  // namespace clm3d::ui
