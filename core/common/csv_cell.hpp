// One cell of a CSV table written for spreadsheets and pandas (RFC 4180): text holding a comma, a
// double quote or a line break is put in double quotes, its quotes doubled; other text is as is.
// For tables whose cells may hold file names and error messages (the batch fit summary, the
// per-image point evaluation).
#pragma once

#include <string>
#include <string_view>

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

}  // namespace clm3d
