// A ground truth being made for a video: the tracker's table with one row per frame, the frames a
// person corrected by hand marked as keyframes, and linear interpolation between keyframes, so a
// whole video gets reference landmarks from a few hand-placed frames. Saved as a tracks CSV with a
// trailing "keyframe" column (clm3d eval and pandas read it unchanged) and optionally one .pts file
// per frame; docs/ground-truth.md describes the format and the rules.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <vector>

#include "core/track/track_table.hpp"

namespace clm3d {

struct GroundTruthSet {
  // One row per frame 0..n-1 (row i is frame i), the tracker's columns; a frame without points
  // has success = false and NaN points. Rows set by hand or interpolated have no pose, view -1
  // and confidence 1.
  TrackTable table;
  std::vector<bool> keyframe;  // per row: corrected by hand

  // Starts from a tracker output: its rows keep their values, frames it lacks up to frameCount
  // are added without points (timestamps from the track's frame rate when it has two timed
  // rows, else NaN). InputError if frameCount is negative or the track has a frame >= frameCount.
  static GroundTruthSet fromTrack(const TrackTable& track, int frameCount);

  int frameCount() const { return static_cast<int>(table.rows.size()); }
  int keyframeCount() const;
  // Adds rows without points up to frameCount (never removes any); keyframes are kept.
  void padTo(int frameCount);

  // Points of a hand-corrected frame (2 x n pixels, 0-based; a NaN column is a missing point):
  // success if any point is present, confidence 1, no pose, view -1, marked as a keyframe. A set
  // without landmarks yet (n = 0) takes its count from the first keyframe. InputError for a frame
  // outside 0..n-1 or a wrong point count.
  void setKeyframe(int frame, const Eigen::Matrix2Xd& points);
  // Keeps the points, but the frame is no longer a keyframe (InputError outside 0..n-1).
  void clearKeyframe(int frame);
  // Fills every frame strictly between two consecutive keyframes: a landmark present in both is
  // linear in the frame index (so is the timestamp when both are finite); one missing in either
  // stays missing. Filled rows: success if any point is present, confidence 1, no pose, view -1,
  // not keyframes. Returns the number of rows filled.
  int interpolateKeyframes();
};

// Writes the table (tracker columns + "keyframe" 0/1) atomically; with ptsFolder, also
// ptsFolder/frame_000042.pts for every frame (iBUG .pts, 1-based pixels on disk as pts_format.hpp
// documents, "nan nan" for missing points), created if needed. Error if the set is inconsistent
// (keyframe size, row i not frame i).
void saveGroundTruth(const std::filesystem::path& csv, const GroundTruthSet& set,
                     const std::filesystem::path& ptsFolder = {});
// The .pts file name of a frame: frame_000042.pts.
std::filesystem::path groundTruthPtsName(int frame);

// Reads a ground-truth CSV or a plain tracker CSV (no keyframe column: no keyframes). Frames the
// file lacks, up to its largest, are added without points; other extra columns are dropped.
// InputError naming the file (and line) for a malformed table, a keyframe cell other than 0/1, or
// a frame beyond kMaxGroundTruthFrames.
GroundTruthSet loadGroundTruth(const std::filesystem::path& csv);

// The set a table read from `source` holds (loadGroundTruth's rules): its rows as fromTrack gives
// them up to frameCount, keyframes from its keyframe column when it has one. InputError naming
// `source` (and the line lineOf gives a row, when given) for a keyframe cell other than 0/1 or a
// frame beyond kMaxGroundTruthFrames; fromTrack's for a frame at or beyond frameCount.
GroundTruthSet groundTruthFromTable(const TrackTable& table, int frameCount,
                                    const std::filesystem::path& source,
                                    const std::function<int(std::size_t)>& lineOf = {});

// Most frames a ground truth may have (about 9 hours at 30 fps), so a stray huge frame number is
// reported instead of allocating gigabytes.
inline constexpr int kMaxGroundTruthFrames = 1'000'000;

}  // namespace clm3d
