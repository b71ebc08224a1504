// clm3d ict-texture: registers the ICT-FaceKit neutral mesh onto a textured scan (landmarks, then
// non-rigid ICP), bakes the scan's texture into ICT's UV layout and writes the registered neutral
// as OBJ + MTL + PNG, so the transfer can be checked in any mesh viewer before training on it.
// Prints the registration residuals. All work is done by core (dataset, registration).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "app/commands/commands.hpp"
#include "app/commands/scan_options.hpp"
#include "core/common/error.hpp"
#include "core/dataset/ict_textured.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/render/view_tiles.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct IctTextureArgs {
  fs::path model, vertices, scan, landmarks, out;
  std::string up = "+y", front = "+z";
  double scale = 1.0;
  int textureSize = 1024;
  int samples = 0;
  std::uint64_t seedOffset = 0;
  fs::path contactSheet;
  int tileSize = 256;
};

// The sample from the front and turned 40 degrees, framed on the face (points within 110 mm of
// landmark 1, the origin) rather than on the neck and shoulders.
std::vector<cv::Mat> renderViews(const TexturedMesh& mesh, int size) {
  TexturedMesh face;
  for (const auto& p : mesh.positions) {
    if (p.norm() < 110.0F) face.positions.push_back(p);
  }
  return renderTilesFramedOn(mesh, face, {{0.0, 0.0}, {0.0, 40.0}}, size, 0.9);
}

void printResiduals(const char* what, const std::vector<double>& residuals) {
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
  std::cout << "  landmarks " << what << ": mean " << (count ? sum / count : 0.0) << " mm, max "
            << worst << " mm (landmark " << worstIndex << "), " << count << " landmarks\n";
}

void runIctTexture(const IctTextureArgs& args) {
  const Scheme& scheme = Scheme::thesis25();
  const ScanSource source =
      scanFromOptions(args.scan, args.landmarks, args.up, args.front, args.scale);
  const TexturedSubject scan = loadScanSubject(source, scheme);
  const std::vector<int> indices =
      readLandmarkVertexTable(args.vertices, scheme.name(), scheme.size());

  const auto start = std::chrono::steady_clock::now();
  const IctMeshModel model = loadIctMeshModel(args.model, indices, args.vertices);
  const double loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const IctTextureBake bake = bakeScanOntoIct(model, scan.mesh, scan.landmarks, args.textureSize);

  fs::create_directories(args.out);
  const fs::path obj = args.out / ("ict-" + source.subject + ".obj");
  saveObj(bake.registered, obj);

  const auto& r = bake.registration;
  std::cout << std::fixed << std::setprecision(2);
  std::cout << obj.string() << ": ICT neutral registered onto " << args.scan.string() << " ("
            << bake.registered.vertexCount() << " vertices, " << bake.registered.triangleCount()
            << " triangles, texture " << args.textureSize << "x" << args.textureSize << ")\n";
  std::cout << "  surface: mean " << r.meanDistance << " mm, max " << r.maxDistance
            << " mm to the scan over the " << 100.0 * r.matchedFraction
            << "% of face and head vertices the scan covers\n";
  printResiduals("after the similarity", r.landmarkResidualsRigid);
  printResiduals("after non-rigid ICP", r.landmarkResiduals);
  std::cout << "  texture: " << 100.0 * bake.bakedFraction
            << "% of texels baked from the scan, the rest filled\n";
  std::cout << "  time: model read " << loadSeconds << " s, registration and bake " << bake.seconds
            << " s\n";
  if (args.samples == 0) return;

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
    const fs::path stem = args.out / ("ict-" + source.subject + "-sample-" + std::to_string(k));
    saveObj(sample.mesh, stem.string() + ".obj");
    writeLandmarks(stem.string() + ".ljson", sample.landmarks, scheme);
    std::cout << stem.string() << ".obj: " << sample.id << "\n";
    if (args.contactSheet.empty()) continue;
    for (cv::Mat& tile : renderViews(sample.mesh, args.tileSize)) tiles.push_back(tile);
    captions.push_back(sample.id + " front");
    captions.push_back(sample.id + " yaw 40");
  }
  if (!args.contactSheet.empty()) {
    writeImage(args.contactSheet, makeContactSheet(tiles, 4, captions));
    std::cout << args.contactSheet.string() << ": " << tiles.size() << " views\n";
  }
}

}  // namespace

void addIctTextureCommand(CLI::App& root) {
  auto args = std::make_shared<IctTextureArgs>();
  CLI::App* cmd = root.add_subcommand(
      "ict-texture",
      "Register the ICT-FaceKit neutral mesh onto a textured scan and bake the scan's texture "
      "into ICT's UV layout (writes OBJ + MTL + PNG; see docs/texture-transfer.md)");
  cmd->add_option("--model", args->model,
                  "ICT-FaceKit model: ICT-FaceKit_FaceXModel.tar.xz or its unpacked folder")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--vertices", args->vertices,
                  "Landmark vertex table of the ICT topology "
                  "(tests/fixtures/ict-facekit/thesis25_vertices.json)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--scan", args->scan, "Textured scan mesh (OBJ, PLY, ...)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--landmarks", args->landmarks,
                  "The scan's 3D landmarks (thesis25, or ibug68 converted), in the mesh's frame")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--up", args->up, "The scan file's up axis")->capture_default_str();
  cmd->add_option("--front", args->front, "The scan file's out-of-the-face axis")
      ->capture_default_str();
  cmd->add_option("--scale", args->scale, "Scan file units to millimetres")
      ->capture_default_str()
      ->check(CLI::Range(1e-6, 1e6));
  cmd->add_option("--texture-size", args->textureSize, "Baked texture width and height (texels)")
      ->capture_default_str()
      ->check(CLI::Range(64, 8192));
  cmd->add_option("--samples", args->samples,
                  "Also write this many random ICT identities/expressions wearing the texture "
                  "(ict-SCAN-sample-K.obj + .ljson landmarks in model coordinates)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--seed-offset", args->seedOffset,
                  "Sampling stream, as an ict_textured manifest entry's seed_offset")
      ->capture_default_str();
  cmd->add_option("--contact-sheet", args->contactSheet,
                  "With --samples: a PNG of each sample from the front and turned 40 degrees");
  cmd->add_option("--tile-size", args->tileSize, "Contact sheet tile size (pixels)")
      ->capture_default_str()
      ->check(CLI::Range(64, 2048));
  cmd->add_option("--out", args->out, "Output folder (ict-SCAN.obj, .mtl, .png)")->required();
  cmd->callback([args] { runIctTexture(*args); });
}

}  // namespace clm3d::cli
