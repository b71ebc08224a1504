#include "core/dataset/ict_texture_request.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/dataset/axis_name.hpp"
#include "core/dataset/ict_textured.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/render/view_tiles.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace ict_texture_request_detail {

namespace fs = std::filesystem;
using R = IctTextureRequest;

std::vector<Option<R>> makeOptions() {
  const auto file = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(requiredOption(name, help), field, checkExistingFile);
  };
  return {
      textOption<R>(requiredOption("model",
                                   "ICT-FaceKit model: ICT-FaceKit_FaceXModel.tar.xz or "
                                   "its unpacked folder"),
                    &R::model, checkExistingPath),
      file("vertices",
           "Landmark vertex table of the ICT topology "
           "(tests/fixtures/ict-facekit/thesis25_vertices.json)",
           &R::vertices),
      file("scan", "Textured scan mesh (OBJ, PLY, ...)", &R::scan),
      file("landmarks",
           "The scan's 3D landmarks (thesis25, or ibug68 converted), in the mesh's frame",
           &R::landmarks),
      textOption<R>(commandOption("up", "The scan file's up axis"), &R::up, checkAxisName),
      textOption<R>(commandOption("front", "The scan file's out-of-the-face axis"), &R::front,
                    checkAxisName),
      realOption<R>(commandOption("scale", "Scan file units to millimetres", 1e-6, 1e6), &R::scale),
      integerOption<R>(
          commandOption("texture-size", "Baked texture width and height (texels)", 64, 8192),
          &R::textureSize),
      integerOption<R>(commandOption("samples",
                                     "Also write this many random ICT identities/expressions "
                                     "wearing the texture (ict-SCAN-sample-K.obj + .ljson "
                                     "landmarks in model coordinates)",
                                     0, 1000),
                       &R::samples),
      integerOption<R>(commandOption("seed-offset",
                                     "Sampling stream, as an ict_textured manifest entry's "
                                     "seed_offset",
                                     0, 9e18),
                       &R::seedOffset),
      textOption<R>(commandOption("contact-sheet",
                                  "With --samples: a PNG of each sample from the "
                                  "front and turned 40 degrees"),
                    &R::contactSheet),
      integerOption<R>(commandOption("tile-size", "Contact sheet tile size (pixels)", 64, 2048),
                       &R::tileSize),
      textOption<R>(requiredOption("out", "Output folder (ict-SCAN.obj, .mtl, .png)"), &R::out),
  };
}

// The sample from the front and turned 40 degrees, framed on the face (points within 110 mm of
// landmark 1, the origin) rather than on the neck and shoulders.
std::vector<cv::Mat> renderViews(const TexturedMesh& mesh, int size) {
  TexturedMesh face;
  for (const auto& p : mesh.positions) {
    if (p.norm() < 110.0F) face.positions.push_back(p);
  }
  return renderTilesFramedOn(mesh, face, {{0.0, 0.0}, {0.0, 40.0}}, size, 0.9);
}

void writeResiduals(std::ostream& out, const char* what, const std::vector<double>& residuals) {
  double sum = 0.0, worst = 0.0;
  int count = 0, worstIndex = -1;
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    if (std::isnan(residuals[i])) continue;
    sum += residuals[i];
    ++count;
    if (residuals[i] > worst) {
      worst = residuals[i];
      worstIndex = static_cast<int>(i) + 1;
    }
  }
  out << "  landmarks " << what << ": mean " << (count ? sum / count : 0.0) << " mm, max " << worst
      << " mm (landmark " << worstIndex << "), " << count << " landmarks\n";
}

}  // namespace ict_texture_request_detail

const std::vector<Option<IctTextureRequest>>& ictTextureOptions() {
  static const std::vector<Option<IctTextureRequest>> table =
      ict_texture_request_detail::makeOptions();
  return table;
}

std::string runIctTexture(const IctTextureRequest& args) {
  const Scheme& scheme = Scheme::thesis25();
  const ScanSource source =
      scanFromAxes(args.scan, args.landmarks, args.up, args.front, args.scale);
  const TexturedSubject scan = loadScanSubject(source, scheme);
  const std::vector<int> indices =
      readLandmarkVertexTable(args.vertices, scheme.name(), scheme.size());

  const auto start = std::chrono::steady_clock::now();
  const IctMeshModel model = loadIctMeshModel(args.model, indices, args.vertices);
  const double loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const IctTextureBake bake = bakeScanOntoIct(model, scan.mesh, scan.landmarks, args.textureSize);

  std::filesystem::create_directories(args.out);
  const std::filesystem::path obj = args.out / ("ict-" + source.subject + ".obj");
  saveObj(bake.registered, obj);

  const auto& r = bake.registration;
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  out << obj.string() << ": ICT neutral registered onto " << args.scan.string() << " ("
      << bake.registered.vertexCount() << " vertices, " << bake.registered.triangleCount()
      << " triangles, texture " << args.textureSize << "x" << args.textureSize << ")\n";
  out << "  surface: mean " << r.meanDistance << " mm, max " << r.maxDistance
      << " mm to the scan over the " << 100.0 * r.matchedFraction
      << "% of face and head vertices the scan covers\n";
  ict_texture_request_detail::writeResiduals(out, "after the similarity", r.landmarkResidualsRigid);
  ict_texture_request_detail::writeResiduals(out, "after non-rigid ICP", r.landmarkResiduals);
  out << "  texture: " << 100.0 * bake.bakedFraction
      << "% of texels baked from the scan, the rest filled\n";
  out << "  time: model read " << loadSeconds << " s, registration and bake " << bake.seconds
      << " s\n";
  if (args.samples == 0) return out.str();

  // Random identities and expressions wearing the baked texture, as the ict_textured source
  // samples them (one blendshape per sample).
  IctTexturedSet set;
  set.source.model = args.model;
  set.source.vertices = args.vertices;
  set.source.textureFrom = {source.subject};
  set.source.identities = args.samples;
  set.source.seedOffset = args.seedOffset;
  set.sampling.expressionsPerSample = 1;
  for (std::size_t e = 0; e < model.basis.expressions.size(); ++e) {
    set.sampling.expressionPool.push_back(static_cast<int>(e));
  }
  set.textures = {bake.texture};
  set.model = model;
  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  for (int k = 0; k < args.samples; ++k) {
    const TexturedSubject sample = sampleIctTextured(set, scheme, 0, k);
    const std::filesystem::path stem =
        args.out / ("ict-" + source.subject + "-sample-" + std::to_string(k));
    saveObj(sample.mesh, stem.string() + ".obj");
    writeLandmarks(stem.string() + ".ljson", sample.landmarks, scheme);
    out << stem.string() << ".obj: " << sample.id << "\n";
    if (args.contactSheet.empty()) continue;
    for (cv::Mat& tile : ict_texture_request_detail::renderViews(sample.mesh, args.tileSize))
      tiles.push_back(tile);
    captions.push_back(sample.id + " front");
    captions.push_back(sample.id + " yaw 40");
  }
  if (!args.contactSheet.empty()) {
    writeImage(args.contactSheet, makeContactSheet(tiles, 4, captions));
    out << args.contactSheet.string() << ": " << tiles.size() << " views\n";
  }
  return out.str();
}

}  // namespace clm3d
