// The procedural head generator: a closed, textured head mesh of a given identity and
// expression, with the 25 landmarks of the thesis's scheme (Scheme::thesis25()) known exactly.
// It stands in for the real 3D scans wherever they are absent: the demo trains its models on
// renders of these heads, and tests train and track on them.
//
// Contract of generateHead:
// - Coordinates are model coordinates (core/geometry/pose.hpp): millimetres, +x the subject's
//   left, +y up, +z out of the face, landmark 1 (index 0, between the eyes) at the origin.
// - landmarks: 25 points, 3D, all present, each a point of the continuous surface the mesh
//   samples (within the mesh's chord error, well under 0.5 mm at the default resolution), at the
//   feature it names: eye corners where the lid margins meet, eye centres at the iris centre,
//   brow ends where the painted brow ends, nose tip, alar bases where the alae meet the cheek,
//   mouth corners where the lip outline ends, lip points on the red-lip border at the mid-line,
//   chin and cheek points on the jaw line, earlobe points on the outer face of the lobe.
//   All but the earlobes (18, 24) face the front.
// - mesh: closed head with neck stump, ears as closed shells sunk into the head; triangles
//   counter-clockwise seen from outside; per-vertex normals and UVs; texture BGR, row 0 at the
//   top, UV (0, 0) at its bottom-left. It passes TexturedMesh::validate().
// - Deterministic: the same identity, expression and options give bit-identical output.
// - Left and right are mirror images in shape (x -> -x) for every identity; only the painted
//   fine detail (pores, hair strands) differs between the sides.
// Throws InputError for an identity, expression or options out of range.
#pragma once

#include <cstdint>

#include "core/mesh/textured_mesh.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/synth/head_identity.hpp"

namespace clm3d {

struct SynthOptions {
  // Angular grid step on the face, in degrees seen from the head's centre ([0.3, 3]); the back of
  // the head gets a coarser step. 0.75 gives about 110k triangles and ~1.3 mm edges on the face.
  double faceStepDegrees = 0.75;
  // Texture width and height in texels ([256, 8192]). 2048 gives about 6 texels per millimetre
  // on the face; 512 is enough for renders up to 128 pixels across the face.
  int textureSize = 2048;

  void validate() const;  // InputError when out of range
};

struct SynthHead {
  TexturedMesh mesh;
  LandmarkSet landmarks;  // 25 points, 3D, scheme thesis25
  HeadIdentity identity;
  Expression expression;
};

SynthHead generateHead(const HeadIdentity& identity, const Expression& expression = {},
                       const SynthOptions& options = {});

// generateHead(randomIdentity(seed), expression, options).
SynthHead generateHead(std::uint64_t seed, const Expression& expression = {},
                       const SynthOptions& options = {});

}  // namespace clm3d
