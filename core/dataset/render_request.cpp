#include "core/dataset/render_request.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <optional>
#include <sstream>

#include "core/common/error.hpp"
#include "core/dataset/axis_name.hpp"
#include "core/dataset/detail/model_frame.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/mesh/mesh_transform.hpp"
#include "core/render/framing.hpp"
#include "core/render/projected_landmarks.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/viz/image_file.hpp"
#include "core/viz/landmark_overlay.hpp"

namespace clm3d {
namespace render_request_detail {

namespace fs = std::filesystem;
using R = RenderRequest;

std::vector<Option<R>> makeOptions() {
  const auto degrees = [](const char* name, const char* help, double R::*field) {
    return realOption<R>(commandOption(name, help, -1e6, 1e6), field);
  };
  const auto path = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(commandOption(name, help), field);
  };
  return {
      textOption<R>(requiredOption("mesh", "Textured mesh: OBJ (+MTL, image), PLY, glTF/GLB"),
                    &R::mesh),
      path("landmarks",
           "3D landmarks of the mesh (.pts/.ljson/.csv, 25 thesis or 68 iBUG points); the head "
           "then turns about landmark 1",
           &R::landmarks),
      degrees("yaw", "Yaw in degrees (positive: nose towards the subject's left)", &R::yaw),
      degrees("pitch", "Pitch in degrees (positive: nose down)", &R::pitch),
      degrees("roll", "Roll in degrees (positive: counter-clockwise)", &R::roll),
      integerOption<R>(commandOption("size", "Image width and height in pixels", 8, 8192),
                       &R::size),
      realOption<R>(commandOption("fov", "Vertical field of view in degrees", 1.0, 150.0), &R::fov),
      realOption<R>(
          commandOption("fill", "Share of the image the head's larger side spans", 0.05, 1.0),
          &R::fill),
      realListOption<R>(
          commandOption("light-dir", "Direction towards the light, eye space X,Y,Z", -100, 100),
          &R::lightDir),
      realOption<R>(commandOption("ambient", "Ambient light intensity", 0.0, 2.0), &R::ambient),
      realOption<R>(commandOption("diffuse", "Directional light intensity", 0.0, 2.0), &R::diffuse),
      integerOption<R>(
          commandOption("supersample",
                        "Render at N times the size and average down (anti-aliasing)", 1, 4),
          &R::supersample),
      textOption<R>(commandOption("up", "The mesh file's up axis (+x, -y, +z ...)"), &R::up,
                    checkAxisName),
      textOption<R>(commandOption("front", "The mesh file's axis out of the face"), &R::front,
                    checkAxisName),
      textChoiceOption<R>(commandOption("orient",
                                        "auto: level the head on the eye centres of --landmarks "
                                        "(yaw 0 = frontal), else use the file's axes; file: "
                                        "always the file's axes (--up, --front)"),
                          &R::orient, {"auto", "file"}),
      flagOption<R>(commandOption("allow-untextured",
                                  "Render a mesh without texture in mid-grey instead of failing"),
                    &R::allowUntextured),
      textOption<R>(requiredOption("out", "Output image (.png keeps the transparent background)"),
                    &R::out),
      path("out-landmarks",
           "Projected 2D landmarks (.pts/.ljson/.csv), in the landmark file's scheme",
           &R::outLandmarks),
      flagOption<R>(commandOption("hidden-missing",
                                  "Write self-occluded landmarks as missing in --out-landmarks"),
                    &R::hiddenMissing),
      path("out-depth", "Depth map: 32-bit float TIFF, eye distance in mm, 0 on the background",
           &R::outDepth),
      path("overlay",
           "Image of the render with the landmarks (numbered 1..N; filled = visible, hollow = "
           "hidden)",
           &R::overlay),
  };
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

}  // namespace render_request_detail

const std::vector<Option<RenderRequest>>& renderOptions() {
  static const std::vector<Option<RenderRequest>> table = render_request_detail::makeOptions();
  return table;
}

std::string runRender(const RenderRequest& args) {
  if (args.landmarks.empty() && (!args.outLandmarks.empty() || !args.overlay.empty())) {
    throw UsageError("--out-landmarks/--overlay", "need --landmarks");
  }
  if (args.lightDir.size() != 3) throw UsageError("--light-dir", "expected 3 values X,Y,Z");
  MeshLoadOptions loadOptions;
  loadOptions.requireTexture = !args.allowUntextured;
  TexturedMesh mesh = loadTexturedMesh(args.mesh, loadOptions);

  std::optional<render_request_detail::Landmarks> landmarks;
  if (!args.landmarks.empty())
    landmarks = render_request_detail::readModelLandmarks(args.landmarks);

  // To the model convention (+x subject's left, +y up, +z out of the face) as core puts any mesh
  // there: turning about landmark 1 when known, else about the centre of the bounding box;
  // levelled on the eyes with --orient auto when the landmarks give them.
  const auto [up, front] = fileAxes(args.up, args.front);
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

  std::ostringstream out;
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
    out << "landmarks: " << projected.points.presentCount() << " projected, "
        << projected.hidden.size() << " hidden at this pose\n";
  }
  if (level) out << "orientation: levelled on the eyes of the landmarks\n";
  out << "rendered " << args.mesh.filename().string() << " (" << mesh.vertexCount()
      << " vertices) at pitch " << args.pitch << ", yaw " << args.yaw << ", roll " << args.roll
      << " degrees, " << -pose.translation.z() << " mm away, to " << args.out.string() << '\n';
  return out.str();
}

}  // namespace clm3d
