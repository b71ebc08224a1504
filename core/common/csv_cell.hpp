// One cell of a CSV table written for spreadsheets and pandas (RFC 4180): text holding a comma, a
// double quote or a line break is put in double quotes, its quotes doubled; other text is as is.
// For tables whose cells may hold file names and error messages (the batch fit summary, the
// per-image point evaluation, the batch summary), the reverse for one line of such a table, and
// numbers written the same in every locale.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/common/number_text.hpp"

namespace clm3d {

inline std::string csvCell(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

// The cells of one line written with csvCell (no line break inside a cell); nullopt for a quote
// that is not closed or is followed by something other than a comma.
inline std::optional<std::vector<std::string>> parseCsvLine(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t i = 0;
  while (true) {
    std::string cell;
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= line.size()) return std::nullopt;
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            cell += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        cell += line[i++];
      }
      if (i < line.size() && line[i] != ',') return std::nullopt;
    } else {
      const std::size_t end = std::min(line.find(',', i), line.size());
      cell = std::string(line.substr(i, end - i));
      i = end;
    }
    cells.push_back(std::move(cell));
    if (i >= line.size()) return cells;
    ++i;  // the comma
  }
}

// Locale-independent fixed-point text; empty for NaN and infinities.
inline std::string fixedCell(double value, int decimals) {
  return fixedText(value, decimals, {});
}

}  // namespace clm3d
