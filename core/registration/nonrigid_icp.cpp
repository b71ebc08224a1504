#include "core/registration/nonrigid_icp.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "core/common/error.hpp"
#include "core/mesh/mesh_distance.hpp"
#include "core/registration/surface_index.hpp"

namespace clm3d {
namespace {

// Vertices at bit-identical positions (split at UV seams) become one unknown.
struct Welded {
  std::vector<int> of;                     // template vertex -> welded index
  std::vector<int> representative;         // welded index -> a template vertex
  std::vector<std::pair<int, int>> edges;  // welded, i < j, unique
};

Welded weld(const TexturedMesh& mesh) {
  Welded w;
  w.of.resize(mesh.positions.size());
  std::map<std::array<float, 3>, int> index;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const auto& p = mesh.positions[v];
    const auto [it, added] = index.emplace(std::array<float, 3>{p.x(), p.y(), p.z()},
                                           static_cast<int>(w.representative.size()));
    if (added) w.representative.push_back(static_cast<int>(v));
    w.of[v] = it->second;
  }
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      int a = w.of[static_cast<std::size_t>(t[k])],
          b = w.of[static_cast<std::size_t>(t[(k + 1) % 3])];
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      w.edges.emplace_back(a, b);
    }
  }
  std::sort(w.edges.begin(), w.edges.end());
  w.edges.erase(std::unique(w.edges.begin(), w.edges.end()), w.edges.end());
  return w;
}

// Area-weighted unit normals of the welded vertices.
Eigen::Matrix3Xd weldedNormals(const TexturedMesh& mesh, const Welded& w,
                               const Eigen::Matrix3Xd& x) {
  Eigen::Matrix3Xd n = Eigen::Matrix3Xd::Zero(3, x.cols());
  for (const auto& t : mesh.triangles) {
    const int a = w.of[static_cast<std::size_t>(t[0])], b = w.of[static_cast<std::size_t>(t[1])],
              c = w.of[static_cast<std::size_t>(t[2])];
    const Eigen::Vector3d f = (x.col(b) - x.col(a)).cross(x.col(c) - x.col(a));
    n.col(a) += f;
    n.col(b) += f;
    n.col(c) += f;
  }
  for (Eigen::Index i = 0; i < n.cols(); ++i) {
    const double len = n.col(i).norm();
    if (len > 0.0) n.col(i) /= len;
  }
  return n;
}

// A landmark as a weighted sum of welded vertices.
struct BoundLandmark {
  int index;  // landmark index
  std::array<int, 3> vertices;
  Eigen::Vector3d weights;
  Eigen::Vector3d target;
};

void checkMesh(const TexturedMesh& mesh, const char* role) {
  if (mesh.positions.empty() || mesh.triangles.empty()) {
    throw InputError(std::string("registration: the ") + role + " mesh " +
                     (mesh.source.empty() ? std::string() : "'" + mesh.source + "' ") +
                     "has no triangles");
  }
  for (const auto& t : mesh.triangles) {
    if (t.minCoeff() < 0 || static_cast<std::size_t>(t.maxCoeff()) >= mesh.positions.size()) {
      throw InputError(std::string("registration: the ") + role +
                       " mesh has a triangle with a vertex index out of range");
    }
  }
}

}  // namespace

NonRigidIcpResult registerNonRigid(const TexturedMesh& templ, const LandmarkSet& templLandmarks,
                                   const TexturedMesh& target, const LandmarkSet& targetLandmarks,
                                   const std::vector<bool>& dataVertices,
                                   const NonRigidIcpOptions& options,
                                   const ProgressCallback& progress, const CancelToken* cancel) {
  checkMesh(templ, "template");
  checkMesh(target, "target");
  if (templLandmarks.size() != targetLandmarks.size()) {
    throw InputError("registration: the template has " + std::to_string(templLandmarks.size()) +
                     " landmarks but the target has " + std::to_string(targetLandmarks.size()) +
                     "; they must be the same scheme");
  }
  if (!dataVertices.empty() && dataVertices.size() != templ.positions.size()) {
    throw InputError("registration: the data-vertex mask does not match the template's vertices");
  }
  if (options.stiffness.empty() || options.iterationsPerStage < 1) {
    throw InputError("registration: need at least one stiffness stage and one iteration");
  }

  // 1. Similarity from the common landmarks.
  std::vector<int> common;
  for (int i = 0; i < templLandmarks.size(); ++i) {
    if (templLandmarks.has(i) && targetLandmarks.has(i)) common.push_back(i);
  }
  if (common.size() < 3) {
    throw InputError("registration: only " + std::to_string(common.size()) +
                     " landmarks are present in both the template and the target; need 3");
  }
  Eigen::Matrix3Xd from(3, static_cast<Eigen::Index>(common.size())), to(3, from.cols());
  for (std::size_t k = 0; k < common.size(); ++k) {
    from.col(static_cast<Eigen::Index>(k)) = templLandmarks.point(common[k]);
    to.col(static_cast<Eigen::Index>(k)) = targetLandmarks.point(common[k]);
  }
  NonRigidIcpResult result;
  result.similarity = alignSimilarity(from, to, {}, options.allowScale);

  const Welded w = weld(templ);
  const auto n = static_cast<Eigen::Index>(w.representative.size());
  Eigen::Matrix3Xd rest(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    rest.col(i) = result.similarity.apply(Eigen::Vector3d(
        templ.positions[static_cast<std::size_t>(w.representative[static_cast<std::size_t>(i)])]
            .cast<double>()));
  }
  std::vector<char> isData(static_cast<std::size_t>(n), dataVertices.empty() ? 1 : 0);
  if (!dataVertices.empty()) {
    for (std::size_t v = 0; v < dataVertices.size(); ++v) {
      if (dataVertices[v]) isData[static_cast<std::size_t>(w.of[v])] = 1;
    }
  }

  // Landmarks bound to the template surface (before the similarity: binding is invariant).
  std::vector<BoundLandmark> bound;
  for (const int i : common) {
    const SurfacePoint sp = nearestSurfacePoint(templ, templLandmarks.point(i));
    const auto& t = templ.triangles[static_cast<std::size_t>(sp.triangle)];
    BoundLandmark b;
    b.index = i;
    Eigen::Vector3d corners[3];
    for (int k = 0; k < 3; ++k) {
      b.vertices[static_cast<std::size_t>(k)] = w.of[static_cast<std::size_t>(t[k])];
      corners[k] = templ.positions[static_cast<std::size_t>(t[k])].cast<double>();
    }
    const Eigen::Vector3d e0 = corners[1] - corners[0], e1 = corners[2] - corners[0],
                          d = sp.point - corners[0];
    const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
    const double det = d00 * d11 - d01 * d01;
    const double v = det > 0.0 ? (d11 * d.dot(e0) - d01 * d.dot(e1)) / det : 0.0;
    const double u = det > 0.0 ? (d00 * d.dot(e1) - d01 * d.dot(e0)) / det : 0.0;
    b.weights = {1.0 - v - u, v, u};
    b.target = targetLandmarks.point(i);
    bound.push_back(b);
  }
  auto landmarkResiduals = [&](const Eigen::Matrix3Xd& x) {
    std::vector<double> r(static_cast<std::size_t>(templLandmarks.size()),
                          std::numeric_limits<double>::quiet_NaN());
    for (const auto& b : bound) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k)
        p += b.weights[k] * x.col(b.vertices[static_cast<std::size_t>(k)]);
      r[static_cast<std::size_t>(b.index)] = (p - b.target).norm();
    }
    return r;
  };
  result.landmarkResidualsRigid = landmarkResiduals(rest);

  // Fixed part of the normal equations: edge Laplacian and landmark terms.
  std::vector<Eigen::Triplet<double>> laplacian;
  for (const auto& [a, b] : w.edges) {
    laplacian.emplace_back(a, a, 1.0);
    laplacian.emplace_back(b, b, 1.0);
    laplacian.emplace_back(a, b, -1.0);
    laplacian.emplace_back(b, a, -1.0);
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(laplacian.begin(), laplacian.end());
  std::vector<Eigen::Triplet<double>> landmarkTerms;
  Eigen::MatrixX3d landmarkRhs = Eigen::MatrixX3d::Zero(n, 3);
  for (const auto& b : bound) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        landmarkTerms.emplace_back(b.vertices[static_cast<std::size_t>(r)],
                                   b.vertices[static_cast<std::size_t>(c)],
                                   options.landmarkWeight * b.weights[r] * b.weights[c]);
      }
      landmarkRhs.row(b.vertices[static_cast<std::size_t>(r)]) +=
          options.landmarkWeight * b.weights[r] * b.target.transpose();
    }
  }
  Eigen::SparseMatrix<double> B(n, n);
  B.setFromTriplets(landmarkTerms.begin(), landmarkTerms.end());
  const Eigen::MatrixX3d restLaplacian = L * rest.transpose();

  // 2. Non-rigid ICP with annealed stiffness and rejection distance.
  const SurfaceIndex targetIndex(target);
  Eigen::Matrix3Xd x = rest;
  const int stages = static_cast<int>(options.stiffness.size());
  const int total = stages * options.iterationsPerStage;
  int done = 0;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  for (int s = 0; s < stages; ++s) {
    const double t = stages > 1 ? static_cast<double>(s) / (stages - 1) : 1.0;
    const double maxDistance =
        options.maxDistanceFirst * std::pow(options.maxDistanceLast / options.maxDistanceFirst, t);
    const double alpha = options.stiffness[static_cast<std::size_t>(s)];
    for (int it = 0; it < options.iterationsPerStage; ++it) {
      if (cancel) cancel->throwIfCancelled();
      const Eigen::Matrix3Xd normals = weldedNormals(templ, w, x);
      Eigen::VectorXd weight = Eigen::VectorXd::Zero(n);
      Eigen::MatrixX3d dataRhs = Eigen::MatrixX3d::Zero(n, 3);
      for (Eigen::Index i = 0; i < n; ++i) {
        if (!isData[static_cast<std::size_t>(i)]) continue;
        const auto hit = targetIndex.nearest(x.col(i), maxDistance);
        if (!hit || hit->normal.dot(normals.col(i)) < options.minNormalDot) continue;
        weight[i] = 1.0;
        dataRhs.row(i) = hit->point.transpose();
      }
      Eigen::SparseMatrix<double> D(n, n);  // data weights, every diagonal entry present
      std::vector<Eigen::Triplet<double>> diagonal;
      for (Eigen::Index i = 0; i < n; ++i) diagonal.emplace_back(i, i, weight[i] + 1e-9);
      D.setFromTriplets(diagonal.begin(), diagonal.end());
      const Eigen::SparseMatrix<double> A = alpha * L + B + D;
      if (done == 0) solver.analyzePattern(A);  // the pattern never changes
      solver.factorize(A);
      if (solver.info() != Eigen::Success) throw Error("registration: the sparse solve failed");
      const Eigen::MatrixX3d rhs =
          weight.asDiagonal() * dataRhs + alpha * restLaplacian + landmarkRhs;
      const Eigen::MatrixX3d solved = solver.solve(rhs);
      x = solved.transpose();
      ++done;
      if (progress) progress(static_cast<double>(done) / total, "non-rigid ICP");
    }
  }

  // 3. Residuals.
  double sum = 0.0, worst = 0.0;
  std::size_t matched = 0, data = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!isData[static_cast<std::size_t>(i)]) continue;
    ++data;
    const auto hit = targetIndex.nearest(x.col(i), options.maxDistanceLast);
    if (!hit) continue;
    ++matched;
    sum += hit->distance;
    worst = std::max(worst, hit->distance);
  }
  result.meanDistance = matched > 0 ? sum / static_cast<double>(matched) : 0.0;
  result.maxDistance = worst;
  result.matchedFraction =
      data > 0 ? static_cast<double>(matched) / static_cast<double>(data) : 0.0;
  result.landmarkResiduals = landmarkResiduals(x);
  result.positions.resize(templ.positions.size());
  result.rest.resize(templ.positions.size());
  for (std::size_t v = 0; v < templ.positions.size(); ++v) {
    result.positions[v] = x.col(w.of[v]).cast<float>();
    result.rest[v] = rest.col(w.of[v]).cast<float>();
  }
  return result;
}

std::vector<Eigen::Vector3f> followRegistration(const NonRigidIcpResult& registration,
                                                const std::vector<Eigen::Vector3f>& points,
                                                int neighbours) {
  std::vector<Eigen::Vector3f> out;
  out.reserve(points.size());
  const std::size_t k = std::max<std::size_t>(
      1, std::min<std::size_t>(static_cast<std::size_t>(std::max(1, neighbours)),
                               registration.rest.size()));
  std::vector<std::pair<float, std::size_t>> nearest;
  for (const auto& p : points) {
    const Eigen::Vector3f q =
        registration.similarity.apply(Eigen::Vector3d(p.cast<double>())).cast<float>();
    nearest.clear();
    for (std::size_t v = 0; v < registration.rest.size(); ++v) {
      nearest.emplace_back((registration.rest[v] - q).squaredNorm(), v);
    }
    if (nearest.empty()) {
      out.push_back(q);
      continue;
    }
    std::partial_sort(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(k),
                      nearest.end());
    Eigen::Vector3f shift = Eigen::Vector3f::Zero();
    float weights = 0.0F;
    for (std::size_t j = 0; j < k; ++j) {
      const float weight = 1.0F / (std::sqrt(nearest[j].first) + 1e-3F);
      shift += weight *
               (registration.positions[nearest[j].second] - registration.rest[nearest[j].second]);
      weights += weight;
    }
    out.push_back(q + shift / weights);
  }
  return out;
}

}  // namespace clm3d
