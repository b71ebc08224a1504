// The tracker's per-frame output as a table: one row per frame with its time, success,
// confidence, selected view, head pose, the 2D landmarks and whether each is visible. `clm3d track`
// writes it, `clm3d synth` writes ground truth in the same columns, `clm3d eval` and the studio
// read both. CSV so that spreadsheets, pandas and R read it directly (columns: docs/tracks-csv.md).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/pose.hpp"

namespace clm3d {

// Whether a landmark is visible from the fitted pose (rule: docs/tracks-csv.md, visible_k).
enum class Visibility : signed char { Unknown = -1, Hidden = 0, Visible = 1 };

struct TrackRow {
  int frame = 0;           // 0-based frame index in the video
  double timestamp = 0.0;  // seconds from the start of the video
  bool success = false;    // the tracker believes the landmarks are on the face
  // Template optimisers: mean NCC of the landmarks' patches in [-1, 1]; rlms: the patch experts'
  // mean response in (0, 1); 1 for ground truth.
  double confidence = 0.0;
  int view = -1;             // index of the model view used; -1 if none
  std::optional<Pose> pose;  // absent when the frame has no fit
  // 2 x n pixels (OpenCV convention, 0-based, pixel centres at integers); a NaN column is a
  // landmark without a position (written as empty cells).
  Eigen::Matrix2Xd points;
  // Per landmark (n entries), or empty: unknown for every landmark (no fit, a reference frame, or
  // a table without visible_k columns).
  std::vector<Visibility> visibility{};
  // Per landmark (n entries), or empty: the fit's confidence in each point on the scale of
  // `confidence` (FitResult::landmarkConfidence), NaN where there is none (a landmark the view
  // does not model). Empty for ground truth and tables without conf_k columns.
  std::vector<double> landmarkConfidence{};
  // One text cell per TrackTable::extraColumns entry (fewer: the rest are empty).
  std::vector<std::string> extraCells{};
  // The video declares this frame but it could not be decoded: no image was tracked (success 0,
  // no pose, no points). Written as "unreadable" in the status column, which a table has only
  // when some row is unreadable (docs/tracks-csv.md).
  bool unreadable = false;
};

struct TrackTable {
  int landmarkCount = 0;  // n: columns x_1..x_n, y_1..y_n
  std::vector<TrackRow> rows;
  // Named columns beyond the tracker's, written after y_n in this order, so a file can carry
  // more per frame (a ground truth's "keyframe" flag) and still read as a plain track table.
  std::vector<std::string> extraColumns{};
};

// Columns, in order: frame, timestamp, success (0/1), confidence, view, tx, ty, tz, scale,
// pitch, yaw, roll (degrees), x_1..x_n, y_1..y_n, visible_1..visible_n (1, 0, or empty for
// unknown; only when some row has a visibility), conf_1..conf_n (only when some row has
// landmark confidences), status ("unreadable" or empty; only when some row is unreadable), then
// the extra columns. Missing values are empty cells. Written
// atomically (temporary file, then rename). Throws Error if a row's point count is not
// landmarkCount, a row's visibility or landmark confidences are neither empty nor landmarkCount
// long, a row has more
// extra cells than there are extra columns, or an extra column's name or cell is empty (names
// only), holds a comma, quote or line break, or repeats a column.
void writeTrackTable(const std::filesystem::path& path, const TrackTable& table);
std::string formatTrackTable(const TrackTable& table);

// Reads a table written by writeTrackTable (or by another tool with the same header; column order
// is taken from the header; without visible_k columns every row's visibility is empty, with them
// every row's has n entries; the same for conf_k and landmarkConfidence). Throws InputError naming
// the file, the line and the column for a missing column, a malformed number or a wrong cell count.
// Columns the table does not use come back as extraColumns (header order, named ones only) with
// their cells. A frame appears on one line, or on one line per face when there is a `face` column
// (clm3d track --faces); a repeat is an InputError naming both lines. A status cell other than
// empty or "unreadable" is an InputError.
TrackTable readTrackTable(const std::filesystem::path& path);
TrackTable parseTrackTable(const std::string& text, const std::string& sourceName);

// Frames first .. first + count - 1.
struct FrameSpan {
  int first = 0;
  int count = 0;
  bool operator==(const FrameSpan&) const = default;
};

// Marks the rows of the frames in `spans` unreadable in the table written at `path` (by
// writeTrackTable or a TrackTableWriter), adding the status column: how `clm3d track` and `clm3d
// batch`, which stream their rows before they know whether a frame will be missing, mark the frames
// a damaged video lacked. Reads the whole table (only damaged videos pay for it); written
// atomically. InputError naming the file if it cannot be read or written.
void markUnreadableFrames(const std::filesystem::path& path, const std::vector<FrameSpan>& spans);

// The numeric columns a row can be looked up by: frame, timestamp, success, confidence, view, the
// pose's tx, ty, tz, scale, pitch, yaw, roll (degrees, as written), then the extra columns.
std::vector<std::string> numericTrackColumns(const TrackTable& table);
// The value of one of those columns in a row (NaN for an empty cell, a row without a pose, or an
// extra cell that is not a number); nullopt when the table has no column of that name.
std::optional<double> trackColumnValue(const TrackTable& table, const TrackRow& row,
                                       std::string_view column);

}  // namespace clm3d
