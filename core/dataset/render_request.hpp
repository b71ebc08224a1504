// What `clm3d render` is asked for, described once as an option table (the CLI builds the
// command's options from it), and its run: a textured mesh put into the model frame (core/dataset/
// model_frame: turned about landmark 1, levelled on the eyes with --orient auto), framed, rendered
// offscreen at a head pose, with its landmarks projected, depth map and overlay written on demand.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/render/offscreen_renderer.hpp"

namespace clm3d {

struct RenderRequest {
  std::filesystem::path mesh, landmarks;
  double yaw = 0.0, pitch = 0.0, roll = 0.0;  // degrees
  int size = 256;
  double fov = 30.0;
  std::vector<double> lightDir{0.3, 0.4, 1.0};
  double ambient = Lighting{}.ambient;
  double diffuse = Lighting{}.diffuse;
  double fill = 0.85;
  int supersample = 2;
  std::string up = "+y", front = "+z";
  std::string orient = "auto";
  bool allowUntextured = false;
  bool hiddenMissing = false;
  std::filesystem::path out, outLandmarks, outDepth, overlay;
};

// Every option of `clm3d render`, in its help's order.
const std::vector<Option<RenderRequest>>& renderOptions();

// Renders and writes the files the request names; returns what the command prints (landmarks
// projected and hidden, whether the head was levelled, the pose and distance). UsageError for
// options that do not go together, InputError naming a file that cannot be read.
std::string runRender(const RenderRequest& request);

}  // namespace clm3d
