// Deterministic 3D value noise for the painted skin, iris and hair detail: a hash of the lattice
// point and a seed, so a texture is identical on every run and platform (no std::rand, no
// distribution whose output the standard leaves open).
#pragma once

#include <cstdint>

namespace clm3d::synth {

class ValueNoise {
 public:
  explicit ValueNoise(std::uint64_t seed) : seed_(seed) {}
  // Smoothly interpolated noise in [-1, 1] with features about 1 unit apart.
  double operator()(double x, double y, double z) const;
  // Sum of `octaves` octaves, each of double frequency and half amplitude, normalised to [-1, 1].
  double fractal(double x, double y, double z, int octaves) const;

 private:
  double lattice(std::int64_t x, std::int64_t y, std::int64_t z) const;
  std::uint64_t seed_;
};

}  // namespace clm3d::synth
