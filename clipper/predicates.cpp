#include "clipper/predicates.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

// A nonoverlapping expansion in increasing magnitude: an exact sum of doubles. Only the
// rare calls the filters cannot decide get here, so a vector is fine.
class Expansion {
 public:
  Expansion() { terms_.reserve(32); }
  // Shewchuk's Grow-Expansion with zero elimination: adds b exactly.
  void add(double b) {
    std::size_t out = 0;
    double q = b;
    for (double t : terms_) {
      const Pair s = two_sum(q, t);
      q = s.hi;
      if (s.lo != 0.0) terms_[out++] = s.lo;
    }
    terms_.resize(out);
    if (q != 0.0 || terms_.empty()) terms_.push_back(q);
  }
  // Adds the product a·b·c exactly (four terms).
  void add_product(double a, double b, double c) {
    const Pair ab = two_product(a, b);
    const Pair hi = two_product(ab.hi, c);
    const Pair lo = two_product(ab.lo, c);
    add(lo.lo);
    add(lo.hi);
    add(hi.lo);
    add(hi.hi);
  }
  // The largest component carries the sign of the exact sum.
  double sign() const { return terms_.empty() ? 0.0 : terms_.back(); }
  double approximate() const {
    double sum = 0.0;
    for (double t : terms_) sum += t;
    return sum;
  }

 private:
  std::vector<double> terms_;
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
// Shewchuk's o3derrboundA, the same for the 3x3 determinant.
constexpr double kOrient3Bound = (7.0 + 56.0 * kEpsilon) * kEpsilon;

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

Orientation orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                     const glm::dvec3& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  const double bound = kOrient3Bound * permanent;
  if (det > bound || -det > bound) return to_orientation(det);
  // Exact: every difference split in two, the 3x3 determinant expanded into products of
  // three doubles, each added exactly.
  const Pair u[3] = {two_diff(a.x, d.x), two_diff(a.y, d.y), two_diff(a.z, d.z)};
  const Pair v[3] = {two_diff(b.x, d.x), two_diff(b.y, d.y), two_diff(b.z, d.z)};
  const Pair w[3] = {two_diff(c.x, d.x), two_diff(c.y, d.y), two_diff(c.z, d.z)};
  // det = u · (v × w): the six signed permutations of (x, y, z).
  constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                       {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  Expansion e;
  for (int p = 0; p < 6; ++p) {
    const double sign = p < 3 ? 1.0 : -1.0;
    const Pair& x = u[kPermutations[p][0]];
    const Pair& y = v[kPermutations[p][1]];
    const Pair& z = w[kPermutations[p][2]];
    for (double xi : {x.hi, x.lo}) {
      for (double yi : {y.hi, y.lo}) {
        for (double zi : {z.hi, z.lo}) e.add_product(sign * xi, yi, zi);
      }
    }
  }
  return to_orientation(e.sign());
}

bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  if (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x)) return false;
  if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) return false;
  return orient2d(a, b, p) == Orientation::kCollinear;
}

}  // namespace shadowgen::clipper
