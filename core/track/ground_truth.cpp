#include "core/track/ground_truth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/scheme/pts_format.hpp"
#include "core/scheme/text_scan.hpp"
#include "core/track/frame_export.hpp"

namespace clm3d {
namespace {

constexpr const char* kKeyframeColumn = "keyframe";

TrackRow emptyRow(int frame, int landmarkCount, double timestamp) {
  TrackRow row;
  row.frame = frame;
  row.timestamp = timestamp;
  row.success = false;
  row.confidence = 0.0;
  row.view = -1;
  row.points = Eigen::Matrix2Xd::Constant(2, landmarkCount, kNan);
  return row;
}

bool hasPoint(const Eigen::Matrix2Xd& points, int i) {
  return std::isfinite(points(0, i)) && std::isfinite(points(1, i));
}

bool anyPoint(const Eigen::Matrix2Xd& points) {
  for (int i = 0; i < points.cols(); ++i) {
    if (hasPoint(points, i)) return true;
  }
  return false;
}

// A row whose points a person gave (directly or by interpolation): the reference, not a fit.
void markAsReference(TrackRow& row) {
  row.success = anyPoint(row.points);
  row.confidence = 1.0;
  row.view = -1;
  row.pose.reset();
  row.visibility.clear();          // the fit's visibility does not describe a person's points
  row.landmarkConfidence.clear();  // nor do its confidences
}

// Seconds of frame `frame` from the first and last rows with finite timestamps; NaN without two.
double estimatedTimestamp(const TrackTable& track, int frame) {
  const TrackRow* first = nullptr;
  const TrackRow* last = nullptr;
  for (const auto& row : track.rows) {
    if (!std::isfinite(row.timestamp)) continue;
    if (!first || row.frame < first->frame) first = &row;
    if (!last || row.frame > last->frame) last = &row;
  }
  if (!first || !last || first->frame == last->frame) return kNan;
  const double perFrame = (last->timestamp - first->timestamp) / (last->frame - first->frame);
  return first->timestamp + (frame - first->frame) * perFrame;
}

// The line number of every data row of a track CSV, in order: the lines parseTrackTable reads
// (the first non-blank line is the header, blank lines are skipped).
std::vector<int> dataLineNumbers(const std::string& text) {
  std::vector<int> numbers;
  bool header = true;
  for (const auto& line : text::splitLines(text)) {
    if (text::trim(line.text).empty()) continue;
    if (header) {
      header = false;
      continue;
    }
    numbers.push_back(line.number);
  }
  return numbers;
}

void checkFrame(const GroundTruthSet& set, int frame) {
  if (frame < 0 || frame >= set.frameCount()) {
    throw InputError("ground truth: frame " + std::to_string(frame) + " is outside 0.." +
                     std::to_string(set.frameCount() - 1));
  }
}

}  // namespace

GroundTruthSet GroundTruthSet::fromTrack(const TrackTable& track, int frameCount) {
  if (frameCount < 0 || frameCount > kMaxGroundTruthFrames) {
    throw InputError("ground truth: frame count " + std::to_string(frameCount) + " is outside 0.." +
                     std::to_string(kMaxGroundTruthFrames));
  }
  GroundTruthSet set;
  set.table.landmarkCount = track.landmarkCount;
  set.table.rows.reserve(static_cast<std::size_t>(frameCount));
  for (int frame = 0; frame < frameCount; ++frame) {
    set.table.rows.push_back(
        emptyRow(frame, track.landmarkCount, estimatedTimestamp(track, frame)));
  }
  for (const auto& row : track.rows) {
    if (row.frame < 0 || row.frame >= frameCount) {
      throw InputError("ground truth: the track has frame " + std::to_string(row.frame) +
                       ", but the video has " + std::to_string(frameCount) + " frames");
    }
    if (row.points.cols() != track.landmarkCount) {
      throw InputError("ground truth: frame " + std::to_string(row.frame) + " of the track has " +
                       std::to_string(row.points.cols()) + " points, expected " +
                       std::to_string(track.landmarkCount));
    }
    auto& target = set.table.rows[static_cast<std::size_t>(row.frame)];
    target = row;
    target.extraCells.clear();
  }
  set.keyframe.assign(static_cast<std::size_t>(frameCount), false);
  return set;
}

int GroundTruthSet::keyframeCount() const {
  return static_cast<int>(std::count(keyframe.begin(), keyframe.end(), true));
}

void GroundTruthSet::padTo(int count) {
  if (count > kMaxGroundTruthFrames) {
    throw InputError("ground truth: frame count " + std::to_string(count) + " is above " +
                     std::to_string(kMaxGroundTruthFrames));
  }
  for (int frame = frameCount(); frame < count; ++frame) {
    table.rows.push_back(emptyRow(frame, table.landmarkCount, estimatedTimestamp(table, frame)));
  }
  keyframe.resize(table.rows.size(), false);
}

void GroundTruthSet::setKeyframe(int frame, const Eigen::Matrix2Xd& points) {
  checkFrame(*this, frame);
  const int n = static_cast<int>(points.cols());
  if (table.landmarkCount == 0 && n > 0) {
    // No landmarks yet (a set started from an empty track): the first keyframe sets the count.
    table.landmarkCount = n;
    for (auto& row : table.rows) row.points = Eigen::Matrix2Xd::Constant(2, n, kNan);
  }
  if (n != table.landmarkCount) {
    throw InputError("ground truth: frame " + std::to_string(frame) + " was given " +
                     std::to_string(n) + " points, the ground truth has " +
                     std::to_string(table.landmarkCount));
  }
  auto& row = table.rows[static_cast<std::size_t>(frame)];
  row.points = points;
  // Half a point is no point: both coordinates must be finite.
  for (int i = 0; i < n; ++i) {
    if (!hasPoint(row.points, i)) row.points.col(i).setConstant(kNan);
  }
  markAsReference(row);
  keyframe[static_cast<std::size_t>(frame)] = true;
}

void GroundTruthSet::clearKeyframe(int frame) {
  checkFrame(*this, frame);
  keyframe[static_cast<std::size_t>(frame)] = false;
}

int GroundTruthSet::interpolateKeyframes() {
  int filled = 0;
  int previous = -1;
  for (int next = 0; next < frameCount(); ++next) {
    if (!keyframe[static_cast<std::size_t>(next)]) continue;
    if (previous >= 0 && next - previous > 1) {
      const auto& a = table.rows[static_cast<std::size_t>(previous)];
      const auto& b = table.rows[static_cast<std::size_t>(next)];
      for (int frame = previous + 1; frame < next; ++frame) {
        const double t = static_cast<double>(frame - previous) / (next - previous);
        auto& row = table.rows[static_cast<std::size_t>(frame)];
        row.points = Eigen::Matrix2Xd::Constant(2, table.landmarkCount, kNan);
        for (int i = 0; i < table.landmarkCount; ++i) {
          if (hasPoint(a.points, i) && hasPoint(b.points, i)) {
            row.points.col(i) = (1.0 - t) * a.points.col(i) + t * b.points.col(i);
          }
        }
        if (std::isfinite(a.timestamp) && std::isfinite(b.timestamp)) {
          row.timestamp = (1.0 - t) * a.timestamp + t * b.timestamp;
        }
        markAsReference(row);
        ++filled;
      }
    }
    previous = next;
  }
  return filled;
}

std::filesystem::path groundTruthPtsName(int frame) {
  return frameFileName(frame, ".pts");
}

void saveGroundTruth(const std::filesystem::path& csv, const GroundTruthSet& set,
                     const std::filesystem::path& ptsFolder) {
  if (set.keyframe.size() != set.table.rows.size()) {
    throw Error("ground truth: " + std::to_string(set.keyframe.size()) + " keyframe flags for " +
                std::to_string(set.table.rows.size()) + " frames");
  }
  TrackTable table = set.table;
  table.extraColumns = {kKeyframeColumn};
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    auto& row = table.rows[i];
    if (row.frame != static_cast<int>(i)) {
      throw Error("ground truth: row " + std::to_string(i) + " holds frame " +
                  std::to_string(row.frame));
    }
    row.extraCells = {set.keyframe[i] ? "1" : "0"};
  }
  writeTrackTable(csv, table);  // checks the point counts before anything is written

  if (ptsFolder.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(ptsFolder, error);
  if (error) throwInputError(ptsFolder, "cannot create the folder: " + error.message());
  for (const auto& row : set.table.rows) {
    LandmarkSet points(set.table.landmarkCount, 2);
    for (int i = 0; i < set.table.landmarkCount; ++i) {
      if (hasPoint(row.points, i)) points.set(i, Eigen::Vector2d(row.points.col(i)));
    }
    writeTextAtomically(ptsFolder / groundTruthPtsName(row.frame), formatPts(points));
  }
}

GroundTruthSet groundTruthFromTable(const TrackTable& table, int frameCount,
                                    const std::filesystem::path& source,
                                    const std::function<int(std::size_t)>& lineOf) {
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    if (table.rows[r].frame >= kMaxGroundTruthFrames) {
      throwInputError(source,
                      "frame " + std::to_string(table.rows[r].frame) + " is beyond the " +
                          std::to_string(kMaxGroundTruthFrames) + " frames a ground truth may have",
                      lineOf ? lineOf(r) : 0);
    }
  }
  const auto column =
      std::find(table.extraColumns.begin(), table.extraColumns.end(), kKeyframeColumn);
  const bool hasKeyframes = column != table.extraColumns.end();
  const auto keyColumn = static_cast<std::size_t>(column - table.extraColumns.begin());
  GroundTruthSet set = GroundTruthSet::fromTrack(table, frameCount);  // drops the extra columns
  if (!hasKeyframes) return set;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& cells = table.rows[r].extraCells;
    const std::string cell = keyColumn < cells.size() ? cells[keyColumn] : std::string();
    if (cell != "0" && cell != "1") {
      throwInputError(source, "column keyframe: \"" + cell + "\" is not 0 or 1",
                      lineOf ? lineOf(r) : 0);
    }
    set.keyframe[static_cast<std::size_t>(table.rows[r].frame)] = cell == "1";
  }
  return set;
}

GroundTruthSet loadGroundTruth(const std::filesystem::path& csv) {
  const std::string text = readTextFile(csv);
  const TrackTable table = parseTrackTable(text, csv.string());
  int frames = 0;
  for (const auto& row : table.rows) frames = std::max(frames, row.frame + 1);
  const auto lines = dataLineNumbers(text);
  return groundTruthFromTable(table, std::min(frames, kMaxGroundTruthFrames), csv,
                              [&](std::size_t row) { return row < lines.size() ? lines[row] : 0; });
}

}  // namespace clm3d
