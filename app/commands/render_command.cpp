// clm3d render: draws a textured mesh offscreen at a given head pose, framed automatically, and
// writes the image (transparent background), optionally the projected landmarks, the depth map
// and an overlay of the landmarks. All work is done by core (mesh, render, scheme, geometry,
// dataset/model_frame, render/projected_landmarks).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/error.hpp"
#include "core/dataset/axis_name.hpp"
#include "core/dataset/model_frame.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/mesh/mesh_transform.hpp"
#include "core/render/framing.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/render/projected_landmarks.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/viz/image_file.hpp"
#include "core/viz/landmark_overlay.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct RenderArgs {
  fs::path mesh;
  fs::path landmarks;
  double yaw = 0.0;
  double pitch = 0.0;
  double roll = 0.0;
  int size = 256;
  double fov = 30.0;
  std::vector<double> lightDir{0.3, 0.4, 1.0};
  double ambient = Lighting{}.ambient;
  double diffuse = Lighting{}.diffuse;
  double fill = 0.85;
  int supersample = 2;
  std::string up = "+y";
  std::string front = "+z";
  std::string orient = "auto";
  bool allowUntextured = false;
  bool hiddenMissing = false;
  fs::path out;
  fs::path outLandmarks;
  fs::path outDepth;
  fs::path overlay;
};

// "+y", "-z", "x" -> unit vector in the file's coordinates (core's axis names).
Eigen::Vector3d parseAxis(const std::string& text, const std::string& option) {
  if (const auto axis = axisFromName(text)) return *axis;
  throw CLI::ValidationError(option, "expected an axis such as +y, -z or x, got '" + text + "'");
}

struct Landmarks {
  LandmarkSet points;
  const Scheme* scheme = nullptr;
};

Landmarks readModelLandmarks(const fs::path& path) {
  Landmarks result;
  result.points = readLandmarks(path);
  if (result.points.dims() != 3) throwInputError(path, "expected 3D landmarks (x, y, z)");
  if (result.points.size() == Scheme::thesis25().size()) {
    result.scheme = &Scheme::thesis25();
  } else if (result.points.size() == Scheme::ibug68().size()) {
    result.scheme = &Scheme::ibug68();
  } else {
    throwInputError(path, "has " + std::to_string(result.points.size()) +
                              " points; expected 25 (thesis25) or 68 (ibug68)");
  }
  return result;
}

void runRender(const RenderArgs& args) {
  if (args.landmarks.empty() && (!args.outLandmarks.empty() || !args.overlay.empty())) {
    throw CLI::ValidationError("--out-landmarks/--overlay", "need --landmarks");
  }
  MeshLoadOptions loadOptions;
  loadOptions.requireTexture = !args.allowUntextured;
  TexturedMesh mesh = loadTexturedMesh(args.mesh, loadOptions);

  std::optional<Landmarks> landmarks;
  if (!args.landmarks.empty()) landmarks = readModelLandmarks(args.landmarks);

  // To the model convention (+x subject's left, +y up, +z out of the face) as core puts any mesh
  // there (core/dataset/model_frame): turning about landmark 1 when known, else about the centre
  // of the bounding box; levelled on the eyes with --orient auto when the landmarks give them.
  const Eigen::Vector3d up = parseAxis(args.up, "--up");
  const Eigen::Vector3d front = parseAxis(args.front, "--front");
  if (up.dot(front) != 0.0) throw CLI::ValidationError("--up/--front", "the axes must differ");
  bool level = false;
  const ModelFrame frame = viewingFrame(
      landmarks ? &landmarks->points : nullptr, landmarks ? landmarks->scheme : nullptr, up, front,
      args.orient == "auto", Eigen::Vector3d(mesh.bounds().center().cast<double>()), level);
  transformMesh(mesh, frame.rotation, -(frame.rotation * frame.origin));
  if (landmarks) landmarks->points = applyFrame(frame, landmarks->points);

  Camera camera = Camera::fromVerticalFov(args.size, args.size, args.fov);
  Pose pose = Pose::fromDegrees(args.pitch, args.yaw, args.roll);
  pose.translation = frameMesh(mesh, pose, camera, args.fill);
  const double radius = meshRadius(mesh);
  camera = Camera::fromVerticalFov(args.size, args.size, args.fov,
                                   std::max(0.1, 0.5 * (-pose.translation.z() - radius)),
                                   -pose.translation.z() + 2.0 * radius + 10.0);

  Lighting lighting;
  lighting.direction = Eigen::Vector3d(args.lightDir[0], args.lightDir[1], args.lightDir[2]);
  lighting.ambient = args.ambient;
  lighting.diffuse = args.diffuse;
  OffscreenRenderer renderer(mesh, RenderOptions{args.supersample});
  const RenderResult result = renderer.render(pose, camera, lighting);
  writeImage(args.out, result.bgra);

  if (!args.outDepth.empty()) writeImage(args.outDepth, result.depthZeroBackground());

  if (landmarks) {
    const ProjectedLandmarks projected = projectLandmarks(landmarks->points, result, pose, camera);
    if (!args.outLandmarks.empty()) {
      writeLandmarks(args.outLandmarks,
                     args.hiddenMissing ? visiblePointsOnly(projected) : projected.points,
                     *landmarks->scheme);
    }
    if (!args.overlay.empty()) {
      cv::Mat overlay = result.bgra.clone();
      drawLandmarks(overlay, projected.points, projected.visible, *landmarks->scheme);
      writeImage(args.overlay, overlay);
    }
    std::cout << "landmarks: " << projected.points.presentCount() << " projected, "
              << projected.hidden.size() << " hidden at this pose\n";
  }
  if (level) std::cout << "orientation: levelled on the eyes of the landmarks\n";
  std::cout << "rendered " << args.mesh.filename().string() << " (" << mesh.vertexCount()
            << " vertices) at pitch " << args.pitch << ", yaw " << args.yaw << ", roll "
            << args.roll << " degrees, " << -pose.translation.z() << " mm away, to "
            << args.out.string() << '\n';
}

}  // namespace

void addRenderCommand(CLI::App& root) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* command = root.add_subcommand(
      "render",
      "Render a textured mesh offscreen at a head pose (transparent PNG), with optional "
      "projected landmarks, depth map and landmark overlay");
  command->add_option("--mesh", args->mesh, "Textured mesh: OBJ (+MTL, image), PLY, glTF/GLB")
      ->required();
  command->add_option("--landmarks", args->landmarks,
                      "3D landmarks of the mesh (.pts/.ljson/.csv, 25 thesis or 68 iBUG points); "
                      "the head then turns about landmark 1");
  command
      ->add_option("--yaw", args->yaw, "Yaw in degrees (positive: nose towards the subject's left)")
      ->default_val(0.0);
  command->add_option("--pitch", args->pitch, "Pitch in degrees (positive: nose down)")
      ->default_val(0.0);
  command->add_option("--roll", args->roll, "Roll in degrees (positive: counter-clockwise)")
      ->default_val(0.0);
  command->add_option("--size", args->size, "Image width and height in pixels")
      ->default_val(256)
      ->check(CLI::Range(8, 8192));
  command->add_option("--fov", args->fov, "Vertical field of view in degrees")
      ->default_val(30.0)
      ->check(CLI::Range(1.0, 150.0));
  command->add_option("--fill", args->fill, "Share of the image the head's larger side spans")
      ->default_val(0.85)
      ->check(CLI::Range(0.05, 1.0));
  command->add_option("--light-dir", args->lightDir, "Direction towards the light, eye space X,Y,Z")
      ->expected(3)
      ->delimiter(',')
      ->default_str("0.3,0.4,1");
  command->add_option("--ambient", args->ambient, "Ambient light intensity")
      ->default_val(Lighting{}.ambient)
      ->check(CLI::Range(0.0, 2.0));
  command->add_option("--diffuse", args->diffuse, "Directional light intensity")
      ->default_val(Lighting{}.diffuse)
      ->check(CLI::Range(0.0, 2.0));
  command
      ->add_option("--supersample", args->supersample,
                   "Render at N times the size and average down (anti-aliasing)")
      ->default_val(2)
      ->check(CLI::Range(1, 4));
  command->add_option("--up", args->up, "The mesh file's up axis (+x, -y, +z ...)")
      ->default_val("+y");
  command->add_option("--front", args->front, "The mesh file's axis out of the face")
      ->default_val("+z");
  command
      ->add_option("--orient", args->orient,
                   "auto: level the head on the eye centres of --landmarks (yaw 0 = frontal), "
                   "else use the file's axes; file: always the file's axes (--up, --front)")
      ->default_val("auto")
      ->check(CLI::IsMember({"auto", "file"}));
  command->add_flag("--allow-untextured", args->allowUntextured,
                    "Render a mesh without texture in mid-grey instead of failing");
  command->add_option("--out", args->out, "Output image (.png keeps the transparent background)")
      ->required();
  command->add_option("--out-landmarks", args->outLandmarks,
                      "Projected 2D landmarks (.pts/.ljson/.csv), in the landmark file's scheme");
  command->add_flag("--hidden-missing", args->hiddenMissing,
                    "Write self-occluded landmarks as missing in --out-landmarks");
  command->add_option("--out-depth", args->outDepth,
                      "Depth map: 32-bit float TIFF, eye distance in mm, 0 on the background");
  command->add_option("--overlay", args->overlay,
                      "Image of the render with the landmarks (numbered 1..N; filled = visible, "
                      "hollow = hidden)");
  command->callback([args] { runRender(*args); });
}

}  // namespace clm3d::cli
