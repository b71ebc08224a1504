#include "core/dataset/axis_name.hpp"

#include "core/common/error.hpp"

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

void checkAxisName(std::string_view name) {
  if (!axisFromName(name)) {
    throw InputError("expected an axis such as +y, -z or x, got '" + std::string(name) + "'");
  }
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> fileAxes(const std::string& up,
                                                     const std::string& front) {
  for (const auto& [option, value] : {std::pair{"--up", up}, std::pair{"--front", front}}) {
    try {
      checkAxisName(value);
    } catch (const InputError& error) {
      throw UsageError(option, error.what());
    }
  }
  const Eigen::Vector3d upAxis = *axisFromName(up);
  const Eigen::Vector3d frontAxis = *axisFromName(front);
  if (upAxis.dot(frontAxis) != 0.0) {
    throw UsageError("--up/--front", "the axes must be perpendicular");
  }
  return {upAxis, frontAxis};
}

ScanSource scanFromAxes(const std::filesystem::path& mesh, const std::filesystem::path& landmarks,
                        const std::string& up, const std::string& front, double scale) {
  fileAxes(up, front);
  ScanSource source;
  source.mesh = mesh;
  source.landmarks = landmarks;
  source.subject = mesh.stem().string();
  source.expression = "neutral";
  source.up = up;
  source.front = front;
  source.scale = scale;
  return source;
}

}  // namespace clm3d
