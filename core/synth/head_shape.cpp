#include "core/synth/detail/head_shape.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/error.hpp"
#include "core/synth/detail/synth_math.hpp"

namespace clm3d::synth {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double deg(double d) {
  return d * std::numbers::pi / 180.0;
}

Eigen::Vector3d direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(phi), std::cos(theta) * std::cos(phi)};
}

// Distance from the point p to the segment a-b in the chart, and the parameter along it.
double segmentDistance(double px, double py, double ax, double ay, double bx, double by,
                       double* along) {
  const double vx = bx - ax;
  const double vy = by - ay;
  const double t = std::clamp(((px - ax) * vx + (py - ay) * vy) / (vx * vx + vy * vy), 0.0, 1.0);
  *along = t;
  return std::hypot(px - ax - t * vx, py - ay - t * vy);
}

}  // namespace

FaceLayout makeLayout(const HeadIdentity& id, const Expression& ex) {
  FaceLayout L;
  L.eyeX = id.eyeSpacing / 2.0;
  L.eyeHalfWidth = id.eyeWidth / 2.0;
  const double opening = id.eyeOpening * (1.0 - 0.55 * ex.eyesNarrow - 0.12 * ex.smile +
                                          0.22 * ex.browRaise - 0.05 * ex.frown);
  L.eyeUp = 0.56 * opening;
  L.eyeDown = 0.44 * opening * (1.0 - 0.15 * ex.smile);
  L.eyeSlope = std::tan(deg(id.eyeCant));
  L.irisRadius = id.irisRadius;
  L.pupilRadius = 0.36 * id.irisRadius;

  L.browInnerX = L.eyeX - L.eyeHalfWidth - 3.0 - 2.5 * ex.frown;
  L.browOuterX = L.eyeX + L.eyeHalfWidth + 7.0;
  L.browInnerY = id.browHeight + 7.0 * ex.browRaise - 4.5 * ex.frown;
  L.browOuterY = id.browHeight - 2.0 + 5.0 * ex.browRaise - 1.0 * ex.frown;
  L.browArch = id.browArch + 1.5 * ex.browRaise;
  L.browThickness = id.browThickness;
  L.frown = ex.frown;

  L.nasionY = 3.0;
  L.tipY = -id.noseLength;
  L.tipHeight = id.noseProjection;
  L.bridgeHeight = 0.22 * id.noseProjection;
  L.subnasaleY = L.tipY - 0.25 * id.noseProjection - 3.5;
  L.alaX = id.noseWidth / 2.0 - 5.5;
  L.alaY = L.tipY - 0.12 * id.noseProjection - 2.0;
  L.alaHeight = 0.42 * id.noseProjection;
  L.alarBaseX = id.noseWidth / 2.0;
  L.alarBaseY = L.alaY - 4.0;
  L.nostrilX = 0.17 * id.noseWidth;
  L.nostrilY = L.subnasaleY + 3.0;

  L.jawDrop = 18.0 * ex.mouthOpen;
  L.lipGap = 16.0 * ex.mouthOpen;
  L.mouthY = -id.mouthHeight;
  L.mouthHalfWidth = id.mouthWidth / 2.0 * (1.0 + 0.12 * ex.smile - 0.06 * ex.mouthOpen);
  L.cornerLift = 4.5 * ex.smile - 3.5 * ex.frown;
  L.upperLip = id.upperLipThickness * (1.0 - 0.2 * ex.smile);
  L.lowerLip = id.lowerLipThickness * (1.0 - 0.1 * ex.smile);

  L.mentonY = -id.faceHeight - L.jawDrop;
  L.chinHalfWidth = id.chinWidth / 2.0;
  L.chinProjection = id.chinProjection;
  L.cheekHeight = 2.0 + 5.0 * id.cheekFullness + 1.5 * ex.smile;
  L.cheekY = -28.0 + 4.0 * ex.smile;
  L.smileBulge = 2.5 * ex.smile;
  L.foldDepth = 0.8 + 1.6 * ex.smile;

  L.cheekPointX = 0.43 * id.faceWidth;
  L.cheekPointY = L.mouthY + 2.0 - 0.4 * L.jawDrop;
  L.chinPointX = L.chinHalfWidth + 3.0;
  L.chinPointY = L.mentonY + 9.0;

  L.foreheadHeight = id.foreheadHeight;
  L.hairBulk = id.hairBulk;
  L.earTop = id.earPosition + id.earHeight / 2.0;
  return L;
}

EyeField eyeField(const FaceLayout& L, double X, double Y) {
  EyeField f;
  f.lx = std::abs(X) - L.eyeX;
  f.ly = Y;
  const double hw = L.eyeHalfWidth;
  f.t = f.lx / hw;
  const double s = std::max(0.0, 1.0 - f.t * f.t);
  const double base = L.eyeSlope * f.lx;
  f.upper = base + L.eyeUp * std::pow(s, 0.6) * (1.0 - 0.12 * f.t);
  f.lower = base - L.eyeDown * std::pow(s, 0.75) * (1.0 + 0.12 * f.t);
  f.opening = std::min({f.upper - f.ly, f.ly - f.lower, hw - std::abs(f.lx)});
  f.aperture = smoothstep(-0.3, 0.3, f.opening);
  const double ry = f.ly > base ? L.eyeUp + 9.0 : L.eyeDown + 6.0;
  const double q = std::hypot(f.lx / (hw + 7.0), (f.ly - base) / ry);
  f.region = 1.0 - smoothstep(0.72, 1.1, q);
  f.crease = base + (L.eyeUp + 4.0) * std::pow(std::max(0.0, 1.0 - sq(f.lx / (hw + 2.0))), 0.5);
  return f;
}

MouthField mouthField(const FaceLayout& L, double X, double Y) {
  MouthField m;
  m.t = X / L.mouthHalfWidth;
  m.width = std::max(0.0, 1.0 - m.t * m.t);
  m.line = L.mouthY + L.cornerLift * m.t * m.t;
  const double gap = L.lipGap * std::pow(m.width, 0.7);
  m.upperBottom = m.line + 0.15 * gap;
  m.lowerTop = m.line - 0.85 * gap;
  const double at = std::abs(m.t);
  const double bow =
      1.0 + 0.12 * std::exp(-sq((at - 0.22) / 0.1)) - 0.1 * std::exp(-sq(m.t / 0.08));
  m.upperTop = m.upperBottom + L.upperLip * std::pow(m.width, 0.7) * bow;
  m.lowerBottom = m.lowerTop - L.lowerLip * std::pow(m.width, 0.8);
  if (m.width > 0.0) {
    m.upperLip = smoothstep(-0.2, 0.2, std::min(m.upperTop - Y, Y - m.upperBottom + 0.2));
    m.lowerLip = smoothstep(-0.2, 0.2, std::min(Y - m.lowerBottom, m.lowerTop - Y + 0.2));
    if (gap > 0.05) {
      m.interior = smoothstep(-0.8, 1.2, std::min(m.upperBottom - Y, Y - m.lowerTop));
    }
  }
  return m;
}

BrowField browField(const FaceLayout& L, double X, double Y) {
  BrowField b;
  const double length = L.browOuterX - L.browInnerX;
  b.u = (std::abs(X) - L.browInnerX) / length;
  const double uc = std::clamp(b.u, 0.0, 1.0);
  const double centre = mix(L.browInnerY, L.browOuterY, uc) +
                        L.browArch * std::sin(std::numbers::pi * std::pow(uc, 0.75));
  b.halfThickness = 0.6 * L.browThickness * (1.0 - 0.45 * uc);
  b.across = Y - centre;
  const double beyond = b.u < 0.0 ? -b.u * length : (b.u > 1.0 ? (b.u - 1.0) * length * 1.5 : 0.0);
  const double outside = std::max(std::abs(b.across) - b.halfThickness, 0.0) + beyond;
  b.mask = smoothstep(0.7, -0.3, outside);
  return b;
}

double Ellipsoid::exitDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) const {
  const Eigen::Vector3d o = (origin - centre).cwiseQuotient(axes);
  const Eigen::Vector3d d = dir.cwiseQuotient(axes);
  const double a = d.squaredNorm();
  const double b = 2.0 * o.dot(d);
  const double c = o.squaredNorm() - 1.0;
  return (-b + std::sqrt(std::max(0.0, b * b - 4.0 * a * c))) / (2.0 * a);
}

HeadShape::HeadShape(const HeadIdentity& identity, const Expression& expression)
    : identity_(identity), layout_(makeLayout(identity, expression)) {
  identity.validate();
  expression.validate();
  const FaceLayout& L = layout_;
  centre_ = {0.0, -30.0, -80.0};

  // Skull: its top at headHeight, its front 5 mm ahead of the eye line's origin.
  skull_.axes = {identity.headWidth / 2.0, 112.0, identity.headDepth / 2.0};
  skull_.centre.y() = identity.headHeight - skull_.axes.y();
  skull_.centre.z() =
      5.0 - skull_.axes.z() * std::sqrt(1.0 - sq(skull_.centre.y() / skull_.axes.y()));

  // Jaw: wide at the mouth, its front 3 mm ahead of the origin at the mouth, reaching below the
  // chin, where the plane under the chin cuts it.
  jaw_.axes = {0.46 * identity.faceWidth, 90.0 + L.jawDrop / 2.0, 62.0};
  jaw_.centre.y() = -50.0 - L.jawDrop / 2.0;
  jaw_.centre.z() =
      3.0 - jaw_.axes.z() * std::sqrt(1.0 - sq((L.mouthY - jaw_.centre.y()) / jaw_.axes.y()));
  // The plane under the jaw rises from the chin towards the jaw angles, facing down and back.
  const double tilt = deg(17.0);
  chinPlaneNormal_ = Eigen::Vector3d(0.0, -std::cos(tilt), -std::sin(tilt));
  const double chinZ =
      jaw_.centre.z() +
      jaw_.axes.z() *
          std::sqrt(std::max(0.0, 1.0 - sq((L.mentonY - jaw_.centre.y()) / jaw_.axes.y())));
  chinPlaneOffset_ = chinPlaneNormal_.dot(Eigen::Vector3d(0.0, L.mentonY - 4.0, chinZ));

  neckCentreZ_ = -100.0;
  neckRadiusX_ = 0.33 * identity.headWidth;
  neckRadiusZ_ = 52.0;
  neckBottom_ = L.mentonY - 55.0;
  neckTop_ = -20.0;
}

double HeadShape::baseRadius(const Eigen::Vector3d& d) const {
  const Eigen::Vector3d& c = centre_;
  const double rSkull = skull_.exitDistance(c, d);
  double rJaw = jaw_.exitDistance(c, d);
  const double towardsPlane = chinPlaneNormal_.dot(d);
  if (towardsPlane > 1e-9) {
    const double rPlane = (chinPlaneOffset_ - chinPlaneNormal_.dot(c)) / towardsPlane;
    rJaw = smoothMin(rJaw, rPlane, 10.0);
  }
  // Neck: an elliptic cylinder along y between two caps.
  const double ax = d.x() / neckRadiusX_;
  const double az = d.z() / neckRadiusZ_;
  const double ox = c.x() / neckRadiusX_;
  const double oz = (c.z() - neckCentreZ_) / neckRadiusZ_;
  const double qa = ax * ax + az * az;
  double rNeck = kInf;
  if (qa > 1e-12) {
    const double qb = 2.0 * (ox * ax + oz * az);
    const double qc = ox * ox + oz * oz - 1.0;
    rNeck = (-qb + std::sqrt(std::max(0.0, qb * qb - 4.0 * qa * qc))) / (2.0 * qa);
  }
  if (d.y() < -1e-9) rNeck = smoothMin(rNeck, (neckBottom_ - c.y()) / d.y(), 6.0);
  if (d.y() > 1e-9) rNeck = std::min(rNeck, (neckTop_ - c.y()) / d.y());
  return smoothMax(smoothMax(rSkull, rJaw, 14.0), rNeck, 12.0);
}

double HeadShape::hairlineAt(double theta) const {
  const FaceLayout& L = layout_;
  const double a = std::abs(theta) * 180.0 / std::numbers::pi;
  const double earLine = L.earTop + 5.0;
  const std::array<std::pair<double, double>, 8> knots{{{0.0, L.foreheadHeight},
                                                        {30.0, L.foreheadHeight - 3.0},
                                                        {55.0, 0.7 * L.foreheadHeight},
                                                        {80.0, earLine + 12.0},
                                                        {100.0, earLine},
                                                        {118.0, earLine},
                                                        {150.0, -30.0},
                                                        {180.0, -50.0}}};
  for (std::size_t i = 1; i < knots.size(); ++i) {
    if (a <= knots[i].first) {
      const double f = smoothstep(knots[i - 1].first, knots[i].first, a);
      return mix(knots[i - 1].second, knots[i].second, f);
    }
  }
  return knots.back().second;
}

double HeadShape::faceRelief(double X, double Y) const {
  const FaceLayout& L = layout_;
  const double ax = std::abs(X);
  double h = 0.0;

  // Forehead, brow ridges, temples.
  const double browMidX = 0.5 * (L.browInnerX + L.browOuterX);
  const double browMidY = 0.5 * (L.browInnerY + L.browOuterY) + 0.5 * L.browArch;
  h += 3.2 * bump(ax - browMidX, Y - (browMidY - 2.5), 0.7 * (L.browOuterX - L.browInnerX), 6.5);
  h += 1.5 * bump(X, Y - 11.0, 9.0, 8.0);  // glabella
  h -= 3.0 * bump(ax - 62.0, Y - 18.0, 10.0, 16.0);
  // Frown furrows between the brows.
  h -= 0.7 * L.frown * bump(ax - 3.5, Y - 14.0, 1.0, 6.0);

  // Eye sockets (the lids and eyeball are blended in below).
  h -= 6.5 * bump(ax - L.eyeX, Y + 1.0, L.eyeHalfWidth + 4.0, 11.0);

  // Cheekbones and cheeks; the smile bulge beside the nose; the nasolabial fold.
  h += L.cheekHeight * bump(ax - 40.0, Y - L.cheekY, 16.0, 13.0);
  h += 4.0 * bump(ax - 56.0, Y + 16.0, 11.0, 14.0);  // cheekbones widen the mid-face
  h += L.smileBulge * bump(ax - (L.mouthHalfWidth + 4.0), Y - (L.mouthY + 14.0), 9.0, 9.0);
  double along = 0.0;
  const double foldDistance = segmentDistance(ax, Y, L.alaX + 7.5, L.alaY + 1.0,
                                              L.mouthHalfWidth + 4.0, L.mouthY - 10.0, &along);
  h -= L.foldDepth * std::exp(-sq(foldDistance / 2.2)) * smoothstep(1.0, 0.75, along);

  // Nose: bridge and dorsum rising to the tip, rounded underside down to the lip.
  double profile = 0.0;
  if (Y > L.nasionY) {
    profile = L.bridgeHeight * smoothstep(L.nasionY + 12.0, L.nasionY, Y);
  } else if (Y > L.tipY) {
    const double s = (L.nasionY - Y) / (L.nasionY - L.tipY);
    profile = mix(L.bridgeHeight, 0.9 * L.tipHeight, std::pow(s, 1.15));
  } else {
    const double s = std::min(1.0, (L.tipY - Y) / (L.tipY - L.subnasaleY));
    profile = 0.9 * L.tipHeight * std::sqrt(std::max(0.0, 1.0 - s * s));
  }
  const double ridgeWidth = 5.5 + 5.0 * smoothstep(L.nasionY, L.tipY, Y);
  h += profile * std::exp(-sq(X / ridgeWidth));
  h += 0.22 * L.tipHeight * bump(X, Y - L.tipY, 7.0, 5.5);
  // Alae (nostril wings) with their creases; nostrils under the tip.
  h += L.alaHeight * bump(ax - L.alaX, Y - L.alaY, 5.5, 5.0);
  const double alaRing = std::hypot(ax - L.alaX, Y - L.alaY);
  h -= 1.4 * std::exp(-sq((alaRing - 7.0) / 1.3)) * smoothstep(L.alaX - 2.0, L.alaX + 3.0, ax);
  h -= 3.0 * bump(ax - L.nostrilX, Y - L.nostrilY, 3.6, 2.3);

  // Philtrum ridges; the muzzle that carries the lips forward.
  const MouthField m = mouthField(L, X, Y);
  const double philtrumBand = smoothstep(L.subnasaleY + 1.0, L.subnasaleY - 3.0, Y) *
                              smoothstep(m.upperTop - 1.0, m.upperTop + 2.0, Y);
  h += 0.9 * philtrumBand * std::exp(-sq((ax - 4.5) / 1.6));
  h += 7.0 * bump(X, Y - (L.mouthY + 2.0), 30.0, 22.0);

  // Lips: rounded red lips, a groove where they meet, a deep opening when the mouth is open,
  // small pits at the corners.
  if (m.width > 0.0) {
    const double lateral = std::pow(m.width, 0.3);
    const double upperSpan = std::max(m.upperTop - m.upperBottom, 1e-6);
    const double v = std::clamp((Y - m.upperBottom) / upperSpan, 0.0, 1.0);
    h += 2.6 * lateral * 4.0 * v * (1.0 - v) * m.upperLip;
    const double lowerSpan = std::max(m.lowerTop - m.lowerBottom, 1e-6);
    const double w = std::clamp((m.lowerTop - Y) / lowerSpan, 0.0, 1.0);
    h += 3.2 * lateral * 4.0 * w * (1.0 - w) * m.lowerLip;
    // White roll at the upper vermilion border.
    h += 0.5 * lateral * std::exp(-sq((Y - m.upperTop) / 0.7));
    h -= 1.2 * lateral * std::exp(-sq((Y - m.line) / 0.8)) * smoothstep(3.0, 0.5, L.lipGap);
    h -= 11.0 * m.interior;
  }
  const double cornerY = L.mouthY + L.cornerLift;
  h -= 1.2 * bump(ax - L.mouthHalfWidth - 0.5, Y - cornerY, 2.2, 2.2);

  // Below the lips: the groove above the chin, the chin.
  const double lowerLipBottom = L.mouthY - 0.85 * L.lipGap - L.lowerLip;
  h -= 2.0 * bump(X, Y - (lowerLipBottom - 6.0), 16.0, 3.5);
  h += L.chinProjection * bump(X, Y - (L.mentonY + 14.0), L.chinHalfWidth, 11.0);

  // Eyes: eyeball inside the opening, lids over it, a crease above the upper lid.
  const EyeField e = eyeField(L, X, Y);
  if (e.region > 0.0) {
    const double globe = -2.5 + 3.5 * std::max(0.0, 1.0 - sq(e.lx / 15.0) - sq(e.ly / 12.5));
    const double irisDistance = std::hypot(e.lx, e.ly);
    const double cornea = 0.7 * std::max(0.0, 1.0 - sq(irisDistance / (L.irisRadius + 0.5)));
    const double lidThickness = e.ly > L.eyeSlope * e.lx ? 1.7 : 1.1;
    double lids = globe + cornea * e.aperture + lidThickness * (1.0 - e.aperture);
    lids -= 0.6 * std::exp(-sq((e.ly - e.crease) / 1.1)) * (e.ly > e.upper ? 1.0 : 0.0);
    h = mix(h, lids, e.region);
  }
  return h;
}

SurfaceSample HeadShape::sample(double theta, double phi) const {
  SurfaceSample s;
  s.theta = theta;
  s.phi = phi;
  const Eigen::Vector3d d = direction(theta, phi);
  const double r0 = baseRadius(d);
  s.base = centre_ + r0 * d;
  s.X = s.base.x();
  s.Y = s.base.y();
  s.front = smoothstep(0.0, 0.3, d.z());
  double relief = 0.0;
  if (s.front > 0.0) relief = s.front * faceRelief(s.X, s.Y);
  s.hairline = hairlineAt(theta);
  relief += layout_.hairBulk * smoothstep(s.hairline - 2.0, s.hairline + 14.0, s.Y);
  s.position = centre_ + (r0 + relief) * d;
  return s;
}

Eigen::Vector2d HeadShape::solveChart(double X, double Y) const {
  const auto chart = [&](double theta, double phi) {
    const Eigen::Vector3d d = direction(theta, phi);
    const Eigen::Vector3d p = centre_ + baseRadius(d) * d;
    return Eigen::Vector2d(p.x(), p.y());
  };
  Eigen::Vector2d a(std::atan2(X, 85.0), std::atan2(Y - centre_.y(), 90.0));
  const Eigen::Vector2d target(X, Y);
  constexpr double h = 1e-6;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const Eigen::Vector2d f = chart(a.x(), a.y()) - target;
    if (f.norm() < 1e-9) return a;
    Eigen::Matrix2d J;
    J.col(0) = (chart(a.x() + h, a.y()) - chart(a.x() - h, a.y())) / (2.0 * h);
    J.col(1) = (chart(a.x(), a.y() + h) - chart(a.x(), a.y() - h)) / (2.0 * h);
    Eigen::Vector2d step = J.colPivHouseholderQr().solve(-f);
    const double limit = 0.15;
    if (step.norm() > limit) step *= limit / step.norm();
    a += step;
  }
  if ((chart(a.x(), a.y()) - target).norm() < 1e-6) return a;
  throw Error("synthetic head: chart point (" + std::to_string(X) + ", " + std::to_string(Y) +
              ") is not on the face");
}

double HeadShape::chinBottomY() const {
  // Walk down the mid-line from the mouth to the first local minimum of the height (the chin
  // turning under, before the throat rises and the neck falls again), then refine it.
  const auto height = [&](double phi) {
    return centre_.y() + baseRadius(direction(0.0, phi)) * std::sin(phi);
  };
  const double step = deg(0.5);
  double phi = std::atan2(layout_.mouthY - centre_.y(), 90.0);
  while (phi > deg(-88.0) && height(phi - step) < height(phi)) phi -= step;
  double a = phi - step;
  double b = phi + step;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 60; ++i) {
    const double c = b - g * (b - a);
    const double d = a + g * (b - a);
    if (height(c) < height(d)) {
      b = d;
    } else {
      a = c;
    }
  }
  return height(0.5 * (a + b));
}

Eigen::Vector3d HeadShape::pointAt(double X, double Y) const {
  const Eigen::Vector2d a = solveChart(X, Y);
  return sample(a.x(), a.y()).position;
}

EarShape::EarShape(const HeadShape& head) {
  const HeadIdentity& id = head.identity();
  const Ellipsoid& skull = head.skull();
  halfHeight_ = id.earHeight / 2.0;
  halfWidth_ = 0.29 * id.earHeight;
  protrusion_ = std::tan(deg(id.earProtrusion));
  const double y = id.earPosition;
  const double z = skull.centre.z() + 6.0;
  const double inside = 1.0 - sq((y - skull.centre.y()) / skull.axes.y()) -
                        sq((z - skull.centre.z()) / skull.axes.z());
  const double x = skull.axes.x() * std::sqrt(std::max(0.05, inside));
  const Eigen::Vector3d attach(x, y, z);
  normal_ = (attach - skull.centre).cwiseQuotient(skull.axes.cwiseProduct(skull.axes)).normalized();
  Eigen::Vector3d up = Eigen::Vector3d::UnitY() - normal_ * normal_.y();
  up.normalize();
  Eigen::Vector3d back = up.cross(normal_);  // points to -z on the left side
  // Lean the ear's top backwards by 15 degrees.
  const double lean = deg(15.0);
  up_ = std::cos(lean) * up + std::sin(lean) * back;
  back_ = std::cos(lean) * back - std::sin(lean) * up;
  origin_ = attach + back_ * (0.55 * halfWidth_);
}

EarSample EarShape::sample(double rho, double psi, bool lateral) const {
  EarSample s;
  const double c = std::cos(psi);
  const double sn = std::sin(psi);
  s.lobe = smoothstep(-0.45, -0.9, sn);
  const double narrow = smoothstep(0.0, -1.0, sn);
  const double a = halfWidth_ * rho * (c * (1.0 - 0.3 * narrow) - 0.15 * s.lobe);
  const double b = halfHeight_ * rho * sn;
  const double along = a / halfWidth_;  // -1 front .. +1 back
  double out = -4.0 + (along + 1.0) * halfWidth_ * protrusion_ + 6.0 * s.lobe;
  s.rim = std::exp(-sq((rho - 0.9) / 0.08)) * smoothstep(-0.85, -0.4, sn);
  out += 2.2 * s.rim;
  out += 1.4 * std::exp(-sq((rho - 0.62) / 0.1)) * smoothstep(-0.2, 0.3, sn) *
         smoothstep(-0.6, 0.0, c);
  s.concha =
      bump(a + 0.15 * halfWidth_, b + 0.08 * halfHeight_, 0.42 * halfWidth_, 0.3 * halfHeight_);
  out -= 6.0 * s.concha;
  out += 2.5 *
         bump(a + 0.8 * halfWidth_, b + 0.1 * halfHeight_, 0.16 * halfWidth_, 0.12 * halfHeight_);
  const double thickness = (2.4 + 2.8 * s.lobe) * std::sqrt(std::max(0.0, 1.0 - rho * rho));
  out += lateral ? 0.5 * thickness : -0.5 * thickness;
  s.position = origin_ + normal_ * out + back_ * a + up_ * b;
  return s;
}

Eigen::Vector3d EarShape::lobePoint() const {
  return sample(0.8, -std::numbers::pi / 2.0, true).position;
}

}  // namespace clm3d::synth
