#include "app/commands/scan_options.hpp"

#include <CLI/CLI.hpp>
#include <utility>

#include "core/dataset/axis_name.hpp"

namespace clm3d::cli {

ScanSource scanFromOptions(const std::filesystem::path& mesh,
                           const std::filesystem::path& landmarks, const std::string& up,
                           const std::string& front, double scale) {
  for (const auto& [option, value] : {std::pair{"--up", up}, std::pair{"--front", front}}) {
    if (!axisFromName(value)) {
      throw CLI::ValidationError(option,
                                 "expected an axis such as +y, -z or x, got '" + value + "'");
    }
  }
  if (axisFromName(up)->dot(*axisFromName(front)) != 0.0) {
    throw CLI::ValidationError("--up/--front", "the axes must be perpendicular");
  }
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

}  // namespace clm3d::cli
