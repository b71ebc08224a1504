#include "core/render/offscreen_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/geometry/projection.hpp"
#include "core/render/detail/render_module.hpp"

namespace clm3d {
namespace {

constexpr std::size_t kErrorSize = 1024;

// Column-major copy of an Eigen matrix (Eigen's default storage is already column-major).
void copyMatrix(const Eigen::Matrix4d& matrix, double* out) {
  Eigen::Map<Eigen::Matrix4d> target(out);
  target = matrix;
}

cv::Mat toBgr8(const cv::Mat& texture) {
  cv::Mat bgr;
  if (texture.type() == CV_8UC3) {
    bgr = texture;
  } else if (texture.type() == CV_8UC4) {
    cv::cvtColor(texture, bgr, cv::COLOR_BGRA2BGR);
  } else if (texture.type() == CV_8UC1) {
    cv::cvtColor(texture, bgr, cv::COLOR_GRAY2BGR);
  } else {
    throw Error("renderer: unsupported texture type " + std::to_string(texture.type()));
  }
  return bgr.isContinuous() ? bgr : bgr.clone();
}

}  // namespace

struct OffscreenRenderer::Impl {
  const clm3d_render_api* api = nullptr;
  clm3d_render_context* context = nullptr;
  RenderOptions options;
  std::vector<unsigned char> rgba;
  std::vector<float> depth;

  ~Impl() {
    if (context != nullptr) api->destroy(context);
  }
};

OffscreenRenderer::OffscreenRenderer(const TexturedMesh& mesh, const RenderOptions& options)
    : impl_(std::make_unique<Impl>()) {
  mesh.validate();
  if (options.supersample < 1 || options.supersample > 8) {
    throw Error("renderer: supersample must be in 1..8");
  }
  impl_->options = options;
  impl_->api = &renderModule();

  std::vector<float> positions;
  std::vector<float> normals;
  std::vector<float> uvs;
  std::vector<std::uint32_t> indices;
  positions.reserve(mesh.vertexCount() * 3);
  uvs.reserve(mesh.vertexCount() * 2);
  for (const auto& p : mesh.positions) positions.insert(positions.end(), {p.x(), p.y(), p.z()});
  for (const auto& t : mesh.uvs) uvs.insert(uvs.end(), {t.x(), t.y()});
  if (mesh.normals.size() == mesh.positions.size()) {
    for (const auto& n : mesh.normals) normals.insert(normals.end(), {n.x(), n.y(), n.z()});
  } else {
    TexturedMesh withNormals;
    withNormals.positions = mesh.positions;
    withNormals.triangles = mesh.triangles;
    withNormals.computeNormals();
    for (const auto& n : withNormals.normals) normals.insert(normals.end(), {n.x(), n.y(), n.z()});
  }
  indices.reserve(mesh.triangleCount() * 3);
  for (const auto& t : mesh.triangles) {
    indices.insert(indices.end(),
                   {static_cast<std::uint32_t>(t.x()), static_cast<std::uint32_t>(t.y()),
                    static_cast<std::uint32_t>(t.z())});
  }
  cv::Mat texture = toBgr8(mesh.texture);
  // Keep within what every GL implementation accepts.
  constexpr int kMaxTexture = 8192;
  if (texture.cols > kMaxTexture || texture.rows > kMaxTexture) {
    const double factor = static_cast<double>(kMaxTexture) / std::max(texture.cols, texture.rows);
    cv::resize(texture, texture, cv::Size(), factor, factor, cv::INTER_AREA);
  }

  clm3d_render_mesh data{};
  data.positions = positions.data();
  data.normals = normals.data();
  data.uvs = uvs.data();
  data.indices = indices.data();
  data.vertex_count = static_cast<std::uint32_t>(mesh.vertexCount());
  data.triangle_count = static_cast<std::uint32_t>(mesh.triangleCount());
  data.texture_bgr = texture.data;
  data.texture_width = texture.cols;
  data.texture_height = texture.rows;
  char error[kErrorSize] = {};
  impl_->context = impl_->api->create(&data, error, sizeof error);
  if (impl_->context == nullptr) {
    throw Error("renderer: cannot set up " + mesh.source + ": " + error);
  }
}

OffscreenRenderer::~OffscreenRenderer() = default;
OffscreenRenderer::OffscreenRenderer(OffscreenRenderer&&) noexcept = default;
OffscreenRenderer& OffscreenRenderer::operator=(OffscreenRenderer&&) noexcept = default;

RenderResult OffscreenRenderer::render(const Pose& pose, const Camera& camera,
                                       const Lighting& lighting) {
  if (camera.width <= 0 || camera.height <= 0) throw Error("renderer: image size must be positive");
  if (!(camera.near > 0.0 && camera.far > camera.near))
    throw Error("renderer: need 0 < near < far");
  const int k = impl_->options.supersample;
  const int width = camera.width * k;
  const int height = camera.height * k;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  impl_->rgba.resize(pixels * 4);
  impl_->depth.resize(pixels);

  clm3d_render_frame frame{};
  frame.width = width;
  frame.height = height;
  copyMatrix(pose.viewMatrix(), frame.modelview);
  copyMatrix(camera.projectionMatrix(), frame.projection);
  for (int i = 0; i < 3; ++i) frame.light_direction[i] = static_cast<float>(lighting.direction[i]);
  frame.ambient = static_cast<float>(lighting.ambient);
  frame.diffuse = static_cast<float>(lighting.diffuse);
  frame.out_rgba = impl_->rgba.data();
  frame.out_depth = impl_->depth.data();
  char error[kErrorSize] = {};
  if (impl_->api->draw(impl_->context, &frame, error, sizeof error) != 0) {
    throw Error(std::string("renderer: ") + error);
  }

  // OpenGL rows start at the bottom; flip while converting. Window depth d in [0, 1] becomes
  // the eye distance 2fn / ((f + n) - (2d - 1)(f - n)).
  cv::Mat bgra(height, width, CV_8UC4);
  cv::Mat depth(height, width, CV_32F);
  const double n = camera.near;
  const double f = camera.far;
  const float background = std::numeric_limits<float>::infinity();
  for (int row = 0; row < height; ++row) {
    const std::size_t source = static_cast<std::size_t>(height - 1 - row) * width;
    const unsigned char* in = impl_->rgba.data() + source * 4;
    const float* d = impl_->depth.data() + source;
    auto* out = bgra.ptr<cv::Vec4b>(row);
    auto* z = depth.ptr<float>(row);
    for (int col = 0; col < width; ++col) {
      out[col] = {in[4 * col + 2], in[4 * col + 1], in[4 * col], in[4 * col + 3]};
      if (d[col] >= 1.0F) {
        z[col] = background;
      } else {
        const double ndc = 2.0 * d[col] - 1.0;
        z[col] = static_cast<float>(2.0 * f * n / ((f + n) - ndc * (f - n)));
      }
    }
  }

  RenderResult result;
  result.pose = pose;
  result.camera = camera;
  if (k == 1) {
    result.bgra = bgra;
    result.depth = depth;
    return result;
  }
  // Average premultiplied colour over each k x k block (the background is transparent black),
  // then divide by coverage; depth keeps the nearest surface of the block.
  cv::Mat average;
  bgra.convertTo(average, CV_32FC4);
  cv::resize(average, average, cv::Size(camera.width, camera.height), 0, 0, cv::INTER_AREA);
  result.bgra.create(camera.height, camera.width, CV_8UC4);
  result.depth.create(camera.height, camera.width, CV_32F);
  for (int row = 0; row < camera.height; ++row) {
    const auto* a = average.ptr<cv::Vec4f>(row);
    auto* out = result.bgra.ptr<cv::Vec4b>(row);
    auto* z = result.depth.ptr<float>(row);
    for (int col = 0; col < camera.width; ++col) {
      const float alpha = a[col][3];
      const float scale = alpha > 0.0F ? 255.0F / alpha : 0.0F;
      for (int c = 0; c < 3; ++c) out[col][c] = cv::saturate_cast<uchar>(a[col][c] * scale);
      out[col][3] = cv::saturate_cast<uchar>(alpha);
      float nearest = background;
      for (int dy = 0; dy < k; ++dy) {
        const float* source = depth.ptr<float>(row * k + dy) + col * k;
        for (int dx = 0; dx < k; ++dx) nearest = std::min(nearest, source[dx]);
      }
      z[col] = nearest;
    }
  }
  return result;
}

bool RenderResult::isVisible(const Eigen::Vector3d& modelPoint, double toleranceMm) const {
  const Eigen::Vector3d eye = pose.toEye(modelPoint);
  if (eye.z() >= 0.0 || depth.empty()) return false;
  const Eigen::Vector2d pixel = projectPoint(modelPoint, pose, camera);
  const double pointDepth = -eye.z();
  const int x0 = static_cast<int>(std::floor(pixel.x()));
  const int y0 = static_cast<int>(std::floor(pixel.y()));
  for (int y = y0; y <= y0 + 1; ++y) {
    for (int x = x0; x <= x0 + 1; ++x) {
      if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows) continue;
      if (pointDepth <= static_cast<double>(depth.at<float>(y, x)) + toleranceMm) return true;
    }
  }
  return false;
}

cv::Mat RenderResult::depthZeroBackground() const {
  cv::Mat out = depth.clone();
  out.setTo(0.0F, out == std::numeric_limits<float>::infinity());
  return out;
}

}  // namespace clm3d
