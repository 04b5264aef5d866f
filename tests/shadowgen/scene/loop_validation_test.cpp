// Tests of shadowgen/scene/detail/loop_validation.h: check_loops against the exact
// oracle (tests/support), and the loops it accepts triangulate (clipper/triangulate.h
// takes them as its precondition).

#include "shadowgen/scene/detail/loop_validation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "clipper/polygon.h"
#include "clipper/triangulate.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen {
namespace {

double signed_area(const clipper::Point2& a, const clipper::Point2& b, const clipper::Point2& c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// Loops on a small integer grid: many touching, collinear and crossing configurations.
std::vector<clipper::Loop2> random_grid_loops(std::mt19937& rng) {
  std::vector<clipper::Loop2> loops;
  const int count = 1 + static_cast<int>(rng() % 4);
  for (int l = 0; l < count; ++l) {
    clipper::Loop2 loop;
    const int vertices = 3 + static_cast<int>(rng() % (l == 0 ? 6 : 3));
    const int span = l == 0 ? 9 : 5;
    const int ox = l == 0 ? 0 : static_cast<int>(rng() % 6);
    const int oy = l == 0 ? 0 : static_cast<int>(rng() % 6);
    for (int j = 0; j < vertices; ++j) {
      loop.push_back({static_cast<double>(ox + static_cast<int>(rng() % span)),
                      static_cast<double>(oy + static_cast<int>(rng() % span))});
    }
    loops.push_back(loop);
  }
  return loops;
}

// Whether loops that are each simple make a valid face by areas alone, exactly (CGAL):
// the holes' union is as large as their sum (no overlap) and adding them to the outer
// loop adds nothing (all inside). Loops that cross each other fail one of the two;
// loops that touch or share segments pass both.
bool valid_by_areas(const std::vector<clipper::Loop2>& loops) {
  std::vector<clipper::PolygonSet2> holes;
  double sum = 0.0;
  for (std::size_t h = 1; h < loops.size(); ++h) {
    holes.push_back({{loops[h], {}}});
    sum += std::abs(clipper::signed_area(loops[h]));  // half-integers: exact
  }
  std::vector<clipper::PolygonSet2> all = holes;
  all.push_back({{loops[0], {}}});
  return test::exact_union_area(holes) == sum &&
         test::exact_union_area(all) == std::abs(clipper::signed_area(loops[0]));
}

TEST(LoopValidation, AgreesWithTheExactOracle) {
  // The oracle (tests/support, exact predicates, cross-checked against CGAL) is stricter
  // in four ways the scene format is not: it rejects consecutive repeated vertices, a
  // vertex of one loop inside an edge of another (a touch at a point, which the format
  // allows), a loop through one vertex twice (a pinch, which the format allows when
  // the edges do not cross), and loops that share a segment (which the format allows
  // when holes stay inside the outer loop and apart: LoopCheck::shares_edges). Otherwise
  // the verdicts must agree. Where every loop is simple on its own, the verdict must be
  // the one areas give (valid_by_areas), shared segments or not.
  std::mt19937 rng(11);
  int accepted = 0;
  int rejected = 0;
  int sharing = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::vector<clipper::Loop2> loops = random_grid_loops(rng);
    if (std::any_of(loops.begin(), loops.end(),
                    [](const clipper::Loop2& l) { return clipper::signed_area(l) == 0; })) {
      continue;  // no area: the reader handles those before validation
    }
    std::vector<std::string> names{"outer loop"};
    for (std::size_t h = 1; h < loops.size(); ++h) names.push_back("hole " + std::to_string(h - 1));
    const scene::detail::LoopCheck ours = scene::detail::check_loops(loops, names);
    const clipper::PolygonWithHoles2 polygon{loops[0], {loops.begin() + 1, loops.end()}};
    const std::string theirs = test::validity_problem(test::oriented({polygon})[0]);
    const bool each_simple = std::all_of(loops.begin(), loops.end(), [](const clipper::Loop2& l) {
      return test::validity_problem(test::oriented({{l, {}}})[0]).empty();
    });
    if (each_simple) {
      EXPECT_EQ(!ours.problem, valid_by_areas(loops))
          << "trial " << trial << ": " << ours.problem.value_or("accepted");
    }
    if (!ours.problem && ours.shares_edges) {
      ++sharing;
      EXPECT_NE(theirs, "");  // the oracle refuses loops along each other
    } else if (ours.problem) {
      ++rejected;
      EXPECT_NE(theirs, "") << "we reject (" << *ours.problem << ") what the oracle accepts";
    } else {
      ++accepted;
      // A loop through one point twice without crossing is valid in the format.
      EXPECT_TRUE(theirs.empty() || theirs.find("zero-length edge") != std::string::npos ||
                  theirs.find("lies inside an edge") != std::string::npos ||
                  theirs.find(" twice") != std::string::npos)
          << "we accept what the oracle rejects: " << theirs;
      for (std::size_t l = 0; l < loops.size(); ++l) {
        EXPECT_EQ(ours.counter_clockwise[l], clipper::signed_area(loops[l]) > 0);
      }
    }
    if (HasFailure()) break;
  }
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(rejected, 1000);
  EXPECT_GT(sharing, 0);
}

// An 8 x 8 square with some of its boundary's grid points, either way round.
clipper::Loop2 random_square(std::mt19937& rng) {
  clipper::Loop2 outer;
  for (int i = 0; i < 8; ++i) {
    if (i == 0 || rng() % 2) outer.push_back({static_cast<double>(i), 0});
  }
  for (int i = 0; i < 8; ++i) {
    if (i == 0 || rng() % 2) outer.push_back({8, static_cast<double>(i)});
  }
  for (int i = 8; i > 0; --i) {
    if (i == 8 || rng() % 2) outer.push_back({static_cast<double>(i), 8});
  }
  for (int i = 8; i > 0; --i) {
    if (i == 8 || rng() % 2) outer.push_back({0, static_cast<double>(i)});
  }
  if (rng() % 2) std::reverse(outer.begin(), outer.end());
  return outer;
}

// A rectangle or a triangle on the grid 0..8, either way round: windows and doors that
// often share edges with the square and with each other.
clipper::Loop2 random_opening(std::mt19937& rng) {
  auto coordinate = [&rng] { return static_cast<double>(rng() % 9); };
  clipper::Loop2 loop;
  if (rng() % 3 != 0) {
    const double x0 = coordinate(), y0 = coordinate(), x1 = coordinate(), y1 = coordinate();
    loop = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  } else {
    loop = {
        {coordinate(), coordinate()}, {coordinate(), coordinate()}, {coordinate(), coordinate()}};
  }
  if (rng() % 2) std::reverse(loop.begin(), loop.end());
  return loop;
}

TEST(LoopValidation, HolesSharingEdgesAreValidExactlyWhenTheAreasSaySo) {
  // Holes inside the outer loop and apart, sharing edges with it and each other or not,
  // are valid; any overlap or any part outside is not, whatever touches (valid_by_areas).
  std::mt19937 rng(17);
  int sharing = 0;
  int rejected_sharing = 0;
  for (int trial = 0; trial < 20000 && !HasFailure(); ++trial) {
    std::vector<clipper::Loop2> loops{random_square(rng)};
    const int holes = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < holes; ++k) loops.push_back(random_opening(rng));
    if (std::any_of(loops.begin(), loops.end(),
                    [](const clipper::Loop2& l) { return clipper::signed_area(l) == 0; })) {
      continue;
    }
    std::vector<std::string> names{"outer loop"};
    for (std::size_t h = 1; h < loops.size(); ++h) names.push_back("hole " + std::to_string(h - 1));
    const scene::detail::LoopCheck ours = scene::detail::check_loops(loops, names);
    const bool valid = valid_by_areas(loops);
    EXPECT_EQ(!ours.problem, valid)
        << "trial " << trial << ": " << ours.problem.value_or("accepted");
    if (!ours.problem && ours.shares_edges) ++sharing;
    const std::string theirs =
        test::validity_problem(test::oriented({{loops[0], {loops.begin() + 1, loops.end()}}})[0]);
    if (!valid && theirs.find("along") != std::string::npos) ++rejected_sharing;
  }
  EXPECT_GT(sharing, 1000);
  EXPECT_GT(rejected_sharing, 1000);
}

TEST(Triangulate, RandomHolesTouchingTheBoundaryAndEachOther) {
  std::mt19937 rng(5);
  int triangulated = 0;
  for (int trial = 0; trial < 20000 && !HasFailure(); ++trial) {
    std::vector<clipper::Loop2> loops{random_square(rng)};
    const int holes = 1 + static_cast<int>(rng() % 6);
    for (int k = 0; k < holes; ++k) {
      clipper::Loop2 hole;
      const int vertices = 3 + static_cast<int>(rng() % 2);
      for (int j = 0; j < vertices; ++j) {
        hole.push_back({static_cast<double>(rng() % 9), static_cast<double>(rng() % 9)});
      }
      loops.push_back(hole);
    }
    if (std::any_of(loops.begin(), loops.end(),
                    [](const clipper::Loop2& l) { return clipper::signed_area(l) == 0; })) {
      continue;
    }
    std::vector<std::string> names(loops.size(), "loop");
    const scene::detail::LoopCheck check = scene::detail::check_loops(loops, names);
    if (check.problem || check.shares_edges) continue;  // triangulate's precondition
    ++triangulated;
    const auto triangles = clipper::triangulate(loops);
    ASSERT_TRUE(triangles);
    std::vector<clipper::Point2> all;
    for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
    const double sign = clipper::signed_area(loops[0]) > 0 ? 1.0 : -1.0;
    double sum = 0.0;
    for (const auto& t : *triangles) {
      const double a = sign * signed_area(all[t[0]], all[t[1]], all[t[2]]);
      EXPECT_GE(a, 0.0) << "trial " << trial;
      sum += a;
    }
    double expected = std::abs(clipper::signed_area(loops[0]));
    for (std::size_t h = 1; h < loops.size(); ++h)
      expected -= std::abs(clipper::signed_area(loops[h]));
    EXPECT_EQ(sum, expected) << "trial " << trial;  // half-integers: exact
  }
  EXPECT_GT(triangulated, 1000);
}

}  // namespace
}  // namespace shadowgen
