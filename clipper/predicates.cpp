#include "clipper/predicates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

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

// A nonoverlapping expansion in increasing magnitude: an exact sum of doubles. Each add
// grows it by at most one term, so N, the number of adds a caller makes, is enough room;
// the terms live on the stack (the exact paths run often enough inside the crossing
// construction that a heap allocation per call showed in profiles).
template <std::size_t N>
class Expansion {
 public:
  // Shewchuk's Grow-Expansion with zero elimination: adds b exactly.
  void add(double b) {
    if (b == 0.0) return;
    std::size_t out = 0;
    double q = b;
    for (std::size_t i = 0; i < size_; ++i) {
      const Pair s = two_sum(q, terms_[i]);
      q = s.hi;
      if (s.lo != 0.0) terms_[out++] = s.lo;
    }
    size_ = out;
    if (q != 0.0) terms_[size_++] = q;
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
  std::span<const double> terms() const { return {terms_.data(), size_}; }
  // The largest component carries the sign of the exact sum.
  double sign() const { return size_ == 0 ? 0.0 : terms_[size_ - 1]; }
  double approximate() const {
    double sum = 0.0;
    for (std::size_t i = 0; i < size_; ++i) sum += terms_[i];
    return sum;
  }

 private:
  std::array<double, N> terms_;
  std::size_t size_ = 0;
};

// 16 adds: four two_diff halves on each side, multiplied out in pairs.
using Determinant = Expansion<16>;

// p·q − r·s, each factor a difference split exactly in two.
Determinant exact_difference_of_products(const Pair& p, const Pair& q, const Pair& r,
                                         const Pair& s) {
  Determinant e;
  if (p.lo == 0.0 && q.lo == 0.0 && r.lo == 0.0 && s.lo == 0.0) {
    // Differences taken exactly, the common case (Sterbenz: coordinates within a factor
    // of two of each other): the loops below would add only these four terms, every
    // other product being zero, so this is the same expansion, term for term.
    const Pair product = two_product(p.hi, q.hi);
    e.add(product.lo);
    e.add(product.hi);
    const Pair negated = two_product(-r.hi, s.hi);
    e.add(negated.lo);
    e.add(negated.hi);
    return e;
  }
  for (double l : {p.hi, p.lo}) {
    for (double m : {q.hi, q.lo}) {
      const Pair product = two_product(l, m);
      e.add(product.lo);
      e.add(product.hi);
    }
  }
  for (double l : {r.hi, r.lo}) {
    for (double m : {s.hi, s.lo}) {
      const Pair product = two_product(-l, m);
      e.add(product.lo);
      e.add(product.hi);
    }
  }
  return e;
}

Determinant exact_determinant(const Point2& a, const Point2& b, const Point2& c) {
  // (b - a) x (c - a) = bax * cay - bay * cax.
  return exact_difference_of_products(two_diff(b.x, a.x), two_diff(c.y, a.y), two_diff(b.y, a.y),
                                      two_diff(c.x, a.x));
}

// The unit roundoff u (orient2d's bound, kOrient2dBound, is in predicates.h).
constexpr double kEpsilon = 0x1p-53;
// Shewchuk's o3derrboundA, the same for the 3x3 determinant.
constexpr double kOrient3Bound = (7.0 + 56.0 * kEpsilon) * kEpsilon;

Orientation to_orientation(double s) {
  return s > 0.0 ? Orientation::kCounterClockwise
                 : (s < 0.0 ? Orientation::kClockwise : Orientation::kCollinear);
}

}  // namespace

Orientation orient2d_exact(const Point2& a, const Point2& b, const Point2& c) {
  // Two of the points the same (faces that share a vertex test it against their edges
  // all the time): one difference is exactly zero, and so is the determinant. The
  // filter cannot tell, its bound being zero too.
  if (a == c || b == c || a == b) return Orientation::kCollinear;
  return to_orientation(exact_determinant(a, b, c).sign());
}

double orient2d_value(const Point2& a, const Point2& b, const Point2& c) {
  return exact_determinant(a, b, c).approximate();
}

int dot_sign(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  // The same shape as orient2d's determinant (two differences, two products, one sum),
  // so the same filter bound holds.
  const double left = (b.x - a.x) * (d.x - c.x);
  const double right = (b.y - a.y) * (d.y - c.y);
  const double dot = left + right;
  const double bound = kOrient2dBound * (std::fabs(left) + std::fabs(right));
  if (dot > bound) return 1;
  if (-dot > bound) return -1;
  // (b − a)·(d − c) = bax * dcx − (−bay) * dcy.
  const Pair bay = two_diff(b.y, a.y);
  const double s = exact_difference_of_products(two_diff(b.x, a.x), two_diff(d.x, c.x),
                                                {-bay.hi, -bay.lo}, two_diff(d.y, c.y))
                       .sign();
  return s > 0.0 ? 1 : (s < 0.0 ? -1 : 0);
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
  // Two of the points the same (a vertex of a mesh tested against the plane of a
  // neighbour that shares it): the determinant is exactly zero, which the filter cannot
  // tell.
  if (d == a || d == b || d == c || a == b || a == c || b == c) return Orientation::kCollinear;
  // The four on a plane square to an axis (a model's flat floor or wall): one column of
  // the determinant is exactly zero.
  for (int k = 0; k < 3; ++k) {
    if (a[k] == d[k] && b[k] == d[k] && c[k] == d[k]) return Orientation::kCollinear;
  }
  // Exact: every difference split in two, the 3x3 determinant expanded into products of
  // three doubles, each added exactly.
  const Pair u[3] = {two_diff(a.x, d.x), two_diff(a.y, d.y), two_diff(a.z, d.z)};
  const Pair v[3] = {two_diff(b.x, d.x), two_diff(b.y, d.y), two_diff(b.z, d.z)};
  const Pair w[3] = {two_diff(c.x, d.x), two_diff(c.y, d.y), two_diff(c.z, d.z)};
  // det = u · (v × w): the six signed permutations of (x, y, z).
  constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                       {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  Expansion<6 * 8 * 4> e;
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

namespace {

// Sign of (a − c) + (b − c) = a + b − 2c. The filter: each of the three roundings is
// within u of its result, so the computed sum is off by at most 3u·(|a − c| + |b − c|)
// (to first order; 4u covers the rest).
int midpoint_sign(double a, double b, double c) {
  const double da = a - c;
  const double db = b - c;
  const double sum = da + db;
  const double bound = 4.0 * kEpsilon * (std::fabs(da) + std::fabs(db));
  if (sum > bound) return 1;
  if (-sum > bound) return -1;
  const Pair ea = two_diff(a, c);
  const Pair eb = two_diff(b, c);
  Expansion<4> e;
  for (double t : {ea.lo, eb.lo, ea.hi, eb.hi}) e.add(t);
  const double s = e.sign();
  return s > 0.0 ? 1 : (s < 0.0 ? -1 : 0);
}

}  // namespace

Orientation orient2d_crossing(const Point2& g0, const Point2& g1, const Point2& e0,
                              const Point2& e1, const Point2& f0, const Point2& f1) {
  // The crossing is X = e0 + t·(e1 − e0) with t = A / (A − B), A = [f0 f1 e0] and
  // B = [f0 f1 e1] of opposite signs. [g0 g1 X] is affine in X, so
  //     [g0 g1 X] = (A·G1 − B·G0) / (A − B),   G0 = [g0 g1 e0], G1 = [g0 g1 e1],
  // and A − B has A's sign. The filter: each determinant is rounded once from its exact
  // value (relative error 2^-52), each product and the difference once more, so the
  // computed numerator is off by less than 4·2^-52·(|A·G1| + |B·G0|) (8 leaves room).
  const Determinant ea = exact_determinant(f0, f1, e0), eb = exact_determinant(f0, f1, e1);
  const Determinant eg0 = exact_determinant(g0, g1, e0), eg1 = exact_determinant(g0, g1, e1);
  const double a = ea.approximate(), b = eb.approximate();
  const double g0v = eg0.approximate(), g1v = eg1.approximate();
  const double left = a * g1v, right = b * g0v;
  const double numerator = left - right;
  const double bound = 16.0 * kEpsilon * (std::fabs(left) + std::fabs(right));
  double sign = 0.0;
  if (numerator > bound || -numerator > bound) {
    sign = numerator;
  } else {
    Expansion<2 * 16 * 16 * 2> e;
    auto add_product = [&e](const Determinant& x, const Determinant& y, double s) {
      for (double xi : x.terms()) {
        for (double yi : y.terms()) {
          const Pair p = two_product(s * xi, yi);
          e.add(p.lo);
          e.add(p.hi);
        }
      }
    };
    add_product(ea, eg1, 1.0);
    add_product(eb, eg0, -1.0);
    sign = e.sign();
  }
  return to_orientation(a > 0.0 ? sign : -sign);
}

Point2 crossing_point_exact(const Point2& a0, const Point2& a1, const Point2& b0,
                            const Point2& b1) {
  // X = (A·a1 − B·a0) / (A − B) with A = [b0 b1 a0] and B = [b0 b1 a1] of opposite
  // signs, both exact; numerators and denominator are exact expansions, each rounded once
  // (relative error below 2u: the largest component dominates a nonoverlapping
  // expansion), then divided.
  const Determinant a = exact_determinant(b0, b1, a0);
  const Determinant b = exact_determinant(b0, b1, a1);
  Expansion<32> denominator;
  for (double t : a.terms()) denominator.add(t);
  for (double t : b.terms()) denominator.add(-t);
  auto coordinate = [&](double at0, double at1) {
    Expansion<64> numerator;
    for (double t : a.terms()) {
      const Pair p = two_product(t, at1);
      numerator.add(p.lo);
      numerator.add(p.hi);
    }
    for (double t : b.terms()) {
      const Pair p = two_product(-t, at0);
      numerator.add(p.lo);
      numerator.add(p.hi);
    }
    return numerator.approximate() / denominator.approximate();
  };
  return {coordinate(a0.x, a1.x), coordinate(a0.y, a1.y)};
}

int compare_x(const Midpoint2& m, double x) { return midpoint_sign(m.a.x, m.b.x, x); }

int compare_y(const Midpoint2& m, double y) { return midpoint_sign(m.a.y, m.b.y, y); }

Orientation orient2d(const Point2& p, const Point2& q, const Midpoint2& m) {
  // 2·(q − p) x (m − p) = (q − p) x ((a − p) + (b − p)). The filter: the differences and
  // the sums are rounded once each (relative error u), the products and the final
  // difference once more, so the error is below 5u·(|dx|·Ty + |dy|·Tx) + u·|det| with
  // T the sums of the absolute differences; 8u·permanent covers it with room to spare.
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double ax = m.a.x - p.x, bx = m.b.x - p.x;
  const double ay = m.a.y - p.y, by = m.b.y - p.y;
  const double left = dx * (ay + by);
  const double right = dy * (ax + bx);
  const double det = left - right;
  const double permanent = std::fabs(dx) * (std::fabs(ay) + std::fabs(by)) +
                           std::fabs(dy) * (std::fabs(ax) + std::fabs(bx));
  const double bound = 8.0 * kEpsilon * permanent;
  if (det > bound || -det > bound) return to_orientation(det);
  const Pair ex = two_diff(q.x, p.x), ey = two_diff(q.y, p.y);
  const Pair sx[2] = {two_diff(m.a.x, p.x), two_diff(m.b.x, p.x)};
  const Pair sy[2] = {two_diff(m.a.y, p.y), two_diff(m.b.y, p.y)};
  Expansion<2 * 2 * 2 * 2 * 2> e;
  auto add_products = [&e](const Pair& l, const Pair(&r)[2], double sign) {
    for (double li : {l.hi, l.lo}) {
      for (const Pair& rp : r) {
        for (double ri : {rp.hi, rp.lo}) {
          const Pair prod = two_product(sign * li, ri);
          e.add(prod.lo);
          e.add(prod.hi);
        }
      }
    }
  };
  add_products(ex, sy, 1.0);
  add_products(ey, sx, -1.0);
  return to_orientation(e.sign());
}

bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  if (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x)) return false;
  if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) return false;
  return orient2d(a, b, p) == Orientation::kCollinear;
}

}  // namespace shadowgen::clipper
