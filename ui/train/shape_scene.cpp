#include "ui/train/shape_scene.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkGlyph3D.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <limits>

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

std::vector<std::pair<int, int>> spanningTree(const Eigen::Matrix3Xd& points,
                                              const std::vector<int>& indices) {
  std::vector<int> members;
  for (int index : indices) {
    if (index >= 0 && index < points.cols()) members.push_back(index);
  }
  std::vector<std::pair<int, int>> edges;
  if (members.size() < 2) return edges;
  // Prim's algorithm: grow the tree from the first member by the shortest edge leaving it.
  std::vector<bool> inTree(members.size(), false);
  inTree[0] = true;
  for (std::size_t added = 1; added < members.size(); ++added) {
    double best = std::numeric_limits<double>::infinity();
    std::pair<std::size_t, std::size_t> edge{0, 0};
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (!inTree[i]) continue;
      for (std::size_t j = 0; j < members.size(); ++j) {
        if (inTree[j]) continue;
        const double d = (points.col(members[i]) - points.col(members[j])).squaredNorm();
        if (d < best) {
          best = d;
          edge = {i, j};
        }
      }
    }
    inTree[edge.second] = true;
    edges.emplace_back(members[edge.first], members[edge.second]);
  }
  return edges;
}

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
  vtkNew<vtkCellArray> segments;
  for (const LandmarkRegion& region : scheme.regions()) {
    for (const auto& [a, b] : spanningTree(points, region.indices)) {
      const vtkIdType ends[2] = {a, b};
      segments->InsertNextCell(2, ends);
      insertColour(lineColours, region.colour);
    }
  }
  lines_->SetLines(segments);
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
  camera->Azimuth(15);
  camera->Elevation(10);
  camera->OrthogonalizeViewUp();
  renderer_->ResetCamera();
  camera->Zoom(1.25);  // ResetCamera fits the bounding sphere, which leaves wide margins
  renderer_->ResetCameraClippingRange();
}

}  // namespace clm3d::ui
