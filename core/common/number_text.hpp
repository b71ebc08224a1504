// Numbers as text the same on every machine: std::to_chars, never the C locale, which a Qt
// application or a user's LC_NUMERIC may change. For reports, plot labels and messages; CSV cells
// use fixedCell (core/common/csv_cell.hpp), which builds on these. Header-only.
#pragma once

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>

namespace clm3d {

// The value that marks a missing number (a hidden point, an empty cell).
inline constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// `value` with `decimals` digits after the point; NaN and infinities as to_chars writes them
// ("nan", "inf", "-inf").
inline std::string fixedText(double value, int decimals) {
  char buffer[64];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::fixed, decimals);
  return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

// As fixedText, with `nonFinite` written for NaN and infinities.
inline std::string fixedText(double value, int decimals, std::string_view nonFinite) {
  return std::isfinite(value) ? fixedText(value, decimals) : std::string(nonFinite);
}

}  // namespace clm3d
