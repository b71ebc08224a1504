// The mapping between a grid parameter s in [0, 1] and an angle, dense where the face is and
// sparse elsewhere. The head mesh puts its vertices at s = i / cells() and the texture puts its
// texels at s = u, through the same function, so every texel is painted with the colour of the
// surface point the mesh maps it to, and the face gets most of the triangles and texels.
#pragma once

#include <vector>

namespace clm3d::synth {

class AngleWarp {
 public:
  // Angles in degrees over [low, high]; steps of fineStep inside [fineLow, fineHigh], of
  // coarseStep elsewhere, blended over `blend` degrees.
  AngleWarp(double low, double high, double fineLow, double fineHigh, double fineStep,
            double coarseStep, double blend = 10.0);

  int cells() const { return cells_; }
  // The angle in radians at grid parameter s (clamped to [0, 1]).
  double angle(double s) const;

 private:
  double low_;
  double high_;
  std::vector<double> cdf_;  // cumulative share at equally spaced angles
  int cells_;
};

}  // namespace clm3d::synth
