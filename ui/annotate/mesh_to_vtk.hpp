// The one conversion from core's TexturedMesh (per-vertex positions, normals, UVs, a BGR texture
// with row 0 at the top) to what VTK draws: a vtkPolyData of triangles with normals and texture
// coordinates, and an RGB vtkImageData with row 0 at the bottom. Data objects only, so it may run
// on the worker thread that loads the scan.
#pragma once

#include <vtkSmartPointer.h>

#include "core/mesh/textured_mesh.hpp"

class vtkImageData;
class vtkPolyData;

namespace clm3d::ui {

vtkSmartPointer<vtkPolyData> toVtkPolyData(const TexturedMesh& mesh);
// Empty image (no scalars) for an empty texture.
vtkSmartPointer<vtkImageData> toVtkImage(const cv::Mat& bgrTexture);

}  // namespace clm3d::ui
