#include "core/profile/dense_face.hpp"

#include <algorithm>
#include <string>

#include "core/common/error.hpp"
#include "core/registration/surface_index.hpp"

namespace clm3d {
namespace {

// ICT vertex ranges (the model's README): the head-and-neck region a photo of the face rarely
// shows.
constexpr int kIctHeadNeckFirst = 9409;
constexpr int kIctHeadNeckLast = 11247;

}  // namespace

Eigen::Matrix3Xd DenseFace::at(const Eigen::VectorXd& weights) const {
  if (weights.size() != static_cast<Eigen::Index>(modes.size())) {
    throw InputError("dense face: " + std::to_string(weights.size()) + " weights for " +
                     std::to_string(modes.size()) + " modes");
  }
  Eigen::Matrix3Xd columns = neutral;
  for (std::size_t k = 0; k < modes.size(); ++k) {
    if (weights[static_cast<Eigen::Index>(k)] != 0.0) {
      columns += weights[static_cast<Eigen::Index>(k)] * modes[k];
    }
  }
  return columns;
}

LandmarkSet DenseFace::landmarksAt(const Eigen::Matrix3Xd& columns) const {
  LandmarkSet landmarks(static_cast<int>(landmarkColumns.size()), 3);
  for (std::size_t p = 0; p < landmarkColumns.size(); ++p) {
    if (landmarkColumns[p] >= 0) {
      landmarks.set(static_cast<int>(p), Eigen::Vector3d(columns.col(landmarkColumns[p])));
    }
  }
  return landmarks;
}

TexturedMesh DenseFace::meshAt(const Eigen::Matrix3Xd& columns) const {
  TexturedMesh out = mesh;
  for (std::size_t v = 0; v < column.size(); ++v) {
    out.positions[v] = columns.col(column[v]).cast<float>();
  }
  out.normals.clear();
  out.computeNormals();
  return out;
}

std::vector<int> mirrorColumns(const DenseFace& face, double maxDistanceMm) {
  TexturedMesh surface = face.meshAt(face.neutral);
  const SurfaceIndex index(surface);
  std::vector<int> mirror(static_cast<std::size_t>(face.columnCount()));
  for (int c = 0; c < face.columnCount(); ++c) {
    mirror[static_cast<std::size_t>(c)] = c;
    Eigen::Vector3d image = face.neutral.col(c);
    image.x() = -image.x();
    const auto hit = index.nearest(image, maxDistanceMm);
    if (!hit) continue;
    const Eigen::Vector3i& corners = surface.triangles[static_cast<std::size_t>(hit->triangle)];
    int best = 0;
    hit->barycentric.maxCoeff(&best);
    mirror[static_cast<std::size_t>(c)] = face.column[static_cast<std::size_t>(corners[best])];
  }
  return mirror;
}

DenseFace denseFaceFromIct(const IctMeshModel& model, const IctDenseSettings& settings) {
  const IctLandmarkBasis& basis = model.basis;
  if (model.landmarkColumns.empty() || model.landmarkColumns[0] < 0) {
    throwInputError(model.file, "landmark 1, the profile's origin, has no vertex");
  }
  DenseFace face;
  const Eigen::Vector3d origin = basis.neutral.col(model.landmarkColumns[0]);
  face.neutral = basis.neutral.colwise() - origin;
  const int identities =
      std::clamp(settings.identityModes, 0, static_cast<int>(basis.identities.size()));
  for (int k = 0; k < identities; ++k) {
    face.modes.push_back(basis.identities[static_cast<std::size_t>(k)]);
    face.modeNames.push_back("identity" + std::to_string(k));
  }
  for (const std::string& name : settings.expressions) {
    const auto it = std::find(basis.expressionNames.begin(), basis.expressionNames.end(), name);
    if (it == basis.expressionNames.end()) {
      throwInputError(model.file, "has no expression blendshape '" + name + "'");
    }
    face.modes.push_back(
        settings.expressionSd *
        basis.expressions[static_cast<std::size_t>(it - basis.expressionNames.begin())]);
    face.modeNames.push_back(name);
  }
  face.mesh = model.mesh;
  face.column = model.column;
  face.landmarkColumns = model.landmarkColumns;
  face.mesh.translate(-origin.cast<float>());
  face.outerTriangle.assign(face.mesh.triangles.size(), false);
  for (std::size_t t = 0; t < face.mesh.triangles.size(); ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      const int c = face.column[static_cast<std::size_t>(face.mesh.triangles[t][corner])];
      const int v = model.keptVertices[static_cast<std::size_t>(c)];
      if (v >= kIctHeadNeckFirst && v <= kIctHeadNeckLast) face.outerTriangle[t] = true;
    }
  }
  face.mirrorColumn = mirrorColumns(face);
  return face;
}

DenseFace denseFaceFromMesh(const TexturedMesh& mesh, const LandmarkSet& landmarks) {
  mesh.validate();
  DenseFace face;
  face.mesh = mesh;
  const int vertices = static_cast<int>(mesh.vertexCount());
  face.neutral.resize(3, vertices + landmarks.presentCount());
  for (int v = 0; v < vertices; ++v) {
    face.neutral.col(v) = mesh.positions[static_cast<std::size_t>(v)].cast<double>();
    face.column.push_back(v);
  }
  int next = vertices;
  for (int i = 0; i < landmarks.size(); ++i) {
    if (!landmarks.has(i)) {
      face.landmarkColumns.push_back(-1);
      continue;
    }
    face.neutral.col(next) = landmarks.point(i);
    face.landmarkColumns.push_back(next++);
  }
  face.mirrorColumn = mirrorColumns(face);
  return face;
}

}  // namespace clm3d
