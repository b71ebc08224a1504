// What the trainer consumes from a dataset manifest: textured heads in model coordinates, ready to
// render from every training view (the scans, oriented and centred, and the procedural heads), and
// shape-only 3D landmark sets that widen the shape model without any texture (ICT-FaceKit samples).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/dataset/manifest.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

// One textured head ready to render.
struct TexturedSubject {
  std::string id;  // "james/neutral", "procedural/7/smile" (scanSubjectId, proceduralSubjectId)
  std::string subject, expression;  // "james" / "procedural/7"; "neutral", "smile"
  TexturedMesh mesh;  // model coordinates: mm, +y up, +z front, levelled on the eyes, landmark 1 at
                      // the origin
  LandmarkSet landmarks;  // 3D, the manifest's scheme, same coordinates; missing points allowed
};

// Loads the scans and generates the procedural heads, on `threads` threads (0 = one per core),
// in manifest order: scans first, then each procedural entry seed by seed, each seed's expressions
// in the order listed, then each MakeHuman entry identity by identity ("makehuman/SEED/EXPRESSION",
// seed = seed_offset + i, each read of the MakeHuman data shared by the entry's identities), then
// each ict_textured entry texture by texture ("ict/TEXTURE/K"; the model read and each texture
// baked once per call, docs/texture-transfer.md). The result does not depend on `threads`. Scans
// are turned from their file axes (up/front) into model axes, or, with level_eyes (the default), so
// that the line between the eye centres is the +x axis; then moved so that landmark 1 is the
// origin. Throws InputError naming the data file that is wrong, Cancelled when `cancel` fires.
std::vector<TexturedSubject> loadTexturedSubjects(const DatasetManifest& manifest, int threads,
                                                  const ProgressCallback& progress = {},
                                                  const CancelToken* cancel = nullptr);

// One scan as loadTexturedSubjects loads it (file units to mm, turned into model axes, landmark 1
// at the origin), e.g. to register a template onto it (clm3d ict-texture).
TexturedSubject loadScanSubject(const ScanSource& scan, const Scheme& scheme);

// One procedural head (seed, expression preset) as loadTexturedSubjects generates it from a
// procedural entry with `source`'s texture size and mesh step (its seeds and expressions unused),
// e.g. for one synthetic test sequence (clm3d synth --head-seed).
TexturedSubject makeProceduralSubject(std::uint64_t seed, const std::string& expression,
                                      const ProceduralSource& source);

// Shape-only 3D landmark sets from the manifest's ICT-FaceKit sources (in order, each
// `identities` samples), in the same coordinates as the textured subjects (mm, +y up, +z front,
// levelled on the eyes, landmark 1 at the origin). Deterministic for a seed (plus each source's
// seed_offset). Reads each source's model once; nothing is cached on disk.
std::vector<LandmarkSet> sampleShapeOnlyLandmarks(const DatasetManifest& manifest,
                                                  std::uint64_t seed,
                                                  const ProgressCallback& progress = {},
                                                  const CancelToken* cancel = nullptr);

}  // namespace clm3d
