// Which files make up one annotated scan, and loading them on a worker thread: the textured mesh
// through core's importer (converted to VTK data objects there, so the GUI thread only adds
// actors) and its landmarks. The annotation is always written as LJSON v3: to the scan's landmark
// file when that is LJSON, else to the mesh's stem + .ljson, which is then read in preference to
// the original (a 68-point .pts, say) on the next open.
#pragma once

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <Eigen/Geometry>
#include <QString>
#include <filesystem>

#include "core/common/progress.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {
struct ScanSource;
}

namespace clm3d::ui {

struct ScanFiles {
  std::filesystem::path mesh;
  std::filesystem::path landmarks;   // read when the annotation does not exist yet; may not exist
  std::filesystem::path annotation;  // the LJSON the page saves to
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  Eigen::Vector3d front = Eigen::Vector3d::UnitZ();
  QString title;  // shown in the scan list
};

// A mesh opened on its own: landmarks beside it with the same stem and .ljson.
ScanFiles scanFilesForMesh(const std::filesystem::path& mesh);
// A scan of the dataset manifest (its axes and landmark file).
ScanFiles scanFilesForSource(const ScanSource& source, const QString& title);

struct LoadedScan {
  ScanFiles files;
  vtkSmartPointer<vtkPolyData> mesh;
  vtkSmartPointer<vtkImageData> texture;
  Eigen::AlignedBox3d bounds;
  LandmarkSet points;  // scheme order, 3D; all missing when no file existed
};

// Throws InputError naming the file for an unreadable mesh or landmark file, and for landmarks
// that are not 3D.
LoadedScan loadScan(const ScanFiles& files, const Scheme& scheme, const ProgressCallback& progress,
                    CancelToken& cancel);

// Reads 3D landmarks in the scheme's order (68-point iBUG files converted for thesis25); throws
// InputError naming the file if they are 2D.
LandmarkSet readScanLandmarks(const std::filesystem::path& path, const Scheme& scheme);

}  // namespace clm3d::ui
