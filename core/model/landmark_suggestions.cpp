#include "core/model/landmark_suggestions.hpp"

#include "core/geometry/symmetry_plane.hpp"
#include "core/model/detail/shape_guess.hpp"

namespace clm3d {

std::optional<Eigen::Vector3d> mirrorSuggestion(const Scheme& scheme, const LandmarkSet& points,
                                                int index, const Eigen::Vector3d& left,
                                                const SnapToSurface& snap) {
  if (index < 0 || index >= points.size() || points.has(index)) return std::nullopt;
  const int mirror = scheme.mirrorOf(index);
  if (mirror == index || !points.has(mirror)) return std::nullopt;
  std::vector<int> mirrors(static_cast<std::size_t>(scheme.size()));
  for (int i = 0; i < scheme.size(); ++i) mirrors[static_cast<std::size_t>(i)] = scheme.mirrorOf(i);
  const auto plane = estimateSymmetryPlane(points.matrix(), points.presentMask(), mirrors, left);
  if (!plane) return std::nullopt;
  return snap(plane->reflect(points.point(mirror)));
}

LandmarkSet firstGuess(const ShapeModel& model, const LandmarkSet& points,
                       const Eigen::AlignedBox3d& bounds, const SnapToSurface& snap) {
  const ShapeGuess guess = guessShape(model, points, bounds);
  LandmarkSet result = points;
  for (int i = 0; i < points.size(); ++i) {
    if (!points.has(i)) result.set(i, snap(guess.points.col(i)));
  }
  return result;
}

LandmarkSet mergeImported(const LandmarkSet& current, const LandmarkSet& imported,
                          const SnapToSurface& snap) {
  LandmarkSet result = current;
  for (int i = 0; i < std::min(current.size(), imported.size()); ++i) {
    if (imported.has(i)) result.set(i, snap(imported.point(i)));
  }
  return result;
}

}  // namespace clm3d
