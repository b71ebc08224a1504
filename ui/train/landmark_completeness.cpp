#include "ui/train/landmark_completeness.hpp"

#include <exception>

#include "core/scheme/landmark_file.hpp"
#include "ui/common/error_dialog.hpp"

namespace clm3d::ui {

LandmarkCompleteness landmarkCompleteness(const std::filesystem::path& file, const Scheme& scheme) {
  LandmarkCompleteness result;
  result.total = scheme.size();
  try {
    const LandmarkSet points = readLandmarks(file, &scheme);
    for (int i = 0; i < scheme.size(); ++i) {
      if (points.has(i)) {
        ++result.placed;
      } else {
        result.missing << QString("%1 %2").arg(i + 1).arg(QString::fromStdString(scheme.label(i)));
      }
    }
  } catch (...) {
    result.placed = 0;
    result.missing.clear();
    result.error = messageOf(std::current_exception());
  }
  return result;
}

}  // namespace clm3d::ui
