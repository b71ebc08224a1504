// The VTK scene of the shape-mode explorer: a landmark set as spheres coloured by the scheme's
// regions, with lines joining each region's landmarks in the scheme's order. The points can be
// moved in place (update) so a slider drag only changes coordinates, not the pipeline.
#pragma once

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>

#include "core/scheme/scheme.hpp"

class vtkActor;
class vtkPoints;
class vtkPolyData;
class vtkRenderer;

namespace clm3d::ui {

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
