#include "core/train/detail/framing_landmarks.hpp"

#include <string>

#include "core/common/error.hpp"
#include "core/geometry/procrustes.hpp"

namespace clm3d {

LandmarkSet framingLandmarks(const std::vector<const LandmarkSet*>& all, std::size_t index,
                             std::pair<int, int> pair, const std::string& id) {
  const LandmarkSet& target = *all[index];
  if (target.has(pair.first) && target.has(pair.second)) return target;
  const int n = target.size();
  Eigen::Vector3d sumFirst = Eigen::Vector3d::Zero();
  Eigen::Vector3d sumSecond = Eigen::Vector3d::Zero();
  int donors = 0;
  for (std::size_t k = 0; k < all.size(); ++k) {
    const LandmarkSet& other = *all[k];
    if (k == index || other.size() != n || other.dims() != 3) continue;
    if (!other.has(pair.first) || !other.has(pair.second)) continue;
    std::vector<bool> common(static_cast<std::size_t>(n), false);
    int count = 0;
    for (int i = 0; i < n; ++i) {
      common[static_cast<std::size_t>(i)] = target.has(i) && other.has(i);
      count += common[static_cast<std::size_t>(i)] ? 1 : 0;
    }
    if (count < 3) continue;
    const Similarity3 onto = alignSimilarity(other.matrix(), target.matrix(), common);
    sumFirst += onto.apply(other.point(pair.first));
    sumSecond += onto.apply(other.point(pair.second));
    ++donors;
  }
  if (donors == 0) {
    throw InputError("training: subject '" + id + "' lacks landmark " +
                     std::to_string(pair.first + 1) + " or " + std::to_string(pair.second + 1) +
                     " (the eye centres, which set the face size in the renders) and no other "
                     "subject or shape-only set has both to impute them from");
  }
  LandmarkSet framing = target;
  if (!framing.has(pair.first)) framing.set(pair.first, Eigen::Vector3d(sumFirst / donors));
  if (!framing.has(pair.second)) framing.set(pair.second, Eigen::Vector3d(sumSecond / donors));
  return framing;
}

}  // namespace clm3d
