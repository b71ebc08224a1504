#include "core/model/view_check.hpp"

#include <string>

#include "core/common/error.hpp"

namespace clm3d {

void ViewCheck::validate(int schemeSize) const {
  if (empty()) return;
  const auto k = static_cast<Eigen::Index>(landmarks.size());
  if (k < 3) throw Error("check: needs at least 3 landmarks");
  for (std::size_t j = 0; j < landmarks.size(); ++j) {
    if (landmarks[j] < 0 || landmarks[j] >= schemeSize)
      throw Error("check: landmark index " + std::to_string(landmarks[j]) + " out of range");
    if (j > 0 && landmarks[j] <= landmarks[j - 1])
      throw Error("check: landmarks must be ascending");
  }
  if (meanShape.cols() != k || !meanShape.allFinite())
    throw Error("check: mean shape size or values");
  classifier.validate(k);
}

}  // namespace clm3d
