#include "ui/annotate/scan_loader.hpp"

#include <vtkImageData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cctype>

#include "core/common/error.hpp"
#include "core/dataset/axis_name.hpp"
#include "core/dataset/manifest.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/scheme/landmark_file.hpp"
#include "ui/annotate/mesh_to_vtk.hpp"

namespace clm3d::ui {

namespace fs = std::filesystem;

namespace {

bool isLjson(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".ljson" || ext == ".json";
}

fs::path ljsonBeside(const fs::path& mesh) {
  fs::path path = mesh;
  path.replace_extension(".ljson");
  return path;
}

}  // namespace

ScanFiles scanFilesForMesh(const fs::path& mesh) {
  ScanFiles files;
  files.mesh = fs::absolute(mesh);
  files.landmarks = ljsonBeside(files.mesh);
  files.annotation = files.landmarks;
  files.title = QString::fromStdString(files.mesh.filename().string());
  return files;
}

ScanFiles scanFilesForSource(const ScanSource& source, const QString& title) {
  ScanFiles files;
  files.mesh = source.mesh;
  files.landmarks = source.landmarks;
  files.annotation = isLjson(source.landmarks) ? source.landmarks : ljsonBeside(source.mesh);
  files.up = axisFromName(source.up).value_or(Eigen::Vector3d::UnitY());
  files.front = axisFromName(source.front).value_or(Eigen::Vector3d::UnitZ());
  files.title = title;
  return files;
}

LandmarkSet readScanLandmarks(const fs::path& path, const Scheme& scheme) {
  LandmarkSet points = readLandmarks(path, &scheme);
  if (points.dims() != 3) {
    throwInputError(path, "the landmarks are 2D; a scan needs 3D landmarks");
  }
  return points;
}

LoadedScan loadScan(const ScanFiles& files, const Scheme& scheme, const ProgressCallback& progress,
                    CancelToken& cancel) {
  LoadedScan scan;
  scan.files = files;
  progress(0.05, "reading the mesh");
  const TexturedMesh mesh = loadTexturedMesh(files.mesh, {.requireTexture = false});
  cancel.throwIfCancelled();
  progress(0.6, "reading the landmarks");
  std::error_code error;
  if (fs::exists(files.annotation, error)) {
    scan.points = readScanLandmarks(files.annotation, scheme);
  } else if (fs::exists(files.landmarks, error)) {
    scan.points = readScanLandmarks(files.landmarks, scheme);
  } else {
    scan.points = LandmarkSet(scheme.size(), 3);
  }
  cancel.throwIfCancelled();
  progress(0.7, "preparing the view");
  scan.mesh = toVtkPolyData(mesh);
  scan.texture = toVtkImage(mesh.texture);
  const Eigen::AlignedBox3f bounds = mesh.bounds();
  scan.bounds = Eigen::AlignedBox3d(bounds.min().cast<double>(), bounds.max().cast<double>());
  return scan;
}

}  // namespace clm3d::ui
