// Textured ICT-FaceKit heads: the model's neutral mesh reduced to the regions a rendered head needs
// (face, head and neck, mouth and eye sockets, eyeballs), with its UV tiles packed into one
// texture; a scan's texture baked into that layout after registering the neutral mesh onto the
// scan (core/registration); and samples of new identities and expressions that wear the baked
// texture (same UVs, new vertex positions). Each texture source is baked once per load.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/dataset/ict_facekit.hpp"
#include "core/dataset/manifest.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/registration/nonrigid_icp.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

// The ICT model's kept regions as full meshes.
struct IctMeshModel {
  std::filesystem::path file;
  std::vector<int> keptVertices;  // ICT vertex indices kept, ascending; basis column k = vertex k
  IctLandmarkBasis basis;         // positions of the kept vertices (mm, file axes)
  // The neutral as a renderable mesh: vertices split where UVs differ (mesh vertex v shows basis
  // column column[v]); UVs in the packed layout (ICT tiles u in [0, 1] and [1, 2] side by side in
  // the top half, left and right eyeball tiles in the bottom half); no texture.
  TexturedMesh mesh;
  std::vector<int> column;
  std::vector<bool> skinVertex;      // mesh vertex of the face or head-and-neck regions
  std::vector<bool> mouthTriangle;   // mesh triangle of the mouth socket
  std::vector<int> landmarkColumns;  // per scheme point: basis column, -1 = missing
};

// Reads the model (archive or folder) once: positions of the kept vertices of every mesh, and the
// neutral's faces and UVs. landmarkVertices: the ICT vertex index of each scheme point (-1 =
// missing; readLandmarkVertexTable). Throws InputError naming the model or vertex table.
IctMeshModel loadIctMeshModel(const std::filesystem::path& model,
                              const std::vector<int>& landmarkVertices,
                              const std::filesystem::path& vertexTable,
                              const ProgressCallback& progress = {},
                              const CancelToken* cancel = nullptr);

// The mesh with positions given per basis column (3 x columns, mm) and `texture`.
TexturedMesh ictMeshAt(const IctMeshModel& model, const Eigen::Matrix3Xd& columns,
                       const cv::Mat& texture);
// The scheme's landmarks at those positions (missing where the table has no vertex).
LandmarkSet ictLandmarksAt(const IctMeshModel& model, const Eigen::Matrix3Xd& columns);

struct IctTextureBake {
  cv::Mat texture;          // in the model's packed UV layout
  TexturedMesh registered;  // the neutral registered onto the scan (scan frame), with texture
  NonRigidIcpResult registration;
  double bakedFraction = 0.0;  // texels that found the scan (the others are filled)
  double seconds = 0.0;        // registration and bake
};

// Registers the neutral onto `scan` (whose `scanLandmarks` are the same scheme, in the scan's
// frame, mm) and bakes the scan's texture at textureSize x textureSize. Throws InputError naming
// the scan for too few common landmarks or a failed bake; Cancelled.
IctTextureBake bakeScanOntoIct(const IctMeshModel& model, const TexturedMesh& scan,
                               const LandmarkSet& scanLandmarks, int textureSize,
                               const ProgressCallback& progress = {},
                               const CancelToken* cancel = nullptr);

// One ict_textured manifest entry ready to sample: the model read once and each texture baked once.
struct IctTexturedSet {
  std::size_t entry = 0;  // index in manifest.ictTextured (for subject ids)
  IctTexturedSource source;
  IctMeshModel model;
  IctSampling sampling;
  std::vector<cv::Mat> textures;  // per source.textureFrom
  bool levelEyes = true;          // level on the eye centres like the scans (thesis25, ibug68)
};

// Reads the entry's model and bakes each of its texture sources (`skins[i]`: the scan subject
// named by source.textureFrom[i], as loadTexturedSubjects loads it). Throws InputError naming the
// manifest field for an unknown blendshape name; Cancelled.
IctTexturedSet prepareIctTextured(const DatasetManifest& manifest, std::size_t entry,
                                  const std::vector<TexturedSubject>& skins, const Scheme& scheme,
                                  const ProgressCallback& progress = {},
                                  const CancelToken* cancel = nullptr);

// Sample `index` wearing texture `texture`: a random identity and expression (seeded by the
// entry's seed_offset, independent of threads), in model coordinates like the scans.
TexturedSubject sampleIctTextured(const IctTexturedSet& set, const Scheme& scheme,
                                  std::size_t texture, int index);

}  // namespace clm3d
