#include "core/synth/detail/value_noise.hpp"

#include <cmath>

namespace clm3d::synth {
namespace {

std::uint64_t mixBits(std::uint64_t x) {
  // splitmix64 finaliser.
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

double fade(double t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

}  // namespace

double ValueNoise::lattice(std::int64_t x, std::int64_t y, std::int64_t z) const {
  std::uint64_t h = seed_;
  h = mixBits(h ^ static_cast<std::uint64_t>(x) * 0x9e3779b97f4a7c15ULL);
  h = mixBits(h ^ static_cast<std::uint64_t>(y) * 0xc2b2ae3d27d4eb4fULL);
  h = mixBits(h ^ static_cast<std::uint64_t>(z) * 0x165667b19e3779f9ULL);
  return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;
}

double ValueNoise::operator()(double x, double y, double z) const {
  const double fx = std::floor(x);
  const double fy = std::floor(y);
  const double fz = std::floor(z);
  const auto ix = static_cast<std::int64_t>(fx);
  const auto iy = static_cast<std::int64_t>(fy);
  const auto iz = static_cast<std::int64_t>(fz);
  const double tx = fade(x - fx);
  const double ty = fade(y - fy);
  const double tz = fade(z - fz);
  double c[2][2];
  for (int dz = 0; dz < 2; ++dz) {
    for (int dy = 0; dy < 2; ++dy) {
      const double a = lattice(ix, iy + dy, iz + dz);
      const double b = lattice(ix + 1, iy + dy, iz + dz);
      c[dz][dy] = a + (b - a) * tx;
    }
  }
  const double y0 = c[0][0] + (c[0][1] - c[0][0]) * ty;
  const double y1 = c[1][0] + (c[1][1] - c[1][0]) * ty;
  return y0 + (y1 - y0) * tz;
}

double ValueNoise::fractal(double x, double y, double z, int octaves) const {
  double sum = 0.0;
  double amplitude = 1.0;
  double total = 0.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amplitude * (*this)(x, y, z);
    total += amplitude;
    x = x * 2.0 + 17.3;
    y = y * 2.0 + 5.1;
    z = z * 2.0 + 11.7;
    amplitude *= 0.5;
  }
  return sum / total;
}

}  // namespace clm3d::synth
