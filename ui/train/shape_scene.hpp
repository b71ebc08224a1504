// The VTK scene of the shape-mode explorer: a landmark set as spheres coloured by the scheme's
// regions, with lines joining each region's landmarks (the region's shortest spanning tree on the
// shape the scene is built for, so an eye or the jaw reads as one connected outline). The points
// can be moved in place (update) so a slider drag only changes coordinates, not the pipeline.
#pragma once

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "core/scheme/scheme.hpp"

class vtkActor;
class vtkPoints;
class vtkPolyData;
class vtkRenderer;

namespace clm3d::ui {

// The edges (landmark index pairs) of the minimum spanning tree of `indices` by 3D distance
// between their points; indices outside the points are skipped.
std::vector<std::pair<int, int>> spanningTree(const Eigen::Matrix3Xd& points,
                                              const std::vector<int>& indices);

class ShapeScene {
 public:
  ShapeScene();
  ~ShapeScene();
  ShapeScene(const ShapeScene&) = delete;
  ShapeScene& operator=(const ShapeScene&) = delete;

  // Rebuilds the scene for `points` (3 x n, n = scheme size); sphereRadius in the points' units.
  void build(const Eigen::Matrix3Xd& points, const Scheme& scheme, double sphereRadius);
  // Moves the points (same count as build); the caller renders.
  void update(const Eigen::Matrix3Xd& points);
  // The displayed coordinates, read back from the VTK points.
  Eigen::Matrix3Xd points() const;
  // Looks at the shape from the front and a little to the side.
  void resetCamera();
  vtkRenderer* renderer() const { return renderer_; }

 private:
  vtkNew<vtkRenderer> renderer_;
  vtkNew<vtkPoints> points_;
  vtkNew<vtkPolyData> landmarks_;
  vtkNew<vtkPolyData> lines_;
  vtkNew<vtkActor> sphereActor_;
  vtkNew<vtkActor> lineActor_;
};

}  // namespace clm3d::ui
