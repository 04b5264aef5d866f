#include "bench/sampled/stratified_samples.h"

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>

namespace shadowgen::bench {
namespace {

// splitmix64: a cheap, well-mixed stream, so that the jitter costs next to nothing
// against the rays it places.
class Jitter {
 public:
  double next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;  // [0, 1)
  }

 private:
  std::uint64_t state_ = 0x5DEECE66Dull;
};

}  // namespace

void stratified_samples(const std::vector<glm::dvec3>& loop, int k, std::vector<glm::dvec3>& out) {
  out.clear();
  // Cumulative areas of the fan's triangles (0, v[i], v[i + 1]), as fractions of the whole.
  const std::size_t fan = loop.size() - 2;
  std::vector<double> upto(fan + 1, 0.0);
  for (std::size_t i = 0; i < fan; ++i) {
    upto[i + 1] = upto[i] + glm::length(glm::cross(loop[i + 1] - loop[0], loop[i + 2] - loop[0]));
  }
  if (!(upto[fan] > 0.0)) return;  // a degenerate face: no area to sample
  for (double& u : upto) u /= upto[fan];

  Jitter jitter;
  const double cell = 1.0 / k;
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      double s = (i + jitter.next()) * cell;
      const double t = (j + jitter.next()) * cell;
      std::size_t tri = 0;
      while (tri + 1 < fan && s >= upto[tri + 1]) ++tri;
      const double width = upto[tri + 1] - upto[tri];
      s = width > 0.0 ? (s - upto[tri]) / width : 0.0;
      const double r = std::sqrt(s);
      out.push_back((1.0 - r) * loop[0] + r * (1.0 - t) * loop[tri + 1] + r * t * loop[tri + 2]);
    }
  }
}

}  // namespace shadowgen::bench
