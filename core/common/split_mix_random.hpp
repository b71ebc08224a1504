// SplitMix64, the project's one random generator: small, well mixed and portable (the std
// distributions differ between standard libraries), so a seed gives the same training renders,
// MakeHuman identities and ICT samples everywhere; and `mixKey` to derive independent keys
// (seed -> subject -> view -> sample -> effect), so that every draw comes from its own stream and
// results do not depend on which thread made them.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

namespace clm3d {

class SplitMixRandom {
 public:
  explicit SplitMixRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1).
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  // Uniform in [-range, range].
  double symmetric(double range) { return (2.0 * unit() - 1.0) * range; }
  // Uniform in [lo, hi].
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // Uniform integer in [lo, hi].
  int integer(int lo, int hi) {
    return lo + static_cast<int>(unit() * static_cast<double>(hi - lo + 1));
  }
  // True with probability p.
  bool chance(double p) { return unit() < p; }
  // Uniform index in [0, n) (n > 0; the modulo bias is negligible for small n).
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
  // Standard normal (Box-Muller, one value per two draws).
  double normal() {
    const double u = 1.0 - unit();  // (0, 1]
    const double v = unit();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
  }

 private:
  std::uint64_t state_;
};

// A key derived from `a` and `b`, well mixed (different b, unrelated streams).
inline std::uint64_t mixKey(std::uint64_t a, std::uint64_t b) {
  SplitMixRandom r(a ^ (b * 0xD1B54A32D192ED03ull));
  return r.next();
}

}  // namespace clm3d
