// clip() at the extremes the architecture names: the random and grid pairs of the
// oracle suite moved 1e6 and 1e8 away from the origin, scaled by 1e-4 and 1e5, and
// sliver triangles of aspect 1e-7; always against CGAL's exact answer for the very
// input the clipper saw (the transformed doubles).
//
// The bound, per case: area_error_bound (tests/support/clip_check.h) derives it from
// clip.h's construction error,
//     B = 2·u·(4ℓ + R)·(per(S) + per(C)),   u = 2^-53,
// ℓ the longest edge, R the largest |vertex| of either operand: each constructed point
// moves at most u·(4ℓ + R), and the pieces' boundaries, at most per(S) + per(C) long,
// carry that displacement into the area. B bounds the inside and outside errors, the
// conservation error (inside + outside = subject) and the mismatch of the two argument
// orders. Relative to the subject's area it is about 2u·R·(per S + per C)/area(S): far
// from the origin R dominates, and 1e8 away an error of 1e-7 of the area is legitimate.
// Our pieces' areas are evaluated exactly, so only the clipper's error is measured. Every
// case must also give valid pieces and not throw.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <numbers>
#include <ostream>
#include <random>
#include <string>

#include "clipper/clip.h"
#include "tests/support/cgal_oracle.h"
#include "tests/support/clip_check.h"
#include "tests/support/expect.h"
#include "tests/support/random_polygons.h"
#include "tests/support/transform.h"

namespace shadowgen::test {
namespace {

using clipper::Loop2;
using clipper::Point2;

constexpr int kPairsPerCase = 500;

using PairMaker = std::function<void(std::mt19937_64&, PolygonSet2&, PolygonSet2&)>;
using Transform = std::function<PolygonSet2(const PolygonSet2&)>;

struct ExtremeCase {
  std::string name;
  PairMaker make_pair;
  Transform transform;
};

// Names the case in gtest's listing (instead of a dump of the object's bytes).
void PrintTo(const ExtremeCase& extreme, std::ostream* out) { *out << extreme.name; }

void RandomPair(std::mt19937_64& rng, PolygonSet2& s, PolygonSet2& c) {
  s = {random_polygon_with_holes(rng)};
  c = {random_polygon_with_holes(rng)};
}

void GridPair(std::mt19937_64& rng, PolygonSet2& s, PolygonSet2& c) {
  s = {random_grid_polygon(rng)};
  c = {random_grid_polygon(rng)};
}

constexpr double kSliverAspect = 1e-7;

void SliverPair(std::mt19937_64& rng, PolygonSet2& s, PolygonSet2& c) {
  s = {sliver_triangle(rng, kSliverAspect)};
  c = {sliver_triangle(rng, kSliverAspect)};
}

void SliverAndPolygon(std::mt19937_64& rng, PolygonSet2& s, PolygonSet2& c) {
  s = {sliver_triangle(rng, kSliverAspect)};
  c = {random_polygon_with_holes(rng)};
}

void PolygonAndSliver(std::mt19937_64& rng, PolygonSet2& s, PolygonSet2& c) {
  s = {random_polygon_with_holes(rng)};
  c = {sliver_triangle(rng, kSliverAspect)};
}

// Two slivers on one base edge (a shared, collinear edge), apexes on the same side at
// different heights and positions, or on opposite sides: nested, crossing or touching
// along the base.
void SliversSharingABase(std::mt19937_64& rng, PolygonSet2& s, PolygonSet2& c) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double angle = 2.0 * std::numbers::pi * unit(rng);
  const double length = 1.0 + unit(rng);
  const Point2 d{std::cos(angle), std::sin(angle)};
  const Point2 a{-0.5 * length * d.x, -0.5 * length * d.y};
  const Point2 b{0.5 * length * d.x, 0.5 * length * d.y};
  auto apex = [&](double height) {
    const double t = (unit(rng) - 0.5) * 0.8 * length;
    return Point2{t * d.x - height * length * d.y, t * d.y + height * length * d.x};
  };
  const double side = unit(rng) < 0.25 ? -1.0 : 1.0;
  PolygonWithHoles2 first{{a, b, apex(kSliverAspect)}, {}};
  PolygonWithHoles2 second{{a, b, apex(side * kSliverAspect * (0.2 + unit(rng)))}, {}};
  randomize_loops(first, rng);
  randomize_loops(second, rng);
  s = {first};
  c = {second};
}

PolygonSet2 Identity(const PolygonSet2& p) { return p; }

class Extremes : public ::testing::TestWithParam<ExtremeCase> {};

TEST_P(Extremes, WithinTheDerivedBound) {
  const ExtremeCase& extreme = GetParam();
  CaseFailures failures(extreme.name);
  int pairs = 0;
  int skipped = 0;
  int overlapping = 0;
  double worst_relative = 0.0;
  double worst_ratio = 0.0;
  double bound_relative_at_worst = 0.0;
  for (int i = 0; i < kPairsPerCase; ++i) {
    std::seed_seq seq{std::uint64_t{0xe7e3}, static_cast<std::uint64_t>(i)};
    std::mt19937_64 rng(seq);
    PolygonSet2 s0;
    PolygonSet2 c0;
    extreme.make_pair(rng, s0, c0);
    const PolygonSet2 subject = extreme.transform(s0);
    const PolygonSet2 clip = extreme.transform(c0);
    // Rounding a transformed coordinate may, rarely, make a touching contact cross: the
    // input then lies outside clip()'s contract (and CGAL's). Counted and printed.
    if (!input_problem(subject).empty() || !input_problem(clip).empty()) {
      ++skipped;
      continue;
    }
    ++pairs;
    const ClipCheck check = check_clip(subject, clip);
    const double bound = area_error_bound(subject, clip);
    failures.record("case-" + std::to_string(i), check.failure(bound, bound), check, subject, clip);
    overlapping += check.exact.inside > 0.0 ? 1 : 0;
    const double error = check.worst_error();
    const double relative = error / check.exact.subject;
    if (relative > worst_relative || std::isnan(relative)) {
      worst_relative = relative;
      bound_relative_at_worst = bound / check.exact.subject;
    }
    worst_ratio = std::max(worst_ratio, error / bound);
  }
  std::printf(
      "%-22s %d pairs (%d overlapping), %d pass, %d fail, %d skipped (input invalid after "
      "rounding); worst relative area error %.3g (its bound %.3g); worst error/bound %.3g\n",
      extreme.name.c_str(), pairs, overlapping, pairs - failures.count(), failures.count(), skipped,
      worst_relative, bound_relative_at_worst, worst_ratio);
  if (failures.count() > 0) std::printf("  failures: %s\n", failures.summary().c_str());
  EXPECT_EQ(failures.count(), 0) << "of " << pairs << " pairs";
  EXPECT_LE(skipped, pairs / 50) << "too many transformed inputs became invalid";
}

// gtest names allow letters, digits and underscores only.
std::string TestName(const ::testing::TestParamInfo<ExtremeCase>& info) {
  std::string name = info.param.name;
  for (char& ch : name) {
    if (ch == '-') ch = '_';
  }
  return name;
}

Transform Offset(double distance) {
  return [distance](const PolygonSet2& p) { return translated(p, {distance, -0.75 * distance}); };
}

Transform Scale(double factor) {
  return [factor](const PolygonSet2& p) { return scaled(p, factor); };
}

INSTANTIATE_TEST_SUITE_P(
    Far, Extremes,
    ::testing::Values(ExtremeCase{"random-offset-1e6", RandomPair, Offset(1e6)},
                      ExtremeCase{"grid-offset-1e6", GridPair, Offset(1e6)},
                      ExtremeCase{"random-offset-1e8", RandomPair, Offset(1e8)},
                      ExtremeCase{"grid-offset-1e8", GridPair, Offset(1e8)}),
    TestName);

INSTANTIATE_TEST_SUITE_P(Scaled, Extremes,
                         ::testing::Values(ExtremeCase{"random-scale-1e-4", RandomPair,
                                                       Scale(1e-4)},
                                           ExtremeCase{"grid-scale-1e-4", GridPair, Scale(1e-4)},
                                           ExtremeCase{"random-scale-1e5", RandomPair, Scale(1e5)},
                                           ExtremeCase{"grid-scale-1e5", GridPair, Scale(1e5)}),
                         TestName);

INSTANTIATE_TEST_SUITE_P(
    Slivers, Extremes,
    ::testing::Values(ExtremeCase{"sliver-sliver", SliverPair, Identity},
                      ExtremeCase{"sliver-polygon", SliverAndPolygon, Identity},
                      ExtremeCase{"polygon-sliver", PolygonAndSliver, Identity},
                      ExtremeCase{"slivers-sharing-base", SliversSharingABase, Identity},
                      ExtremeCase{"sliver-sliver-offset-1e6", SliverPair, Offset(1e6)}),
    TestName);

}  // namespace
}  // namespace shadowgen::test
