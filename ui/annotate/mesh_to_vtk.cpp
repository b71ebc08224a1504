#include "ui/annotate/mesh_to_vtk.hpp"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace clm3d::ui {

vtkSmartPointer<vtkPolyData> toVtkPolyData(const TexturedMesh& mesh) {
  const auto vertexCount = static_cast<vtkIdType>(mesh.positions.size());
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vertexCount);
  for (vtkIdType i = 0; i < vertexCount; ++i) {
    const Eigen::Vector3f& p = mesh.positions[static_cast<std::size_t>(i)];
    points->SetPoint(i, p.x(), p.y(), p.z());
  }

  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  const auto triangleCount = static_cast<vtkIdType>(mesh.triangles.size());
  offsets->SetNumberOfValues(triangleCount + 1);
  connectivity->SetNumberOfValues(3 * triangleCount);
  for (vtkIdType t = 0; t < triangleCount; ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[static_cast<std::size_t>(t)];
    offsets->SetValue(t, 3 * t);
    for (int k = 0; k < 3; ++k) connectivity->SetValue(3 * t + k, tri[k]);
  }
  offsets->SetValue(triangleCount, 3 * triangleCount);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(offsets, connectivity);

  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(polys);

  std::vector<Eigen::Vector3f> normals = mesh.normals;
  if (normals.size() != mesh.positions.size()) {
    TexturedMesh copy;
    copy.positions = mesh.positions;
    copy.triangles = mesh.triangles;
    copy.computeNormals();
    normals = std::move(copy.normals);
  }
  auto normalArray = vtkSmartPointer<vtkFloatArray>::New();
  normalArray->SetName("Normals");
  normalArray->SetNumberOfComponents(3);
  normalArray->SetNumberOfTuples(vertexCount);
  for (vtkIdType i = 0; i < vertexCount; ++i) {
    normalArray->SetTypedTuple(i, normals[static_cast<std::size_t>(i)].data());
  }
  polyData->GetPointData()->SetNormals(normalArray);

  if (mesh.uvs.size() == mesh.positions.size()) {
    auto uvArray = vtkSmartPointer<vtkFloatArray>::New();
    uvArray->SetName("TCoords");
    uvArray->SetNumberOfComponents(2);
    uvArray->SetNumberOfTuples(vertexCount);
    for (vtkIdType i = 0; i < vertexCount; ++i) {
      uvArray->SetTypedTuple(i, mesh.uvs[static_cast<std::size_t>(i)].data());
    }
    polyData->GetPointData()->SetTCoords(uvArray);
  }
  return polyData;
}

vtkSmartPointer<vtkImageData> toVtkImage(const cv::Mat& bgrTexture) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  if (bgrTexture.empty()) return image;
  cv::Mat rgb;
  if (bgrTexture.channels() == 1) {
    cv::cvtColor(bgrTexture, rgb, cv::COLOR_GRAY2RGB);
  } else if (bgrTexture.channels() == 4) {
    cv::cvtColor(bgrTexture, rgb, cv::COLOR_BGRA2RGB);
  } else {
    cv::cvtColor(bgrTexture, rgb, cv::COLOR_BGR2RGB);
  }
  if (rgb.depth() != CV_8U) rgb.convertTo(rgb, CV_8U);
  image->SetDimensions(rgb.cols, rgb.rows, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  const auto rowBytes = static_cast<std::size_t>(rgb.cols) * 3;
  for (int row = 0; row < rgb.rows; ++row) {
    // VTK's image row 0 is the bottom one.
    std::copy_n(rgb.ptr<unsigned char>(rgb.rows - 1 - row), rowBytes, out + row * rowBytes);
  }
  return image;
}

}  // namespace clm3d::ui
