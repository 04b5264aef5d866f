#include "shadowgen/sampled/face_samples.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shadowgen::sampled {
namespace {

// splitmix64: a cheap, well-mixed stream whose every state is a valid seed, so one face's
// stream is the fixed seed mixed with the face's index.
class Jitter {
 public:
  explicit Jitter(std::uint64_t stream) : state_(0x5DEECE66Dull ^ mix(stream + 1)) {}

  double next() {
    return static_cast<double>(mix(state_ += 0x9E3779B97F4A7C15ull) >> 11) * 0x1.0p-53;  // [0, 1)
  }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t state_;
};

// The point of the part at (s, t) in the unit square, by area.
glm::dvec3 warp(const PartTriangles& part, double s, double t) {
  const double target = s * part.triangle_area();
  // The triangle whose share of the cumulative area holds the target.
  const auto it = std::upper_bound(part.upto.begin() + 1, part.upto.end() - 1, target);
  const std::size_t k = static_cast<std::size_t>(it - (part.upto.begin() + 1));
  const double width = part.upto[k + 1] - part.upto[k];
  const double u = std::clamp((target - part.upto[k]) / width, 0.0, 1.0);
  const double r = std::sqrt(u);
  const Triangle3& tri = part.triangles[k];
  return (1.0 - r) * tri.a + r * (1.0 - t) * tri.b + r * t * tri.c;
}

}  // namespace

std::vector<int> samples_per_part(std::span<const PartTriangles> parts, int count) {
  std::vector<int> n(parts.size(), 0);
  double total = 0.0;
  int with_area = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (parts[k].triangles.empty()) continue;
    n[k] = 1;
    total += parts[k].triangle_area();
    ++with_area;
  }
  const int rest = count - with_area;
  if (rest <= 0) return n;
  // Largest remainders: each part its whole share of the rest, then one more for the parts
  // with the largest fractions left until the rest is used up.
  std::vector<double> fraction(parts.size(), -1.0);
  int given = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (parts[k].triangles.empty()) continue;
    const double share = rest * (parts[k].triangle_area() / total);
    const int whole = std::min(rest - given, static_cast<int>(std::floor(share)));
    n[k] += whole;
    given += whole;
    fraction[k] = share - whole;
  }
  std::vector<std::size_t> order(parts.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return fraction[a] > fraction[b]; });
  for (std::size_t i = 0; given < rest && i < order.size(); ++i) {
    if (fraction[order[i]] < 0.0) break;
    ++n[order[i]];
    ++given;
  }
  return n;
}

void face_samples(std::span<const PartTriangles> parts, int count, std::uint64_t stream,
                  std::vector<FaceSample>& out) {
  out.clear();
  const std::vector<int> per_part = samples_per_part(parts, count);
  Jitter jitter(stream);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const int n = per_part[k];
    if (n == 0) continue;
    const int rows = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(n)))));
    for (int row = 0; row < rows; ++row) {
      const int cells = n / rows + (row < n % rows ? 1 : 0);
      const double weight = 1.0 / (static_cast<double>(rows) * cells);
      for (int cell = 0; cell < cells; ++cell) {
        const double s = (row + jitter.next()) / rows;
        const double t = (cell + jitter.next()) / cells;
        out.push_back({warp(parts[k], s, t), weight, k});
      }
    }
  }
}

std::vector<double> part_lit_areas(std::span<const PartTriangles> parts,
                                   std::span<const FaceSample> samples,
                                   std::span<const double> lit) {
  std::vector<double> lit_weight(parts.size(), 0.0), weight(parts.size(), 0.0);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    lit_weight[samples[i].part] += samples[i].weight * lit[i];
    weight[samples[i].part] += samples[i].weight;
  }
  std::vector<double> areas(parts.size(), 0.0);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    // The same sums in the same order: a part lit at every point gets its area exactly.
    if (weight[k] > 0.0) areas[k] = parts[k].area * (lit_weight[k] / weight[k]);
  }
  return areas;
}

}  // namespace shadowgen::sampled
