// The median of a sample, for the places that summarise one (fit times, review statistics, the
// thesis's descriptive figures): one definition, so every figure called a median is the same one.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace clm3d {

// The middle value, or the mean of the two middle values of an even count; NaN for none. Takes the
// sample by value: it is partly reordered.
inline double medianOf(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  if (values.size() % 2 == 1) return *middle;
  return 0.5 * (*middle + *std::max_element(values.begin(), middle));
}

}  // namespace clm3d
