#include "core/registration/texture_bake.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"
#include "core/registration/surface_index.hpp"

namespace clm3d {
namespace {

// Bilinear BGR of `texture` at UV (u, v), v up; clamped at the border.
Eigen::Vector3f sampleBilinear(const cv::Mat& texture, float u, float v) {
  const float x = std::clamp(u * static_cast<float>(texture.cols) - 0.5F, 0.0F,
                             static_cast<float>(texture.cols - 1));
  const float y = std::clamp((1.0F - v) * static_cast<float>(texture.rows) - 0.5F, 0.0F,
                             static_cast<float>(texture.rows - 1));
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, texture.cols - 1), y1 = std::min(y0 + 1, texture.rows - 1);
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  Eigen::Vector3f out = Eigen::Vector3f::Zero();
  const auto add = [&](int xx, int yy, float weight) {
    const auto& c = texture.at<cv::Vec3b>(yy, xx);
    out += weight * Eigen::Vector3f(c[0], c[1], c[2]);
  };
  add(x0, y0, (1 - fx) * (1 - fy));
  add(x1, y0, fx * (1 - fy));
  add(x0, y1, (1 - fx) * fy);
  add(x1, y1, fx * fy);
  return out;
}

}  // namespace

void fillUnknownTexels(cv::Mat& image, const cv::Mat& known) {
  // Pull: premultiplied colour and weight averaged down to 1 texel.
  std::vector<cv::Mat> colour, weight;
  cv::Mat c, wgt;
  known.convertTo(wgt, CV_32F, 1.0 / 255.0);
  cv::threshold(wgt, wgt, 0.0, 1.0, cv::THRESH_BINARY);
  image.convertTo(c, CV_32FC3);
  cv::Mat w3;
  cv::merge(std::vector<cv::Mat>{wgt, wgt, wgt}, w3);
  c = c.mul(w3);
  if (cv::countNonZero(wgt) == 0) throw InputError("texture fill: no texel has a known colour");
  colour.push_back(c);
  weight.push_back(wgt);
  while (colour.back().cols > 1 || colour.back().rows > 1) {
    const cv::Size half((colour.back().cols + 1) / 2, (colour.back().rows + 1) / 2);
    cv::Mat cs, ws;
    cv::resize(colour.back(), cs, half, 0, 0, cv::INTER_AREA);
    cv::resize(weight.back(), ws, half, 0, 0, cv::INTER_AREA);
    colour.push_back(cs);
    weight.push_back(ws);
  }
  // Normalise each level where it has weight.
  std::vector<cv::Mat> mean(colour.size());
  for (std::size_t l = 0; l < colour.size(); ++l) {
    mean[l] = cv::Mat(colour[l].size(), CV_32FC3, cv::Scalar::all(0));
    for (int y = 0; y < colour[l].rows; ++y) {
      for (int x = 0; x < colour[l].cols; ++x) {
        const float wv = weight[l].at<float>(y, x);
        if (wv > 1e-6F) mean[l].at<cv::Vec3f>(y, x) = colour[l].at<cv::Vec3f>(y, x) / wv;
      }
    }
  }
  // Push: from coarse to fine, a texel blends its own mean with the coarser estimate by how much
  // of it is known.
  for (std::size_t l = colour.size() - 1; l-- > 0;) {
    cv::Mat up;
    cv::resize(mean[l + 1], up, mean[l].size(), 0, 0, cv::INTER_LINEAR);
    for (int y = 0; y < mean[l].rows; ++y) {
      for (int x = 0; x < mean[l].cols; ++x) {
        const float wv = std::min(1.0F, weight[l].at<float>(y, x));
        mean[l].at<cv::Vec3f>(y, x) =
            wv * mean[l].at<cv::Vec3f>(y, x) + (1.0F - wv) * up.at<cv::Vec3f>(y, x);
      }
    }
  }
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      if (known.at<unsigned char>(y, x) != 0) continue;
      const cv::Vec3f v = mean[0].at<cv::Vec3f>(y, x);
      image.at<cv::Vec3b>(y, x) =
          cv::Vec3b(cv::saturate_cast<unsigned char>(v[0]), cv::saturate_cast<unsigned char>(v[1]),
                    cv::saturate_cast<unsigned char>(v[2]));
    }
  }
}

TextureBakeResult bakeTexture(const TexturedMesh& templ,
                              const std::vector<Eigen::Vector3f>& positions,
                              const TexturedMesh& target, const TextureBakeOptions& options,
                              const ProgressCallback& progress, const CancelToken* cancel) {
  if (templ.triangles.empty() || templ.uvs.size() != templ.positions.size()) {
    throw InputError("texture bake: the template mesh has no triangles or no UV per vertex");
  }
  if (positions.size() != templ.positions.size()) {
    throw InputError("texture bake: " + std::to_string(positions.size()) +
                     " registered positions for a template of " +
                     std::to_string(templ.positions.size()) + " vertices");
  }
  if (target.triangles.empty() || target.texture.empty() || target.texture.type() != CV_8UC3 ||
      target.uvs.size() != target.positions.size()) {
    throw InputError("texture bake: the target mesh " +
                     (target.source.empty() ? std::string() : "'" + target.source + "' ") +
                     "has no triangles, no texture or no UV per vertex");
  }
  if (options.width < 8 || options.height < 8 || options.width > 8192 || options.height > 8192) {
    throw InputError("texture bake: the texture size must be in [8, 8192]");
  }
  if (!options.bakeTriangles.empty() && options.bakeTriangles.size() != templ.triangles.size()) {
    throw InputError("texture bake: the triangle mask does not match the template's triangles");
  }
  for (const auto& t : templ.triangles) {
    if (t.minCoeff() < 0 || static_cast<std::size_t>(t.maxCoeff()) >= templ.positions.size()) {
      throw InputError("texture bake: a template triangle has a vertex index out of range");
    }
  }

  // Smooth template normals from the registered positions.
  std::vector<Eigen::Vector3f> normals(positions.size(), Eigen::Vector3f::Zero());
  for (const auto& t : templ.triangles) {
    const Eigen::Vector3f f =
        (positions[static_cast<std::size_t>(t[1])] - positions[static_cast<std::size_t>(t[0])])
            .cross(positions[static_cast<std::size_t>(t[2])] -
                   positions[static_cast<std::size_t>(t[0])]);
    for (int k = 0; k < 3; ++k) normals[static_cast<std::size_t>(t[k])] += f;
  }

  TextureBakeResult result;
  result.texture = cv::Mat(options.height, options.width, CV_8UC3, cv::Scalar::all(0));
  result.coverage = cv::Mat(options.height, options.width, CV_8U, cv::Scalar::all(0));
  const SurfaceIndex index(target);
  const float w = static_cast<float>(options.width), h = static_cast<float>(options.height);
  std::size_t inside = 0, baked = 0;
  for (std::size_t ti = 0; ti < templ.triangles.size(); ++ti) {
    if (cancel && ti % 1024 == 0) cancel->throwIfCancelled();
    if (progress && ti % 4096 == 0) {
      progress(static_cast<double>(ti) / static_cast<double>(templ.triangles.size()),
               "baking the texture");
    }
    const auto& t = templ.triangles[ti];
    const bool bake = options.bakeTriangles.empty() || options.bakeTriangles[ti];
    // Texel coordinates (x right, y down) of the corners.
    Eigen::Vector2f q[3];
    for (int k = 0; k < 3; ++k) {
      const auto& uv = templ.uvs[static_cast<std::size_t>(t[k])];
      q[k] = {uv.x() * w, (1.0F - uv.y()) * h};
    }
    const float area =
        (q[1] - q[0]).x() * (q[2] - q[0]).y() - (q[1] - q[0]).y() * (q[2] - q[0]).x();
    if (std::abs(area) < 1e-12F) continue;
    const int x0 =
        std::max(0, static_cast<int>(std::floor(std::min({q[0].x(), q[1].x(), q[2].x()}))));
    const int x1 = std::min(options.width - 1,
                            static_cast<int>(std::ceil(std::max({q[0].x(), q[1].x(), q[2].x()}))));
    const int y0 =
        std::max(0, static_cast<int>(std::floor(std::min({q[0].y(), q[1].y(), q[2].y()}))));
    const int y1 = std::min(options.height - 1,
                            static_cast<int>(std::ceil(std::max({q[0].y(), q[1].y(), q[2].y()}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2f p(static_cast<float>(x) + 0.5F, static_cast<float>(y) + 0.5F);
        const auto edge = [&](const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
          return ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / area;
        };
        const float b0 = edge(q[1], q[2]), b1 = edge(q[2], q[0]), b2 = edge(q[0], q[1]);
        constexpr float kSlack = -1e-4F;
        if (b0 < kSlack || b1 < kSlack || b2 < kSlack) continue;
        auto& cover = result.coverage.at<unsigned char>(y, x);
        if (cover == 0) ++inside;
        if (cover == 255) continue;
        cover = 128;
        if (!bake) continue;
        const Eigen::Vector3f point = b0 * positions[static_cast<std::size_t>(t[0])] +
                                      b1 * positions[static_cast<std::size_t>(t[1])] +
                                      b2 * positions[static_cast<std::size_t>(t[2])];
        const Eigen::Vector3f normal = (b0 * normals[static_cast<std::size_t>(t[0])] +
                                        b1 * normals[static_cast<std::size_t>(t[1])] +
                                        b2 * normals[static_cast<std::size_t>(t[2])])
                                           .normalized();
        const auto hit = index.nearest(point.cast<double>(), options.maxDistance);
        if (!hit || hit->normal.dot(normal.cast<double>()) < options.minNormalDot) continue;
        const auto& st = target.triangles[static_cast<std::size_t>(hit->triangle)];
        const Eigen::Vector2f uv =
            static_cast<float>(hit->barycentric[0]) * target.uvs[static_cast<std::size_t>(st[0])] +
            static_cast<float>(hit->barycentric[1]) * target.uvs[static_cast<std::size_t>(st[1])] +
            static_cast<float>(hit->barycentric[2]) * target.uvs[static_cast<std::size_t>(st[2])];
        const Eigen::Vector3f colour = sampleBilinear(target.texture, uv.x(), uv.y());
        result.texture.at<cv::Vec3b>(y, x) = cv::Vec3b(cv::saturate_cast<unsigned char>(colour[0]),
                                                       cv::saturate_cast<unsigned char>(colour[1]),
                                                       cv::saturate_cast<unsigned char>(colour[2]));
        cover = 255;
        ++baked;
      }
    }
  }
  result.bakedFraction =
      inside > 0 ? static_cast<double>(baked) / static_cast<double>(inside) : 0.0;
  if (baked == 0) {
    throw InputError("texture bake: no texel found the target surface within " +
                     std::to_string(options.maxDistance) + " mm; is the registration right?");
  }
  cv::Mat known;
  cv::compare(result.coverage, 255, known, cv::CMP_EQ);
  fillUnknownTexels(result.texture, known);
  if (progress) progress(1.0, "baking the texture");
  return result;
}

}  // namespace clm3d
