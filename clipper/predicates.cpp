#include "clipper/predicates.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace shadowgen::clipper {
namespace {

// Error-free transformations (Shewchuk 1997; Dekker 1971). With -ffp-contract=off each
// operation below is rounded exactly once, which these identities require.
struct Pair {
  double hi;
  double lo;
};

Pair two_sum(double a, double b) {
  const double s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  return {s, (a - av) + (b - bv)};
}

Pair two_diff(double a, double b) {
  const double d = a - b;
  const double bv = a - d;
  const double av = d + bv;
  return {d, (a - av) + (bv - b)};
}

// std::fma is correctly rounded (in hardware or software), so the error term is exact.
Pair two_product(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

// A nonoverlapping expansion of up to 16 components in increasing magnitude, enough for
// the exact 2x2 determinant of two-component differences.
class Expansion {
 public:
  // Shewchuk's Grow-Expansion with zero elimination: adds b exactly.
  void add(double b) {
    int out = 0;
    double q = b;
    for (int i = 0; i < size_; ++i) {
      const Pair s = two_sum(q, terms_[i]);
      q = s.hi;
      if (s.lo != 0.0) terms_[out++] = s.lo;
    }
    if (q != 0.0 || out == 0) terms_[out++] = q;
    size_ = out;
  }
  // The largest component carries the sign of the exact sum.
  double sign() const { return size_ == 0 ? 0.0 : terms_[size_ - 1]; }
  double approximate() const {
    double sum = 0.0;
    for (int i = 0; i < size_; ++i) sum += terms_[i];
    return sum;
  }

 private:
  std::array<double, 64> terms_{};
  int size_ = 0;
};

Expansion exact_determinant(const Point2& a, const Point2& b, const Point2& c) {
  // (b - a) x (c - a) = bax * cay - bay * cax, each difference split exactly in two.
  const Pair bax = two_diff(b.x, a.x);
  const Pair bay = two_diff(b.y, a.y);
  const Pair cax = two_diff(c.x, a.x);
  const Pair cay = two_diff(c.y, a.y);
  Expansion e;
  for (double l : {bax.hi, bax.lo}) {
    for (double r : {cay.hi, cay.lo}) {
      const Pair p = two_product(l, r);
      e.add(p.lo);
      e.add(p.hi);
    }
  }
  for (double l : {bay.hi, bay.lo}) {
    for (double r : {cax.hi, cax.lo}) {
      const Pair p = two_product(-l, r);
      e.add(p.lo);
      e.add(p.hi);
    }
  }
  return e;
}

// Shewchuk's ccwerrboundA: when |det| exceeds this times the permanent, the rounded
// determinant has the exact sign.
constexpr double kEpsilon = 0x1p-53;
constexpr double kOrientBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;

Orientation to_orientation(double s) {
  return s > 0.0 ? Orientation::kCounterClockwise
                 : (s < 0.0 ? Orientation::kClockwise : Orientation::kCollinear);
}

}  // namespace

Orientation orient2d(const Point2& a, const Point2& b, const Point2& c) {
  const double left = (b.x - a.x) * (c.y - a.y);
  const double right = (b.y - a.y) * (c.x - a.x);
  const double det = left - right;
  const double bound = kOrientBound * (std::fabs(left) + std::fabs(right));
  if (det > bound || -det > bound) return to_orientation(det);
  return to_orientation(exact_determinant(a, b, c).sign());
}

double orient2d_value(const Point2& a, const Point2& b, const Point2& c) {
  return exact_determinant(a, b, c).approximate();
}

bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  if (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x)) return false;
  if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) return false;
  return orient2d(a, b, p) == Orientation::kCollinear;
}

}  // namespace shadowgen::clipper
