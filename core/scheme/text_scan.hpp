// Small text helpers shared by the landmark file parsers: splitting into numbered lines, strict
// number parsing (the whole token must be a number) and shortest round-trip number formatting, so
// every format reads and writes numbers the same way whatever the locale.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace clm3d::text {

// Most points any landmark file may declare or hold; larger counts are rejected before anything
// is allocated (a face mark-up has tens to a few thousand points).
inline constexpr int kMaxLandmarkCount = 100000;

struct Line {
  int number;             // 1-based
  std::string_view text;  // without the line break (and without a trailing '\r')
};

std::vector<Line> splitLines(std::string_view text);
std::string_view trim(std::string_view text);
// Splits on spaces and tabs.
std::vector<std::string_view> splitWhitespace(std::string_view text);
// Splits on commas, trimming each cell.
std::vector<std::string_view> splitCommas(std::string_view text);

// A finite number, or NaN for "nan"/"NaN"/"-nan"; nullopt for anything else (including "inf").
std::optional<double> parseNumberOrNan(std::string_view token);
// A non-negative integer without sign or fraction (nullopt otherwise); values above limit come
// back as limit + 1, so the caller can say "too many" without overflow.
std::optional<long long> parseCount(std::string_view token, long long limit);

// Shortest text that reads back to exactly the same double.
std::string formatNumber(double value);

}  // namespace clm3d::text
