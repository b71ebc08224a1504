#include "core/synth/detail/head_texture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/common/parallel_for.hpp"
#include "core/synth/detail/synth_math.hpp"
#include "core/synth/detail/value_noise.hpp"

namespace clm3d::synth {
namespace {

using Rgb = Eigen::Vector3d;

Rgb rgb(const ColourRgb& c) {
  return {c.r, c.g, c.b};
}
Rgb mixRgb(const Rgb& a, const Rgb& b, double t) {
  return a + (b - a) * std::clamp(t, 0.0, 1.0);
}

class Painter {
 public:
  Painter(const HeadShape& head, const EarShape& ear)
      : ear_(ear),
        id_(head.identity()),
        L_(head.layout()),
        noise_(head.identity().detailSeed),
        skin_(rgb(head.identity().skinTone)),
        hair_(rgb(head.identity().hairColour)),
        iris_(rgb(head.identity().irisColour)) {}

  Rgb head(const SurfaceSample& s) const;
  Rgb ear(double rho, double psi, bool lateral) const;

 private:
  Rgb skinAt(const Eigen::Vector3d& p) const;
  void paintEye(const SurfaceSample& s, Rgb& colour) const;
  void paintBrow(const SurfaceSample& s, Rgb& colour) const;
  void paintNose(const SurfaceSample& s, Rgb& colour) const;
  void paintMouth(const SurfaceSample& s, Rgb& colour) const;
  void paintHair(const SurfaceSample& s, Rgb& colour) const;

  const EarShape& ear_;
  const HeadIdentity& id_;
  const FaceLayout& L_;
  ValueNoise noise_;
  Rgb skin_, hair_, iris_;
};

// Skin with blotches, fine mottling and pores.
Rgb Painter::skinAt(const Eigen::Vector3d& p) const {
  const double low = noise_.fractal(p.x() / 22.0, p.y() / 22.0, p.z() / 22.0, 3);
  const double mid = noise_.fractal(p.x() / 3.5 + 40.0, p.y() / 3.5, p.z() / 3.5, 2);
  const double pore = noise_(p.x() / 0.45 + 90.0, p.y() / 0.45, p.z() / 0.45);
  Rgb c = skin_ * (1.0 + 0.07 * low + 0.035 * mid + 0.035 * pore);
  // Slightly redder blotches.
  const double red = 0.04 * noise_.fractal(p.x() / 9.0 - 30.0, p.y() / 9.0, p.z() / 9.0, 2);
  c.y() *= 1.0 - red;
  c.z() *= 1.0 - red;
  return c;
}

void Painter::paintEye(const SurfaceSample& s, Rgb& c) const {
  const EyeField e = eyeField(L_, s.X, s.Y);
  const double ax = std::abs(s.X);
  // Shadowed socket and lids, the crease, the tear trough.
  c *= 1.0 - 0.10 * bump(ax - L_.eyeX, s.Y - 2.0, L_.eyeHalfWidth + 3.0, 8.0);
  if (e.region <= 0.0) return;
  if (e.ly > e.upper) {
    c *= 1.0 - 0.28 * std::exp(-sq((e.ly - e.crease) / 0.55)) * smoothstep(1.1, 0.6, std::abs(e.t));
    const double lid = smoothstep(e.crease + 0.5, e.crease - 1.0, e.ly);
    c = mixRgb(c, Rgb(c.x() * 0.93, c.y() * 0.86, c.z() * 0.86), lid);
  }
  c *= 1.0 - 0.08 * bump(ax - L_.eyeX - 1.0, s.Y + L_.eyeDown + 4.5, L_.eyeHalfWidth, 2.5);
  if (e.aperture > 0.0) {
    const double r = std::hypot(e.lx, e.ly);
    Rgb eye(0.90, 0.87, 0.84);
    eye *= 1.0 - 0.22 * std::pow(std::abs(e.t), 3.0);
    const double caruncle = bump(e.lx + L_.eyeHalfWidth - 1.6, e.ly - L_.eyeSlope * e.lx, 2.0, 1.5);
    eye = mixRgb(eye, Rgb(0.80, 0.48, 0.47), caruncle);
    if (r < L_.irisRadius + 0.3) {
      const double a = std::atan2(e.ly, e.lx);
      const double streak = noise_(std::cos(a) * 9.0, std::sin(a) * 9.0, r * 0.7 + 300.0);
      Rgb iris = iris_ * (0.75 + 0.4 * streak);
      iris *= 1.0 + 0.25 * std::exp(-sq((r - 2.0 * L_.pupilRadius) / 0.7));
      iris *= 1.0 - 0.65 * smoothstep(L_.irisRadius - 1.2, L_.irisRadius, r);
      iris = mixRgb(iris, Rgb(0.02, 0.02, 0.025),
                    smoothstep(L_.pupilRadius + 0.15, L_.pupilRadius - 0.15, r));
      eye = mixRgb(eye, iris, smoothstep(L_.irisRadius + 0.15, L_.irisRadius - 0.15, r));
    }
    // A catch-light up and to the image right of each pupil (model +x, both eyes alike).
    const double ex = s.X - (s.X >= 0.0 ? L_.eyeX : -L_.eyeX);
    eye = mixRgb(eye, Rgb(0.97, 0.97, 0.97), 0.9 * bump(ex - 1.7, e.ly - 1.7, 0.55, 0.55));
    eye *= 0.55 + 0.45 * smoothstep(0.0, 2.2, e.upper - e.ly);
    c = mixRgb(c, eye, e.aperture);
  }
  // Lash lines: heavy on the upper margin, thickening outwards; light on the lower one.
  const Rgb lash = hair_ * 0.35 + Rgb(0.02, 0.02, 0.02);
  const double side = smoothstep(1.15, 0.85, std::abs(e.t));
  const double upperWidth = 0.55 + 0.45 * smoothstep(-0.3, 1.0, e.t);
  const double up = e.ly - e.upper;
  if (up > -0.4) c = mixRgb(c, lash, 0.92 * side * std::exp(-sq(std::max(up, 0.0) / upperWidth)));
  const double down = e.lower - e.ly;
  if (down > -0.3) c = mixRgb(c, lash, 0.45 * side * std::exp(-sq(std::max(down, 0.0) / 0.35)));
}

void Painter::paintBrow(const SurfaceSample& s, Rgb& c) const {
  const BrowField b = browField(L_, s.X, s.Y);
  if (b.mask <= 0.0) return;
  // Hairs grow up and out at the inner end, along the brow further out.
  const double angle = mix(1.25, 0.15, smoothstep(0.0, 0.45, b.u));
  const double dx = std::abs(s.X);
  const double along = dx * std::cos(angle) + s.Y * std::sin(angle);
  const double across = -dx * std::sin(angle) + s.Y * std::cos(angle);
  const double strand = noise_(along / 2.2 + 500.0, across / 0.28, s.X < 0 ? 7.0 : 0.0);
  const double density =
      b.mask * std::clamp(0.8 + 0.8 * strand, 0.0, 1.0) * (1.0 - 0.35 * smoothstep(0.5, 1.0, b.u));
  // Brows are at least as dark as a deep shade of the skin, even for fair hair.
  const Rgb brow = (hair_ * 0.8).cwiseMin(skin_ * 0.3);
  c = mixRgb(c, brow, 0.95 * density);
}

void Painter::paintNose(const SurfaceSample& s, Rgb& c) const {
  const double ax = std::abs(s.X);
  c *= 1.0 - 0.10 * std::exp(-sq((std::hypot(ax - L_.alaX, s.Y - L_.alaY) - 7.0) / 1.0)) *
                 smoothstep(L_.alaX - 2.0, L_.alaX + 3.0, ax);
  const double nostril = bump(ax - L_.nostrilX, s.Y - L_.nostrilY, 3.3, 2.1);
  c = mixRgb(c, Rgb(0.10, 0.05, 0.04), smoothstep(0.3, 0.65, nostril));
  // Shadowed hollows between the bridge and the eyes, and the crease at the nasal root.
  c *= 1.0 - 0.14 * bump(ax - 9.5, s.Y + 1.0, 3.5, 6.0);
  c *= 1.0 - 0.10 * std::exp(-sq((s.Y - L_.nasionY) / 0.6)) * bump(s.X, 0.0, 6.0, 1.0);
  // Redder nose tip and alae.
  const double red = 0.07 * bump(s.X, s.Y - L_.tipY, 9.0, 7.0) +
                     0.06 * bump(ax - L_.alaX, s.Y - L_.alaY, 6.0, 5.0);
  c.y() *= 1.0 - red;
  c.z() *= 1.0 - red;
}

void Painter::paintMouth(const SurfaceSample& s, Rgb& c) const {
  const MouthField m = mouthField(L_, s.X, s.Y);
  const double ax = std::abs(s.X);
  if (m.width > 0.0) {
    const double r = id_.lipRedness;
    Rgb lip(c.x() * (0.80 + 0.06 * r), c.y() * (0.62 - 0.14 * r), c.z() * (0.66 - 0.12 * r));
    lip *= 1.0 + 0.05 * noise_(s.X * 2.5 + 700.0, s.Y * 0.35, 1.0);
    const double lowerSpan = std::max(m.lowerTop - m.lowerBottom, 1e-6);
    const double w = (m.lowerTop - s.Y) / lowerSpan;
    lip *= 1.0 + 0.08 * std::exp(-sq((w - 0.35) / 0.15)) * m.lowerLip;
    c = mixRgb(c, lip, std::max(m.upperLip, m.lowerLip));
    // The line where the lips meet.
    c = mixRgb(c, Rgb(0.16, 0.06, 0.06),
               0.75 * std::pow(m.width, 0.3) * std::exp(-sq((s.Y - m.line) / 0.45)));
    if (m.interior > 0.0) {
      Rgb inside(0.13, 0.04, 0.05);
      const double toothTop = m.upperBottom;
      if (s.Y > toothTop - 5.5 && std::abs(m.t) < 0.8) {
        // Upper incisors: a light band under the upper lip with soft gaps between the teeth.
        const double gap = std::exp(-sq(std::remainder(ax, 8.5) / 0.5));
        const Rgb tooth = Rgb(0.86, 0.84, 0.76) * (1.0 - 0.25 * gap);
        const double band = smoothstep(toothTop - 5.5, toothTop - 4.0, s.Y);
        inside = mixRgb(inside, tooth, band * smoothstep(0.8, 0.55, std::abs(m.t)));
      }
      c = mixRgb(c, inside, m.interior);
    }
  }
  const double cornerY = L_.mouthY + L_.cornerLift;
  c = mixRgb(c, Rgb(0.2, 0.09, 0.08), 0.45 * bump(ax - L_.mouthHalfWidth, s.Y - cornerY, 1.6, 1.1));
}

void Painter::paintHair(const SurfaceSample& s, Rgb& c) const {
  const Eigen::Vector3d& p = s.position;
  const double edge = 1.5 * noise_.fractal(p.x() / 6.0, p.y() / 6.0 + 900.0, p.z() / 6.0, 2);
  const double mask = smoothstep(-1.5, 1.5, s.Y - s.hairline + edge);
  if (mask <= 0.0) return;
  const double strand = noise_(p.x() / 0.35 + 50.0, p.y() / 7.0, p.z() / 0.35);
  const double clump = noise_.fractal(p.x() / 6.0, p.y() / 15.0 + 3.0, p.z() / 6.0, 2);
  const Rgb hair = hair_ * (0.8 + 0.3 * strand + 0.15 * clump);
  c = mixRgb(c, hair, mask);
}

Rgb Painter::head(const SurfaceSample& s) const {
  Rgb c = skinAt(s.position);
  if (s.front > 0.0) {
    const double ax = std::abs(s.X);
    // Cheek blush and a lighter forehead.
    const double blush = 0.07 * bump(ax - 40.0, s.Y - L_.cheekY, 16.0, 13.0) * s.front;
    c.y() *= 1.0 - blush;
    c.z() *= 1.0 - 1.2 * blush;
    Rgb f = c;
    paintNose(s, f);
    paintMouth(s, f);
    paintEye(s, f);
    paintBrow(s, f);
    c = mixRgb(c, f, s.front);
  }
  paintHair(s, c);
  return c;
}

Rgb Painter::ear(double rho, double psi, bool lateral) const {
  const EarSample e = ear_.sample(rho, psi, lateral);
  Rgb c = skinAt(e.position);
  c.y() *= 0.92;
  c.z() *= 0.9;
  c *= 1.0 - 0.35 * e.concha + 0.05 * e.rim;
  if (!lateral) c *= 0.88;
  return c;
}

}  // namespace

cv::Mat paintHeadTexture(const HeadShape& head, const EarShape& ear, const AngleWarp& theta,
                         const AngleWarp& phi, int size) {
  const Painter painter(head, ear);
  cv::Mat texture(size, size, CV_8UC3);
  std::vector<double> thetaOfColumn(static_cast<std::size_t>(size));
  for (int col = 0; col < size; ++col) {
    thetaOfColumn[static_cast<std::size_t>(col)] = theta.angle((col + 0.5) / size);
  }
  const auto store = [&](int row, int col, const Rgb& c) {
    auto& px = texture.at<cv::Vec3b>(row, col);
    for (int k = 0; k < 3; ++k) {
      px[2 - k] = static_cast<unsigned char>(std::lround(std::clamp(c[k], 0.0, 1.0) * 255.0));
    }
  };
  const auto paintRow = [&](int row) {
    const double v = 1.0 - (row + 0.5) / size;
    if (v >= 0.25) {
      const double a = phi.angle((v - kHeadChartBottom) / (1.0 - kHeadChartBottom));
      for (int col = 0; col < size; ++col) {
        store(row, col, painter.head(head.sample(thetaOfColumn[static_cast<std::size_t>(col)], a)));
      }
    } else {
      const double rho = std::clamp(v / kEarChartTop, 0.0, 1.0);
      for (int col = 0; col < size; ++col) {
        const double u = (col + 0.5) / size;
        const bool lateral = u < 0.5;
        const double psi =
            -std::numbers::pi + 2.0 * std::numbers::pi * (lateral ? u : u - 0.5) / 0.5;
        store(row, col, painter.ear(rho, psi, lateral));
      }
    }
  };
  // Texels are independent, so rows are shared among a few threads (the result does not depend
  // on how many).
  parallelFor(size, std::min(4, workerCount(size, 0)), paintRow);
  return texture;
}

}  // namespace clm3d::synth
