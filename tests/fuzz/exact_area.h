#pragma once

// Exact region areas for the fuzzer's conservation checks: an oracle independent of the
// clipper's own polygon.h arithmetic, with no rounding error of its own.
//
// A sum is kept as a floating-point expansion after Shewchuk (1997), "Adaptive
// Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates": doubles of
// increasing magnitude, pairwise non-overlapping, whose exact sum is the value. Each
// product of the shoelace formula enters exactly as two doubles (std::fma gives the
// rounding error of a product). Exact while nothing overflows or underflows: the fuzzer
// makes coordinates that are 0 or of magnitude in [1e-9, 1e9], so products lie in
// [1e-18, 1e18] and their errors far above the subnormal range.

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::fuzz {

class ExactSum {
 public:
  // Grow-Expansion with zero elimination (Shewchuk, figure 6): exact.
  void add(double b) {
    std::vector<double> grown;
    grown.reserve(components_.size() + 1);
    double q = b;
    for (double e : components_) {
      const double sum = q + e;
      const double b_virtual = sum - q;
      const double a_virtual = sum - b_virtual;
      const double error = (q - a_virtual) + (e - b_virtual);
      q = sum;
      if (error != 0.0) grown.push_back(error);
    }
    if (q != 0.0) grown.push_back(q);
    components_ = std::move(grown);
  }

  void add_product(double a, double b) {
    const double product = a * b;
    add(std::fma(a, b, -product));
    add(product);
  }

  // this += sign * other, sign being +1 or -1.
  void add(const ExactSum& other, int sign) {
    for (double e : other.components_) add(sign < 0 ? -e : e);
  }

  // Exact sign of the value: that of the largest component.
  int sign() const {
    if (components_.empty()) return 0;
    return components_.back() > 0.0 ? 1 : -1;
  }

  // The value rounded (summed from the smallest component up: within a few ulps).
  double approx() const {
    double sum = 0.0;
    for (double e : components_) sum += e;
    return sum;
  }

 private:
  std::vector<double> components_;  // increasing magnitude, no zeros
};

// Twice the signed area of a loop (shoelace), exactly: positive when counter-clockwise.
inline ExactSum twice_signed_area(const clipper::Loop2& loop) {
  ExactSum sum;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const clipper::Point2& a = loop[i];
    const clipper::Point2& b = loop[(i + 1) % n];
    sum.add_product(a.x, b.y);
    sum.add_product(-b.x, a.y);
  }
  return sum;
}

// Twice the area of a region whatever the orientation of its loops: |outer| minus the
// |holes|, summed over the polygons (the polygons of a well-formed set are disjoint).
inline ExactSum twice_area(const clipper::PolygonSet2& polygons) {
  ExactSum total;
  for (const clipper::PolygonWithHoles2& polygon : polygons) {
    const ExactSum outer = twice_signed_area(polygon.outer);
    total.add(outer, outer.sign());
    for (const clipper::Loop2& hole : polygon.holes) {
      const ExactSum hole_area = twice_signed_area(hole);
      total.add(hole_area, -hole_area.sign());
    }
  }
  return total;
}

}  // namespace shadowgen::fuzz
