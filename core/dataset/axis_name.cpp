#include "core/dataset/axis_name.hpp"

namespace clm3d {

std::optional<Eigen::Vector3d> axisFromName(std::string_view name) {
  double sign = 1.0;
  if (!name.empty() && (name.front() == '+' || name.front() == '-')) {
    sign = name.front() == '-' ? -1.0 : 1.0;
    name.remove_prefix(1);
  }
  if (name.size() != 1) return std::nullopt;
  switch (name.front()) {
    case 'x':
    case 'X':
      return Eigen::Vector3d(sign, 0.0, 0.0);
    case 'y':
    case 'Y':
      return Eigen::Vector3d(0.0, sign, 0.0);
    case 'z':
    case 'Z':
      return Eigen::Vector3d(0.0, 0.0, sign);
    default:
      return std::nullopt;
  }
}

}  // namespace clm3d
