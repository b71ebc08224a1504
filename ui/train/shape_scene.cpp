#include "ui/train/shape_scene.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkGlyph3D.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

namespace clm3d::ui {
namespace {

constexpr RgbColour kNoRegion{170, 170, 170};

vtkSmartPointer<vtkUnsignedCharArray> colourArray(const char* name) {
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetName(name);
  colours->SetNumberOfComponents(3);
  return colours;
}

void insertColour(vtkUnsignedCharArray* colours, const RgbColour& c) {
  colours->InsertNextTuple3(c.r, c.g, c.b);
}

}  // namespace

ShapeScene::ShapeScene() {
  renderer_->SetBackground(0.13, 0.14, 0.16);
  points_->SetDataTypeToDouble();
  landmarks_->SetPoints(points_);
  lines_->SetPoints(points_);

  vtkNew<vtkPolyDataMapper> lineMapper;
  lineMapper->SetInputData(lines_);
  lineMapper->SetColorModeToDirectScalars();
  lineMapper->SetScalarModeToUseCellData();
  lineActor_->SetMapper(lineMapper);
  lineActor_->GetProperty()->SetLineWidth(2.0);
  lineActor_->GetProperty()->SetLighting(false);
  renderer_->AddActor(lineActor_);
  renderer_->AddActor(sphereActor_);
}

ShapeScene::~ShapeScene() = default;

void ShapeScene::build(const Eigen::Matrix3Xd& points, const Scheme& scheme, double sphereRadius) {
  const auto n = static_cast<vtkIdType>(points.cols());
  points_->SetNumberOfPoints(n);
  update(points);

  auto pointColours = colourArray("region colour");
  vtkNew<vtkCellArray> vertices;
  for (vtkIdType i = 0; i < n; ++i) {
    const int region = i < scheme.size() ? scheme.regionOf(static_cast<int>(i)) : -1;
    insertColour(pointColours, region < 0
                                   ? kNoRegion
                                   : scheme.regions()[static_cast<std::size_t>(region)].colour);
    vertices->InsertNextCell(1, &i);
  }
  landmarks_->SetVerts(vertices);
  landmarks_->GetPointData()->SetScalars(pointColours);

  auto lineColours = colourArray("region colour");
  vtkNew<vtkCellArray> polylines;
  for (const LandmarkRegion& region : scheme.regions()) {
    vtkNew<vtkIdList> ids;
    for (int index : region.indices) {
      if (index < n) ids->InsertNextId(index);
    }
    if (ids->GetNumberOfIds() < 2) continue;
    polylines->InsertNextCell(ids);
    insertColour(lineColours, region.colour);
  }
  lines_->SetLines(polylines);
  lines_->GetCellData()->SetScalars(lineColours);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(sphereRadius);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputData(landmarks_);
  glyphs->SetSourceConnection(sphere->GetOutputPort());
  glyphs->SetScaleModeToDataScalingOff();
  glyphs->SetColorModeToColorByScalar();
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(glyphs->GetOutputPort());
  sphereMapper->SetColorModeToDirectScalars();
  sphereMapper->SetScalarModeToUsePointData();
  sphereActor_->SetMapper(sphereMapper);
  resetCamera();
}

void ShapeScene::update(const Eigen::Matrix3Xd& points) {
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    points_->SetPoint(static_cast<vtkIdType>(i), points(0, i), points(1, i), points(2, i));
  }
  points_->Modified();
  landmarks_->Modified();
  lines_->Modified();
}

Eigen::Matrix3Xd ShapeScene::points() const {
  Eigen::Matrix3Xd result(3, points_->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points_->GetNumberOfPoints(); ++i) {
    double p[3];
    points_->GetPoint(i, p);
    result.col(static_cast<Eigen::Index>(i)) << p[0], p[1], p[2];
  }
  return result;
}

void ShapeScene::resetCamera() {
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 0, 1);
  camera->SetViewUp(0, 1, 0);
  renderer_->ResetCamera();
  camera->Azimuth(25);
  camera->Elevation(10);
  camera->OrthogonalizeViewUp();
  renderer_->ResetCamera();
  renderer_->ResetCameraClippingRange();
}

}  // namespace clm3d::ui
