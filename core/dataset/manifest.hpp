// The dataset manifest: one JSON file (format in docs/dataset.md) listing what a model is trained
// from - textured scans with their landmark files, procedural heads (seeds x expressions) and
// shape-only sources (the ICT-FaceKit morphable model) - so that a training run is reproducible
// from one file. Paths in the file are relative to the file's folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/dataset/augmentation_settings.hpp"

namespace clm3d {

// A textured 3D scan and its landmarks (any format readLandmarks reads, 3D; 68-point iBUG files
// are converted when the scheme is thesis25).
struct ScanSource {
  std::filesystem::path mesh, landmarks;  // absolute
  std::string subject, expression;        // expression defaults to "neutral"
  std::string up = "+y", front = "+z";    // the file's up and out-of-the-face axes
  bool levelEyes = true;                  // turn so that the eye centres are level (yaw/roll 0)
  double scale = 1.0;  // file units to millimetres (mesh and landmarks are multiplied by it)
};

// Procedural heads (core/synth): every seed with every expression preset.
struct ProceduralSource {
  std::vector<std::uint64_t> seeds;
  std::vector<std::string> expressions;  // each seed rendered with each expression
  int textureSize = 1024;
  double faceStepDegrees = 1.0;
};

// Shape-only landmark sets sampled from the ICT-FaceKit morphable model.
struct IctSource {
  std::filesystem::path model;     // the .tar.xz (any archive libarchive reads) or a folder of OBJs
  std::filesystem::path vertices;  // thesis25_vertices.json: the vertex index of each landmark
  int identities = 50;             // number of samples (each a random identity)
  std::vector<std::string> expressions;  // blendshape names to draw from; empty = all
  int expressionsPerSample = 2;          // distinct blendshapes per sample, weights in [0, 1]
  double identityWeightSd = 1.0;         // standard deviation of the identity weights
  std::uint64_t seedOffset = 0;          // added to the sampling seed
};

// Random MakeHuman identities (core/dataset/detail/makehuman_head.hpp): each identity (seed
// seedOffset + i) with each expression is one textured subject.
struct MakeHumanSource {
  std::filesystem::path root;      // the MakeHuman data folder (base/, skins/, eyes/, targets/)
  std::filesystem::path vertices;  // thesis25_vertices.json: base-mesh vertex of each landmark
  int identities = 10;
  std::vector<std::string> skins;        // skin stems to draw from; empty = all
  std::vector<std::string> eyes;         // eye texture stems; empty = all
  std::vector<std::string> expressions;  // "neutral" or unit targets joined by '+'
  std::string expressionUnits = "caucasian";
  double identityWeight = 0.5;
  double asymmetry = 0.1;
  double expressionWeight = 0.8;
  int textureSize = 1024;
  std::uint64_t seedOffset = 0;
};

// Textured ICT-FaceKit heads: the neutral registered onto each listed scan, the scan's texture
// baked into ICT's UV layout, worn by random identities and expressions (docs/texture-transfer.md).
struct IctTexturedSource {
  std::filesystem::path model;     // the .tar.xz (any archive libarchive reads) or a folder of OBJs
  std::filesystem::path vertices;  // thesis25_vertices.json: the vertex index of each landmark
  std::vector<std::string> textureFrom;  // `subject`s of the manifest's scans whose skin is baked
  int identities = 10;                   // samples per texture (each a random identity)
  std::vector<std::string> expressions;  // blendshape names to draw from; empty = all
  int expressionsPerSample = 1;          // distinct blendshapes per sample, weights in [0, 1]
  double identityWeightSd = 1.0;         // standard deviation of the identity weights
  int textureSize = 1024;                // baked texture width and height
  std::uint64_t seedOffset = 0;          // added to the sampling seed
};

// Annotated photos (docs/real-faces.md): every image of a folder, or every image a text file lists
// (one path per line, relative to the list's folder; blank lines and # comments skipped), each
// with a landmark file of the same stem beside it (.pts, .ljson or .csv; 68-point iBUG and
// 21-point AFLW files are converted to the scheme by core/scheme/scheme_map.hpp). Each photo is
// placed in a view by the 3D pose of its points.
struct PhotoSource {
  std::filesystem::path folder;  // absolute; empty when `list` is given
  std::filesystem::path list;    // absolute; empty when `folder` is given
  int limit = 0;                 // at most this many photos, the first in name order (0 = all)
  // Trust the cheek and chin-side points a 68-point file's jaw contour gives (by default they
  // train nothing: the contour slides along the jaw, so they have no fixed anatomical place).
  bool jaw = false;
  // At most this many samples (a photo or its mirror image) of this source join each view (0 = no
  // cap), the first in list order: a large set at every pose (AFLW) trains the side views without
  // multiplying the training time in the views it crowds.
  int perView = 0;
  // The point refiner (core/train/refiner_training.hpp) learns from this source's photos. A
  // source whose photos mark few points at side poses would leave the refiner too few points
  // marked in nearly every photo.
  bool refiner = true;
};

// Annotated photos that the whole photo pipeline fits once the model is trained, so that the point
// check is calibrated on the pipeline's own fits (core/eval/photo_fit_calibration.hpp, as `clm3d
// calibrate`): of the folder or list, the photos at positions offset, offset + every, ...
// (0-based). They should be photos the check did not learn from (a `photos` source with `refiner`
// false).
struct CalibrationPhotos {
  std::filesystem::path folder;  // absolute; empty when `list` is given
  std::filesystem::path list;    // absolute; empty when `folder` is given
  int every = 1;
  int offset = 0;
  double rightBelow = 0.08;  // a fit is right within this share of its truth's face box
  int minEach = 10;          // right and wrong fits a view's |yaw| needs for a curve of its own
  int imageMinFits = 100;    // fits a view's |yaw| needs for the image term (0: never)
};

struct DatasetManifest {
  std::filesystem::path file;       // where it was read from (for messages)
  std::string scheme = "thesis25";  // built-in name or an absolute path to a scheme JSON
  std::vector<ScanSource> scans;
  std::vector<ProceduralSource> procedural;
  std::vector<IctSource> ict;
  std::vector<IctTexturedSource> ictTextured;
  std::vector<MakeHumanSource> makehuman;
  std::vector<PhotoSource> photos;
  std::optional<CalibrationPhotos> calibrationPhotos;
  AugmentationSettings augmentation;  // appearance augmentation of the training renders
  std::string name;                   // for provenance; defaults to the file's stem
};

// Ids of the textured subjects a manifest yields: "SUBJECT/EXPRESSION" for a scan,
// "procedural/SEED/EXPRESSION" for a procedural head. Unique within a manifest.
std::string scanSubjectId(const ScanSource& scan);
std::string proceduralSubjectId(std::uint64_t seed, const std::string& expression);
// "ict/TEXTURE/INDEX" for sample INDEX (0-based) of an ict_textured entry wearing TEXTURE's skin;
// `entry` (0-based) tells entries apart: "ict1/..." for the second entry and so on.
std::string ictTexturedSubjectId(std::size_t entry, const std::string& texture, int index);
// "makehuman/SEED/EXPRESSION" for a MakeHuman identity.
std::string makehumanSubjectId(std::uint64_t seed, const std::string& expression);

// Reads and validates a manifest: every field's type and range, that the referenced files exist,
// expression presets and seed lists. Paths relative to the manifest's folder become absolute.
// Throws InputError "FILE: field scans[2].landmarks: file not found: PATH" and the like.
DatasetManifest loadManifest(const std::filesystem::path& path);

// Parses a manifest from text; `file` names it in errors and its folder resolves relative paths.
DatasetManifest parseManifest(const std::string& text, const std::filesystem::path& file);

}  // namespace clm3d
