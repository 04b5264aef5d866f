#pragma once

// Seeded random doubles for the benchmark scenes: std::mt19937_64 (whose sequence the
// standard fixes) turned into doubles by hand, not by a <random> distribution (whose
// algorithm it does not fix), so a seed makes the same scene everywhere.

#include <cmath>
#include <cstdint>
#include <random>

namespace shadowgen::bench {

class SceneRandom {
 public:
  explicit SceneRandom(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1).
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // Log-uniform in [lo, hi): every factor of 10 equally likely.
  double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace shadowgen::bench
