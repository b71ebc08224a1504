#include "core/synth/synth_head.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/common/error.hpp"
#include "core/synth/detail/angle_warp.hpp"
#include "core/synth/detail/head_shape.hpp"
#include "core/synth/detail/head_texture.hpp"

namespace clm3d {
namespace {

using synth::kEarChartTop;
using synth::kHeadChartBottom;
constexpr int kLandmarkCount = 25;

// Appends one triangle, oriented so that its normal points along `outward`.
void addTriangle(TexturedMesh& mesh, int a, int b, int c, const Eigen::Vector3f& outward) {
  const auto& p = mesh.positions;
  const Eigen::Vector3f n =
      (p[static_cast<std::size_t>(b)] - p[static_cast<std::size_t>(a)])
          .cross(p[static_cast<std::size_t>(c)] - p[static_cast<std::size_t>(a)]);
  if (n.squaredNorm() == 0.0F) return;  // collapsed at a pole or the ear's centre
  if (n.dot(outward) >= 0.0F) {
    mesh.triangles.emplace_back(a, b, c);
  } else {
    mesh.triangles.emplace_back(a, c, b);
  }
}

void addHead(TexturedMesh& mesh, const synth::HeadShape& head, const synth::AngleWarp& theta,
             const synth::AngleWarp& phi) {
  const int columns = theta.cells();
  const int rows = phi.cells();
  const int first = static_cast<int>(mesh.positions.size());
  const auto index = [&](int i, int j) { return first + j * (columns + 1) + i; };
  for (int j = 0; j <= rows; ++j) {
    const double t = static_cast<double>(j) / rows;
    const double elevation = phi.angle(t);
    for (int i = 0; i <= columns; ++i) {
      const double s = static_cast<double>(i) / columns;
      Eigen::Vector3f position;
      if (i == columns) {
        position = mesh.positions[static_cast<std::size_t>(index(0, j))];  // seam: same point
      } else if ((j == 0 || j == rows) && i > 0) {
        position = mesh.positions[static_cast<std::size_t>(index(0, j))];  // pole: one point
      } else {
        position = head.sample(theta.angle(s), elevation).position.cast<float>();
      }
      mesh.positions.push_back(position);
      mesh.uvs.emplace_back(static_cast<float>(s),
                            static_cast<float>(kHeadChartBottom + (1.0 - kHeadChartBottom) * t));
    }
  }
  const Eigen::Vector3f centre = head.centre().cast<float>();
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const int a = index(i, j);
      const int b = index(i + 1, j);
      const int c = index(i + 1, j + 1);
      const int d = index(i, j + 1);
      const Eigen::Vector3f outward = (mesh.positions[static_cast<std::size_t>(a)] +
                                       mesh.positions[static_cast<std::size_t>(c)]) *
                                          0.5F -
                                      centre;
      addTriangle(mesh, a, b, c, outward);
      addTriangle(mesh, a, c, d, outward);
    }
  }
}

// Both ears: the left one from EarShape, the right one its mirror image.
void addEars(TexturedMesh& mesh, const synth::EarShape& ear, const Eigen::Vector3f& headCentre) {
  constexpr int kRings = 20;
  constexpr int kSegments = 80;
  for (int side = 0; side < 2; ++side) {
    const float mirror = side == 0 ? 1.0F : -1.0F;
    for (int sheet = 0; sheet < 2; ++sheet) {
      const bool lateral = sheet == 0;
      const int first = static_cast<int>(mesh.positions.size());
      const auto index = [&](int k, int m) { return first + k * (kSegments + 1) + m; };
      for (int k = 0; k <= kRings; ++k) {
        const double rho = static_cast<double>(k) / kRings;
        for (int m = 0; m <= kSegments; ++m) {
          const double psi =
              -std::numbers::pi + 2.0 * std::numbers::pi * (m == kSegments ? 0 : m) / kSegments;
          Eigen::Vector3f p = ear.sample(rho, psi, lateral).position.cast<float>();
          if (k == 0) p = ear.sample(0.0, -std::numbers::pi, lateral).position.cast<float>();
          p.x() *= mirror;
          mesh.positions.push_back(p);
          const double u = 0.5 * static_cast<double>(m) / kSegments + (lateral ? 0.0 : 0.5);
          mesh.uvs.emplace_back(static_cast<float>(u), static_cast<float>(kEarChartTop * rho));
        }
      }
      // The lateral sheet faces away from the head, the medial one towards it; the ear's centre
      // line is the reference.
      const Eigen::Vector3f earCentre = mesh.positions[static_cast<std::size_t>(index(0, 0))];
      Eigen::Vector3f lateralDirection = earCentre - headCentre;
      lateralDirection.y() = 0.0F;
      lateralDirection.z() = 0.0F;
      const Eigen::Vector3f outward =
          lateral ? lateralDirection : Eigen::Vector3f(-lateralDirection);
      for (int k = 0; k < kRings; ++k) {
        for (int m = 0; m < kSegments; ++m) {
          addTriangle(mesh, index(k, m), index(k + 1, m), index(k + 1, m + 1), outward);
          addTriangle(mesh, index(k, m), index(k + 1, m + 1), index(k, m + 1), outward);
        }
      }
    }
  }
}

LandmarkSet computeLandmarks(const synth::HeadShape& head, const synth::EarShape& ear) {
  const synth::FaceLayout& L = head.layout();
  LandmarkSet set(kLandmarkCount, 3);
  const auto both = [&](int left, int right, double X, double Y) {
    set.set(left, head.pointAt(X, Y));
    set.set(right, head.pointAt(-X, Y));
  };
  const double corner = L.eyeSlope * L.eyeHalfWidth;
  set.set(0, head.pointAt(0.0, 0.0));
  both(1, 2, L.eyeX + L.eyeHalfWidth, corner);              // outer eye corners
  both(3, 6, L.browOuterX, L.browOuterY);                   // outer brow ends
  both(4, 5, L.browInnerX, L.browInnerY);                   // inner brow ends
  both(7, 10, L.eyeX, 0.0);                                 // eye centres
  both(8, 9, L.eyeX - L.eyeHalfWidth, -corner);             // inner eye corners
  set.set(11, head.pointAt(0.0, L.tipY));                   // nose tip
  both(12, 13, L.alarBaseX, L.alarBaseY);                   // alar bases
  both(14, 15, L.mouthHalfWidth, L.mouthY + L.cornerLift);  // mouth corners
  const synth::MouthField middle = synth::mouthField(L, 0.0, L.mouthY);
  set.set(16, head.pointAt(0.0, middle.upperTop));           // top of upper lip
  set.set(17, head.pointAt(0.0, middle.lowerBottom));        // bottom of lower lip
  both(19, 23, L.cheekPointX, L.cheekPointY);                // cheeks
  both(20, 22, L.chinPointX, L.chinPointY);                  // chin sides
  set.set(21, head.pointAt(0.0, head.chinBottomY() + 6.0));  // chin centre
  const Eigen::Vector3d lobe = ear.lobePoint();
  set.set(18, lobe);
  set.set(24, Eigen::Vector3d(-lobe.x(), lobe.y(), lobe.z()));
  return set;
}

}  // namespace

void SynthOptions::validate() const {
  if (!(faceStepDegrees >= 0.3 && faceStepDegrees <= 3.0)) {
    std::ostringstream message;
    message << "synthetic head: faceStepDegrees = " << faceStepDegrees << " is outside [0.3, 3]";
    throw InputError(message.str());
  }
  if (textureSize < 256 || textureSize > 8192) {
    throw InputError("synthetic head: textureSize = " + std::to_string(textureSize) +
                     " is outside [256, 8192]");
  }
}

SynthHead generateHead(const HeadIdentity& identity, const Expression& expression,
                       const SynthOptions& options) {
  options.validate();
  const synth::HeadShape head(identity, expression);
  const synth::EarShape ear(head);
  const double coarse = std::max(2.5, 3.0 * options.faceStepDegrees);
  const synth::AngleWarp theta(-180.0, 180.0, -72.0, 72.0, options.faceStepDegrees, coarse);
  const synth::AngleWarp phi(-90.0, 90.0, -62.0, 56.0, options.faceStepDegrees, coarse);

  SynthHead out;
  out.identity = identity;
  out.expression = expression;
  out.mesh.source = "synthetic head";
  addHead(out.mesh, head, theta, phi);
  addEars(out.mesh, ear, head.centre().cast<float>());
  out.mesh.texture = synth::paintHeadTexture(head, ear, theta, phi, options.textureSize);

  LandmarkSet landmarks = computeLandmarks(head, ear);
  const Eigen::Vector3d origin = landmarks.point(0);
  for (int i = 0; i < landmarks.size(); ++i)
    landmarks.set(i, Eigen::Vector3d(landmarks.point(i) - origin));
  out.landmarks = landmarks;
  out.mesh.translate(-origin.cast<float>());
  out.mesh.computeNormals();
  return out;
}

SynthHead generateHead(std::uint64_t seed, const Expression& expression,
                       const SynthOptions& options) {
  return generateHead(randomIdentity(seed), expression, options);
}

}  // namespace clm3d
