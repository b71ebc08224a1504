#include "core/track/track_table.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/scheme/text_scan.hpp"
#include "core/track/track_table_writer.hpp"

namespace clm3d {
namespace {

constexpr const char* kVisiblePrefix = "visible_";
constexpr const char* kConfidencePrefix = "conf_";
constexpr const char* kStatusColumn = "status";
constexpr const char* kUnreadable = "unreadable";
constexpr std::array<const char*, 7> kPoseColumns = {"tx",    "ty",  "tz",  "scale",
                                                     "pitch", "yaw", "roll"};

// Writes value with std::to_chars (locale-independent); NaN becomes an empty cell.
void appendFixed(std::string& out, double value, int decimals) {
  if (!std::isfinite(value)) return;
  char buffer[64];
  const auto [ptr, ec] =
      std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::fixed, decimals);
  if (ec == std::errc()) {
    out.append(buffer, ptr);
  } else {
    out += text::formatNumber(value);  // beyond 64 characters: shortest exact form instead
  }
}

void appendGeneral(std::string& out, double value, int digits) {
  if (!std::isfinite(value)) return;
  char buffer[64];
  const auto [ptr, ec] =
      std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, digits);
  out.append(buffer, ec == std::errc() ? ptr : buffer);
}

// The cells of one row, with where they came from for messages.
class RowReader {
 public:
  RowReader(const std::string& source, int line, const std::vector<std::string_view>& cells,
            const std::vector<std::string>& header)
      : source_(source), line_(line), cells_(cells), header_(header) {}

  std::string_view cell(int column) const { return cells_[static_cast<std::size_t>(column)]; }

  [[noreturn]] void fail(int column, const std::string& what) const {
    throwInputError(source_, "column " + header_[static_cast<std::size_t>(column)] + ": " + what,
                    line_);
  }

  // A finite number or NaN ("nan" or an empty cell).
  double number(int column) const {
    const auto text = cell(column);
    if (text.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto value = text::parseNumberOrNan(text);
    if (!value) fail(column, "\"" + std::string(text) + "\" is not a number");
    return *value;
  }

  int integer(int column, int minimum) const {
    const auto text = cell(column);
    if (text.empty()) fail(column, "empty cell, expected a whole number");
    int value = 0;
    const auto* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end) {
      fail(column, "\"" + std::string(text) + "\" is not a whole number");
    }
    if (value < minimum) {
      fail(column, std::to_string(value) + " is below " + std::to_string(minimum));
    }
    return value;
  }

  // 1/0 (or true/false); an empty cell or "nan" is unknown.
  Visibility visibility(int column) const {
    const auto text = cell(column);
    if (text.empty() || text == "nan" || text == "NaN") return Visibility::Unknown;
    return flag(column) ? Visibility::Visible : Visibility::Hidden;
  }

  bool flag(int column) const {
    const auto text = cell(column);
    if (text == "1" || text == "true" || text == "True" || text == "TRUE") return true;
    if (text == "0" || text == "false" || text == "False" || text == "FALSE") return false;
    fail(column, "\"" + std::string(text) + "\" is not 0 or 1");
  }

 private:
  const std::string& source_;
  int line_;
  const std::vector<std::string_view>& cells_;
  const std::vector<std::string>& header_;
};

// Extra cells are written as they are, so they must not need CSV quoting.
bool needsQuoting(std::string_view text) {
  return text.find_first_of(",\"\r\n") != std::string_view::npos ||
         text::trim(text).size() != text.size();
}

bool isTrackerColumn(const std::string& name, int landmarkCount) {
  if (name == "frame" || name == "timestamp" || name == "success" || name == "confidence" ||
      name == "view" || name == kStatusColumn) {
    return true;
  }
  for (const char* pose : kPoseColumns) {
    if (name == pose) return true;
  }
  // x_i / y_i / visible_i / conf_i with i in 1..landmarkCount, written without sign or leading
  // zero.
  std::string_view index = name;
  if (index.starts_with("x_") || index.starts_with("y_")) {
    index.remove_prefix(2);
  } else if (index.starts_with(kVisiblePrefix)) {
    index.remove_prefix(std::string_view(kVisiblePrefix).size());
  } else if (index.starts_with(kConfidencePrefix)) {
    index.remove_prefix(std::string_view(kConfidencePrefix).size());
  } else {
    return false;
  }
  if (index.empty() || index.front() == '0') return false;
  int value = 0;
  const auto* end = index.data() + index.size();
  const auto [ptr, ec] = std::from_chars(index.data(), end, value);
  return ec == std::errc() && ptr == end && value >= 1 && value <= landmarkCount;
}

void checkExtraColumns(const TrackTable& table) {
  for (std::size_t k = 0; k < table.extraColumns.size(); ++k) {
    const auto& name = table.extraColumns[k];
    if (name.empty() || needsQuoting(name)) {
      throw Error("track table: extra column name \"" + name +
                  "\" is empty or holds a comma, quote, line break or outer space");
    }
    if (isTrackerColumn(name, table.landmarkCount) ||
        std::find(table.extraColumns.begin(), table.extraColumns.begin() + static_cast<long>(k),
                  name) != table.extraColumns.begin() + static_cast<long>(k)) {
      throw Error("track table: extra column " + name + " repeats a column");
    }
  }
}

void checkExtraCell(const std::string& cell, const std::string& column, int frame) {
  if (needsQuoting(cell)) {
    throw Error("track table: frame " + std::to_string(frame) + ", column " + column + ": \"" +
                cell + "\" holds a comma, quote, line break or outer space");
  }
}

// The header line: the tracker's columns, visible_k / conf_k / status when asked for, the extra
// columns.
void appendTrackHeader(std::string& out, int n, bool withVisibility, bool withConfidence,
                       bool withStatus, const std::vector<std::string>& extraColumns) {
  out += "frame,timestamp,success,confidence,view";
  for (const char* name : kPoseColumns) out += std::string(",") + name;
  for (int i = 1; i <= n; ++i) out += ",x_" + std::to_string(i);
  for (int i = 1; i <= n; ++i) out += ",y_" + std::to_string(i);
  if (withVisibility) {
    for (int i = 1; i <= n; ++i) out += "," + std::string(kVisiblePrefix) + std::to_string(i);
  }
  if (withConfidence) {
    for (int i = 1; i <= n; ++i) out += "," + std::string(kConfidencePrefix) + std::to_string(i);
  }
  if (withStatus) out += std::string(",") + kStatusColumn;
  for (const auto& name : extraColumns) out += ',' + name;
  out += '\n';
}

// One row's line under such a header; Error for a row of the wrong size.
void appendTrackRow(std::string& out, const TrackRow& row, int n, bool withVisibility,
                    bool withConfidence, bool withStatus,
                    const std::vector<std::string>& extraColumns) {
  if (row.points.cols() != n) {
    throw Error("track table: frame " + std::to_string(row.frame) + " has " +
                std::to_string(row.points.cols()) + " points, expected " + std::to_string(n));
  }
  if (!row.visibility.empty() && std::cmp_not_equal(row.visibility.size(), n)) {
    throw Error("track table: frame " + std::to_string(row.frame) + " has " +
                std::to_string(row.visibility.size()) + " visibility flags, expected " +
                std::to_string(n));
  }
  if (!row.landmarkConfidence.empty() && std::cmp_not_equal(row.landmarkConfidence.size(), n)) {
    throw Error("track table: frame " + std::to_string(row.frame) + " has " +
                std::to_string(row.landmarkConfidence.size()) + " landmark confidences, expected " +
                std::to_string(n));
  }
  out += std::to_string(row.frame);
  out += ',';
  appendFixed(out, row.timestamp, 6);
  out += row.success ? ",1," : ",0,";
  appendGeneral(out, row.confidence, 9);
  out += ',' + std::to_string(row.view);
  if (row.pose) {
    const auto& pose = *row.pose;
    const std::array<double, 7> values = {
        pose.translation.x(), pose.translation.y(), pose.translation.z(), pose.scale,
        degrees(pose.pitch),  degrees(pose.yaw),    degrees(pose.roll)};
    for (const double value : values) {
      out += ',';
      appendGeneral(out, value, 9);
    }
  } else {
    out += ",,,,,,,";
  }
  // A point counts as present only when both coordinates are finite; otherwise both cells are
  // left empty, so a reader never sees half a point.
  const auto present = [&](int i) {
    return std::isfinite(row.points(0, i)) && std::isfinite(row.points(1, i));
  };
  for (int axis = 0; axis < 2; ++axis) {
    for (int i = 0; i < n; ++i) {
      out += ',';
      if (present(i)) appendFixed(out, row.points(axis, i), 4);
    }
  }
  if (withVisibility) {
    for (int i = 0; i < n; ++i) {
      const Visibility flag = row.visibility.empty() ? Visibility::Unknown
                                                     : row.visibility[static_cast<std::size_t>(i)];
      out += flag == Visibility::Visible ? ",1" : flag == Visibility::Hidden ? ",0" : ",";
    }
  }
  if (withConfidence) {
    for (int i = 0; i < n; ++i) {
      out += ',';
      if (!row.landmarkConfidence.empty()) {
        appendGeneral(out, row.landmarkConfidence[static_cast<std::size_t>(i)], 6);
      }
    }
  }
  if (withStatus) {
    out += ',';
    if (row.unreadable) out += kUnreadable;
  }
  if (row.extraCells.size() > extraColumns.size()) {
    throw Error("track table: frame " + std::to_string(row.frame) + " has " +
                std::to_string(row.extraCells.size()) + " extra cells, expected at most " +
                std::to_string(extraColumns.size()));
  }
  for (std::size_t k = 0; k < extraColumns.size(); ++k) {
    out += ',';
    if (k < row.extraCells.size()) {
      checkExtraCell(row.extraCells[k], extraColumns[k], row.frame);
      out += row.extraCells[k];
    }
  }
  out += '\n';
}

}  // namespace

std::string formatTrackTable(const TrackTable& table) {
  if (table.landmarkCount < 0) throw Error("track table: negative landmark count");
  const int n = table.landmarkCount;
  const bool withVisibility =
      std::any_of(table.rows.begin(), table.rows.end(),
                  [](const TrackRow& row) { return !row.visibility.empty(); });
  const bool withConfidence =
      std::any_of(table.rows.begin(), table.rows.end(),
                  [](const TrackRow& row) { return !row.landmarkConfidence.empty(); });
  const bool withStatus = std::any_of(table.rows.begin(), table.rows.end(),
                                      [](const TrackRow& row) { return row.unreadable; });
  checkExtraColumns(table);
  std::string out;
  appendTrackHeader(out, n, withVisibility, withConfidence, withStatus, table.extraColumns);
  for (const auto& row : table.rows) {
    appendTrackRow(out, row, n, withVisibility, withConfidence, withStatus, table.extraColumns);
  }
  return out;
}

TrackTableWriter::TrackTableWriter(std::ostream& out, int landmarkCount,
                                   std::vector<std::string> extraColumns)
    : out_(&out), landmarkCount_(landmarkCount), extraColumns_(std::move(extraColumns)) {
  if (landmarkCount < 0) throw Error("track table: negative landmark count");
  TrackTable columns;
  columns.extraColumns = extraColumns_;
  checkExtraColumns(columns);
  std::string header;
  appendTrackHeader(header, landmarkCount_, true, true, false, extraColumns_);
  out_->write(header.data(), static_cast<std::streamsize>(header.size()));
}

void TrackTableWriter::write(const TrackRow& row) {
  line_.clear();
  appendTrackRow(line_, row, landmarkCount_, true, true, false, extraColumns_);
  out_->write(line_.data(), static_cast<std::streamsize>(line_.size()));
  ++rows_;
}

void writeTrackTable(const std::filesystem::path& path, const TrackTable& table) {
  writeTextAtomically(path, formatTrackTable(table));
}

void markUnreadableFrames(const std::filesystem::path& path, const std::vector<FrameSpan>& spans) {
  if (spans.empty()) return;
  TrackTable table = readTrackTable(path);
  const auto inSpan = [&](int frame) {
    return std::any_of(spans.begin(), spans.end(), [frame](const FrameSpan& span) {
      return frame >= span.first && frame - span.first < span.count;
    });
  };
  for (TrackRow& row : table.rows) row.unreadable = row.unreadable || inSpan(row.frame);
  writeTrackTable(path, table);
}

TrackTable parseTrackTable(const std::string& input, const std::string& sourceName) {
  std::string_view text = input;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  const auto lines = text::splitLines(text);
  std::size_t next = 0;
  while (next < lines.size() && text::trim(lines[next].text).empty()) ++next;
  if (next >= lines.size()) {
    throwInputError(sourceName, "empty file: expected a header line \"frame,timestamp,...\"");
  }

  // Header: every column by name, so other tools may order or add columns as they like.
  const int headerLine = lines[next].number;
  std::vector<std::string> header;
  std::unordered_map<std::string, int> columnOf;
  for (const auto cell : text::splitCommas(lines[next].text)) {
    std::string name(cell);
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') {
      name = name.substr(1, name.size() - 2);  // a quoted header cell, as some tools write
    }
    if (!name.empty() && !columnOf.emplace(name, static_cast<int>(header.size())).second) {
      throwInputError(sourceName, "column " + name + " appears twice in the header", headerLine);
    }
    header.push_back(name);
  }
  ++next;
  const auto find = [&](const std::string& name) {
    const auto it = columnOf.find(name);
    return it == columnOf.end() ? -1 : it->second;
  };
  const auto require = [&](const std::string& name) {
    const int column = find(name);
    if (column < 0) throwInputError(sourceName, "missing column " + name, headerLine);
    return column;
  };

  const int frameColumn = require("frame");
  const int successColumn = require("success");
  const int timestampColumn = find("timestamp");
  const int confidenceColumn = find("confidence");
  const int viewColumn = find("view");
  const int statusColumn = find(kStatusColumn);
  // Pose columns: all seven or none.
  std::array<int, 7> poseColumns{};
  int poseFound = 0;
  for (std::size_t k = 0; k < kPoseColumns.size(); ++k) {
    poseColumns[k] = find(kPoseColumns[k]);
    poseFound += poseColumns[k] >= 0 ? 1 : 0;
  }
  if (poseFound != 0 && poseFound != static_cast<int>(kPoseColumns.size())) {
    for (std::size_t k = 0; k < kPoseColumns.size(); ++k) {
      if (poseColumns[k] < 0) {
        throwInputError(sourceName,
                        std::string("missing column ") + kPoseColumns[k] +
                            " (the pose needs tx, ty, tz, scale, pitch, yaw and roll)",
                        headerLine);
      }
    }
  }
  const bool hasPose = poseFound != 0;

  // Landmarks: x_1..x_n and y_1..y_n, n given by the longest unbroken run of either.
  int n = 0;
  while (find("x_" + std::to_string(n + 1)) >= 0 || find("y_" + std::to_string(n + 1)) >= 0) ++n;
  if (n > text::kMaxLandmarkCount) {
    throwInputError(sourceName, "too many landmark columns", headerLine);
  }
  std::vector<int> xColumns(static_cast<std::size_t>(n));
  std::vector<int> yColumns(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    xColumns[static_cast<std::size_t>(i)] = require("x_" + std::to_string(i + 1));
    yColumns[static_cast<std::size_t>(i)] = require("y_" + std::to_string(i + 1));
  }
  // Visibility: visible_1..visible_n, all or none (a table from before them has none: unknown).
  std::vector<int> visibleColumns;
  bool anyVisible = false;
  for (int i = 1; i <= n && !anyVisible; ++i) {
    anyVisible = find(kVisiblePrefix + std::to_string(i)) >= 0;
  }
  if (anyVisible) {
    for (int i = 0; i < n; ++i) {
      visibleColumns.push_back(require(kVisiblePrefix + std::to_string(i + 1)));
    }
  }

  // Landmark confidences: conf_1..conf_n, all or none (older tables have none).
  std::vector<int> confidenceColumns;
  bool anyConfidence = false;
  for (int i = 1; i <= n && !anyConfidence; ++i) {
    anyConfidence = find(kConfidencePrefix + std::to_string(i)) >= 0;
  }
  if (anyConfidence) {
    for (int i = 0; i < n; ++i) {
      confidenceColumns.push_back(require(kConfidencePrefix + std::to_string(i + 1)));
    }
  }

  TrackTable table;
  table.landmarkCount = n;
  // Every named column the table does not use is kept as text.
  std::vector<int> extraColumns;
  for (int column = 0; column < static_cast<int>(header.size()); ++column) {
    const auto& name = header[static_cast<std::size_t>(column)];
    if (!name.empty() && !isTrackerColumn(name, n)) {
      extraColumns.push_back(column);
      table.extraColumns.push_back(name);
    }
  }
  // A frame appears once, or once per face in a multi-face table (a `face` column: clm3d track
  // --faces, docs/tracks-csv.md).
  const int faceColumn = find("face");
  std::map<std::pair<int, std::string>, int> lineOfFrame;
  for (; next < lines.size(); ++next) {
    const auto& line = lines[next];
    if (text::trim(line.text).empty()) continue;
    const auto cells = text::splitCommas(line.text);
    if (cells.size() != header.size()) {
      throwInputError(sourceName,
                      "expected " + std::to_string(header.size()) + " cells (as in the header), " +
                          "found " + std::to_string(cells.size()),
                      line.number);
    }
    const RowReader reader(sourceName, line.number, cells, header);
    TrackRow row;
    row.frame = reader.integer(frameColumn, 0);
    const std::string face = faceColumn >= 0 ? std::string(reader.cell(faceColumn)) : std::string();
    if (const auto [it, inserted] = lineOfFrame.emplace(std::pair(row.frame, face), line.number);
        !inserted) {
      reader.fail(frameColumn, "frame " + std::to_string(row.frame) +
                                   (face.empty() ? "" : " of face " + face) +
                                   " already appears on line " + std::to_string(it->second));
    }
    row.success = reader.flag(successColumn);
    row.timestamp = timestampColumn >= 0 ? reader.number(timestampColumn)
                                         : std::numeric_limits<double>::quiet_NaN();
    row.confidence = confidenceColumn >= 0 ? reader.number(confidenceColumn)
                                           : std::numeric_limits<double>::quiet_NaN();
    row.view =
        viewColumn >= 0 && !reader.cell(viewColumn).empty() ? reader.integer(viewColumn, -1) : -1;
    if (statusColumn >= 0) {
      const auto status = reader.cell(statusColumn);
      if (!status.empty() && status != kUnreadable) {
        reader.fail(statusColumn, "\"" + std::string(status) + "\" is not empty or " + kUnreadable);
      }
      row.unreadable = !status.empty();
    }

    if (hasPose) {
      std::array<double, 7> values{};
      int missing = 0;
      for (std::size_t k = 0; k < values.size(); ++k) {
        values[k] = reader.number(poseColumns[k]);
        missing += std::isnan(values[k]) ? 1 : 0;
      }
      if (missing != 0 && missing != static_cast<int>(values.size())) {
        for (std::size_t k = 0; k < values.size(); ++k) {
          if (std::isnan(values[k])) {
            reader.fail(poseColumns[k],
                        "empty, but other pose cells are not (leave all seven empty for no pose)");
          }
        }
      }
      if (missing == 0) {
        Pose pose;
        pose.translation = Eigen::Vector3d(values[0], values[1], values[2]);
        pose.scale = values[3];
        pose.pitch = radians(values[4]);
        pose.yaw = radians(values[5]);
        pose.roll = radians(values[6]);
        row.pose = pose;
      }
    }

    row.points.resize(2, n);
    for (int i = 0; i < n; ++i) {
      const int xColumn = xColumns[static_cast<std::size_t>(i)];
      const int yColumn = yColumns[static_cast<std::size_t>(i)];
      const double x = reader.number(xColumn);
      const double y = reader.number(yColumn);
      if (std::isnan(x) != std::isnan(y)) {
        reader.fail(std::isnan(x) ? xColumn : yColumn,
                    "empty, but the other coordinate of the point is not");
      }
      row.points(0, i) = x;
      row.points(1, i) = y;
    }
    for (const int column : visibleColumns) row.visibility.push_back(reader.visibility(column));
    for (const int column : confidenceColumns) {
      row.landmarkConfidence.push_back(reader.number(column));
    }
    for (const int column : extraColumns) row.extraCells.emplace_back(reader.cell(column));
    table.rows.push_back(std::move(row));
  }
  return table;
}

TrackTable readTrackTable(const std::filesystem::path& path) {
  return parseTrackTable(readTextFile(path), path.string());
}

std::vector<std::string> numericTrackColumns(const TrackTable& table) {
  std::vector<std::string> names = {"frame", "timestamp", "success", "confidence", "view"};
  for (const char* pose : kPoseColumns) names.emplace_back(pose);
  names.insert(names.end(), table.extraColumns.begin(), table.extraColumns.end());
  return names;
}

std::optional<double> trackColumnValue(const TrackTable& table, const TrackRow& row,
                                       std::string_view column) {
  if (column == "frame") return row.frame;
  if (column == "timestamp") return row.timestamp;
  if (column == "success") return row.success ? 1.0 : 0.0;
  if (column == "confidence") return row.confidence;
  if (column == "view") return row.view;
  for (std::size_t k = 0; k < kPoseColumns.size(); ++k) {
    if (column != kPoseColumns[k]) continue;
    if (!row.pose) return kNan;
    const Pose& pose = *row.pose;
    const std::array<double, 7> values = {
        pose.translation.x(), pose.translation.y(), pose.translation.z(), pose.scale,
        degrees(pose.pitch),  degrees(pose.yaw),    degrees(pose.roll)};
    return values[k];
  }
  for (std::size_t k = 0; k < table.extraColumns.size(); ++k) {
    if (column != table.extraColumns[k]) continue;
    if (k >= row.extraCells.size() || row.extraCells[k].empty()) return kNan;
    return text::parseNumberOrNan(row.extraCells[k]).value_or(kNan);
  }
  return std::nullopt;
}

}  // namespace clm3d
