// The ICT-FaceKit morphable model (neutral mesh + identity principal components + expression
// blendshapes, all OBJ on one topology) reduced to the landmark vertices: enough to sample
// plausible 3D landmark sets of new identities and expressions for the shape model, read straight
// from the distributed .tar.xz (or an unpacked folder) in a few seconds.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

// Reads a landmark vertex table (tests/fixtures/ict-facekit/thesis25_vertices.json): "scheme"
// (must equal schemeName) and "vertices" (one 0-based OBJ vertex index per scheme point, -1 =
// missing). Throws InputError naming the file and field.
std::vector<int> readLandmarkVertexTable(const std::filesystem::path& path,
                                         const std::string& schemeName, int schemeSize);

// The landmark vertices of every mesh of the model, in millimetres (the files are centimetres),
// file axes (+y up, +z out of the face). Missing landmarks are NaN columns.
struct IctLandmarkBasis {
  Eigen::Matrix3Xd neutral;                   // generic_neutral_mesh
  std::vector<Eigen::Matrix3Xd> identities;   // identityNNN - neutral, by name
  std::vector<std::string> expressionNames;   // every other OBJ's name (file stem), sorted
  std::vector<Eigen::Matrix3Xd> expressions;  // blendshape - neutral, same order
};

// `model` is an archive libarchive reads (.tar.xz, .tar.gz, .zip) or a folder, searched
// recursively for *.obj. Throws InputError naming the model (and the entry) for a missing neutral
// mesh, no identities, two meshes of one name or a malformed OBJ; Cancelled when cancel fires.
IctLandmarkBasis loadIctLandmarkBasis(const std::filesystem::path& model,
                                      const std::vector<int>& vertexIndices,
                                      const ProgressCallback& progress = {},
                                      const CancelToken* cancel = nullptr);

// loadIctLandmarkBasis for any vertex list (e.g. every vertex of the regions a textured ICT head
// keeps: the basis then holds full meshes), also handing back the whole text of
// generic_neutral_mesh.obj in neutralObjText when given (its faces and UVs), from the same pass
// over the archive.
IctLandmarkBasis loadIctBasis(const std::filesystem::path& model,
                              const std::vector<int>& vertexIndices, std::string* neutralObjText,
                              const ProgressCallback& progress = {},
                              const CancelToken* cancel = nullptr);

// How one sample is drawn.
struct IctSampling {
  double identityWeightSd = 1.0;    // every identity weight ~ N(0, sd^2)
  std::vector<int> expressionPool;  // indices into basis.expressions to draw from
  int expressionsPerSample = 2;     // distinct draws, weights uniform in [0, 1]
};

// Sample `index` of a stream fixed by `seed`: neutral + sum w_i identity_i + sum e_j expression_j,
// in the model's file coordinates (mm), for whatever vertices the basis holds (landmarks or whole
// meshes: the weights depend only on the seed, the index and the basis's mesh counts). A drawn
// _L/_R blendshape comes with its mirror partner at the same weight when the partner is in the
// pool, so sampled expressions are symmetric.
Eigen::Matrix3Xd sampleIctLandmarks(const IctLandmarkBasis& basis, const IctSampling& sampling,
                                    std::uint64_t seed, std::uint64_t index);

}  // namespace clm3d
