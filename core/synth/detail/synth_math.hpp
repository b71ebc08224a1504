// Small smooth functions shared by the head's geometry and its texture painter, so that a
// feature's outline in the texture and in the surface come from the same formula.
#pragma once

#include <algorithm>
#include <cmath>

namespace clm3d::synth {

inline double sq(double x) {
  return x * x;
}

// Hermite step from 0 at e0 to 1 at e1 (e1 < e0 gives a falling step).
inline double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

inline double mix(double a, double b, double t) {
  return a + (b - a) * t;
}

// exp(-(dx/sx)^2 - (dy/sy)^2): the anisotropic bump every feature is made of.
inline double bump(double dx, double dy, double sx, double sy) {
  return std::exp(-sq(dx / sx) - sq(dy / sy));
}

// Polynomial smooth maximum / minimum with blend width k (> 0); exact max/min when |a - b| >= k.
inline double smoothMax(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::max(a, b) + h * h * k * 0.25;
}
inline double smoothMin(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

}  // namespace clm3d::synth
