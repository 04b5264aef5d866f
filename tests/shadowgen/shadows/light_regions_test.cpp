// Light-set regions (shadowgen/light_regions.h): hand scenes whose regions are known
// exactly, and on generated scenes the two invariants that define the partition: the
// regions are disjoint and cover the face, and the regions holding a light add up to that
// light's lit area.

#include "shadowgen/shadows/light_regions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <glm/geometric.hpp>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "hsr/area.h"
#include "hsr/plane_chart.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/support/cgal_oracle.h"
#include "tests/support/relative_error.h"

namespace shadowgen {
namespace {

using LightSet = std::vector<std::size_t>;
using test::generated;
using test::kDartUnderRoof;
using test::kTwoLights;
using test::relative_error;

std::size_t face_index(const Scene& scene, const std::string& id) {
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    if (scene.faces[f].id == id) return f;
  }
  ADD_FAILURE() << "no face " << id;
  return 0;
}

std::vector<LightSet> sets_of(const std::vector<LightRegion>& regions) {
  std::vector<LightSet> sets;
  for (const LightRegion& r : regions) sets.push_back(r.lights);
  return sets;
}

double region_area(const std::vector<LightRegion>& regions, const LightSet& set) {
  for (const LightRegion& r : regions) {
    if (r.lights == set) return lit_area(r.polygons);
  }
  return 0.0;
}

// Every polygon of a region lies in the plane of some part of its face (within rounding of
// the lifted crossing points) and faces the same way.
void ExpectInFacePlanes(const Face& face, const std::vector<LightRegion>& regions) {
  double extent = 0.0;
  for (const hsr::Polygon3& part : face.parts) {
    for (const glm::dvec3& p : part.outer) {
      extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
  }
  for (const LightRegion& r : regions) {
    for (const LitPolygon& lit : r.polygons) {
      const hsr::Polygon3& polygon = lit.polygon;
      const hsr::Plane3 own = hsr::plane_of(polygon);
      bool found = false;
      for (const hsr::Polygon3& part : face.parts) {
        const hsr::Plane3 plane = hsr::plane_of(part);
        bool in_plane = glm::dot(own.normal, plane.normal) > 1.0 - 1e-12;
        for (const glm::dvec3& p : polygon.outer) {
          in_plane = in_plane && std::abs(plane.signed_distance(p)) <= 1e-12 * (1.0 + extent);
        }
        found = found || in_plane;
      }
      EXPECT_TRUE(found) << face.id << ": a polygon of region " << r.lights.size()
                         << " lights is off the face's planes or faces the other way";
    }
  }
}

struct Worst {
  double cover = 0.0;           // |Σ regions − face area| / face area
  double lit = 0.0;             // |Σ regions holding l − lit area of l| / face area
  double overlap = 0.0;         // area of pairwise overlaps / face area
  std::size_t faces = 0;        // faces checked
  std::size_t invalid_lit = 0;  // faces left out: a lit polygon outside the clipper's contract
};

// "" when every lit polygon of the face is valid (simple loops, holes inside, ...) in its
// plane's exact chart: the precondition of the clipper, and so of light_regions.
std::string lit_problem(const ShadowedScene& shadowed, std::size_t face) {
  for (std::size_t l = 0; l < shadowed.lit()[face].size(); ++l) {
    for (const LitPolygon& lit : shadowed.lit()[face][l]) {
      const hsr::Polygon3& polygon = lit.polygon;
      const hsr::PlaneChart chart = hsr::chart_facing(hsr::plane_of(polygon).normal);
      clipper::PolygonWithHoles2 p;
      for (const glm::dvec3& v : polygon.outer) p.outer.push_back(chart(v));
      for (const hsr::Loop3& h : polygon.holes) {
        p.holes.emplace_back();
        for (const glm::dvec3& v : h) p.holes.back().push_back(chart(v));
      }
      const std::string problem = test::validity_problem(clipper::normalized({p}));
      if (!problem.empty()) return shadowed.scene().lights[l].id + ": " + problem;
    }
  }
  return "";
}

// The partition's invariants on every face of a shadowed scene whose lit polygons meet the
// clipper's contract (the others are counted in invalid_lit); returns the worst errors.
Worst ExpectPartition(const ShadowedScene& shadowed, double tolerance) {
  Worst worst;
  const Scene& scene = shadowed.scene();
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const Face& face = scene.faces[f];
    if (const std::string problem = lit_problem(shadowed, f); !problem.empty()) {
      ++worst.invalid_lit;
      std::printf("left out: face %s: lit polygon of %s\n", face.id.c_str(), problem.c_str());
      continue;
    }
    ++worst.faces;
    const std::vector<LightRegion> regions = light_regions(shadowed, f);
    const double face_area = hsr::area(face.parts);
    if (face_area == 0.0) {
      EXPECT_TRUE(regions.empty()) << face.id;
      continue;
    }
    // Sets: distinct, ascending, in the contract's order, no empty polygon list.
    for (std::size_t i = 0; i < regions.size(); ++i) {
      EXPECT_FALSE(regions[i].polygons.empty()) << face.id;
      EXPECT_TRUE(std::is_sorted(regions[i].lights.begin(), regions[i].lights.end()));
      EXPECT_TRUE(std::adjacent_find(regions[i].lights.begin(), regions[i].lights.end()) ==
                  regions[i].lights.end());
      for (const std::size_t l : regions[i].lights) EXPECT_LT(l, scene.lights.size());
      if (i > 0) {
        const LightSet& a = regions[i - 1].lights;
        const LightSet& b = regions[i].lights;
        EXPECT_TRUE(a.size() < b.size() || (a.size() == b.size() && a < b))
            << face.id << ": regions out of order";
      }
    }

    double sum = 0.0;
    for (const LightRegion& r : regions) sum += lit_area(r.polygons);
    const double cover = relative_error(sum, face_area);
    EXPECT_LE(cover, tolerance) << face.id << ": regions " << sum << ", face " << face_area;
    worst.cover = std::max(worst.cover, cover);

    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      double with_light = 0.0;
      for (const LightRegion& r : regions) {
        if (std::find(r.lights.begin(), r.lights.end(), l) != r.lights.end()) {
          with_light += lit_area(r.polygons);
        }
      }
      const double lit = lit_area(shadowed.lit()[f][l]);
      const double lit_error = std::abs(with_light - lit) / face_area;
      EXPECT_LE(lit_error, tolerance) << face.id << ", light " << scene.lights[l].id << ": regions "
                                      << with_light << ", lit area " << lit;
      // Relative to the lit area too, unless that is a sliver only rounding made (generation
      // leaves a few of area ~1e-16; the clipper drops such slivers).
      if (lit > 1e-9 * face_area) {
        EXPECT_LE(relative_error(with_light, lit), tolerance)
            << face.id << ", light " << scene.lights[l].id << ": regions " << with_light
            << ", lit area " << lit << ", face " << face_area;
      }
      worst.lit = std::max(worst.lit, lit_error);
    }

    // Disjoint: every polygon valid in its part's exact chart, and no two polygons of the
    // face (of one region or of two) overlap.
    for (const hsr::Polygon3& part : face.parts) {
      const hsr::Plane3 plane = hsr::plane_of(part);
      const hsr::PlaneChart chart = hsr::chart_facing(plane.normal);
      const double scale = std::abs(plane.normal[chart.dropped_axis]);
      std::vector<clipper::PolygonWithHoles2> images;
      for (const LightRegion& r : regions) {
        for (const LitPolygon& lit : r.polygons) {
          const hsr::Polygon3& polygon = lit.polygon;
          if (glm::dot(hsr::plane_of(polygon).normal, plane.normal) < 1.0 - 1e-9) continue;
          clipper::PolygonWithHoles2 p;
          for (const glm::dvec3& v : polygon.outer) p.outer.push_back(chart(v));
          for (const hsr::Loop3& h : polygon.holes) {
            p.holes.emplace_back();
            for (const glm::dvec3& v : h) p.holes.back().push_back(chart(v));
          }
          const clipper::PolygonSet2 normal_form = clipper::normalized({p});
          EXPECT_EQ(normal_form.size(), 1u) << face.id;
          // normalized() drops vertices where a loop runs straight on, among them one where
          // a hole touches the outer loop; after it, such a touch lies inside an edge.
          for (const clipper::PolygonWithHoles2& q : normal_form) {
            EXPECT_EQ(test::validity_problem(q, test::Contacts::kAnyPoint), "") << face.id;
          }
          images.push_back(std::move(p));
        }
      }
      for (std::size_t i = 0; i < images.size(); ++i) {
        for (std::size_t j = i + 1; j < images.size(); ++j) {
          const double overlap =
              clipper::area(clipper::intersection({images[i]}, {images[j]})) / scale / face_area;
          EXPECT_LE(overlap, tolerance) << face.id << ": polygons " << i << " and " << j;
          worst.overlap = std::max(worst.overlap, overlap);
        }
      }
    }
    ExpectInFacePlanes(face, regions);
  }
  return worst;
}

TEST(LightRegions, TwoLightsWithOverlappingShadows) {
  const ShadowedScene s = generated(kTwoLights);
  const std::size_t ground = face_index(s.scene(), "ground");
  const std::vector<LightRegion> regions = light_regions(s, ground);
  ASSERT_EQ(sets_of(regions), (std::vector<LightSet>{{}, {0}, {1}, {0, 1}}));
  // Shadow of both: [3,6] × [3,7]; only "down" reaches [6,7] × [3,7]; only "slant" reaches
  // [2,3] × [3,7]; the rest, 100 − 20, sees both.
  EXPECT_NEAR(region_area(regions, {}), 12.0, 1e-12);
  EXPECT_NEAR(region_area(regions, {0}), 4.0, 1e-12);
  EXPECT_NEAR(region_area(regions, {1}), 4.0, 1e-12);
  EXPECT_NEAR(region_area(regions, {0, 1}), 80.0, 1e-12);
  EXPECT_EQ(light_set_name(s.scene(), regions[3].lights), "down+slant");

  const std::vector<LightRegion> square = light_regions(s, face_index(s.scene(), "square"));
  ASSERT_EQ(sets_of(square), (std::vector<LightSet>{{0, 1}}));
  EXPECT_NEAR(lit_area(square[0].polygons), 16.0, 1e-12);

  EXPECT_EQ(ExpectPartition(s, 1e-12).invalid_lit, 0u);
}

TEST(LightRegions, ResultDoesNotDependOnLightOrderButIndicesFollowIt) {
  std::string swapped = kTwoLights;
  const std::string down = R"({"id": "down", "type": "directional", "direction": [0,0,-1]})";
  const std::string slant = R"({"id": "slant", "type": "directional", "direction": [1,0,-1]})";
  swapped.replace(swapped.find(down), down.size(), "@");
  swapped.replace(swapped.find(slant), slant.size(), down);
  swapped.replace(swapped.find('@'), 1, slant);
  const ShadowedScene s = generated(swapped);
  ASSERT_EQ(s.scene().lights[0].id, "slant");
  const std::vector<LightRegion> regions = light_regions(s, face_index(s.scene(), "ground"));
  ASSERT_EQ(sets_of(regions), (std::vector<LightSet>{{}, {0}, {1}, {0, 1}}));
  EXPECT_NEAR(region_area(regions, {0}), 4.0, 1e-12);  // slant only: [2,3] × [3,7]
  EXPECT_NEAR(region_area(regions, {1}), 4.0, 1e-12);
  EXPECT_EQ(light_set_name(s.scene(), regions[3].lights), "slant+down");
  // The "slant only" region is the strip [2,3] × [3,7] and nothing else.
  ASSERT_EQ(regions[1].polygons.size(), 1u);
  for (const glm::dvec3& p : regions[1].polygons[0].polygon.outer) {
    // Within the strip up to the rounding of generation's back-projection, and in the
    // ground's plane exactly.
    EXPECT_TRUE(p.x >= 2.0 && p.x <= 3.0 + 1e-12 && p.y >= 3.0 && p.y <= 7.0 && p.z == 0.0)
        << p.x << " " << p.y << " " << p.z;
  }
}

TEST(LightRegions, FaceWithAHole) {
  // A 2 × 2 window [4,6]² in the ground; the square over [3,5]² shades 4 − 1 = 3 of it.
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]],
       "holes": [[[4,4,0],[6,4,0],[6,6,0],[4,6,0]]]},
      {"id": "square", "outer": [[3,3,1],[5,3,1],[5,5,1],[3,5,1]]}
    ],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })");
  const std::vector<LightRegion> regions = light_regions(s, face_index(s.scene(), "ground"));
  ASSERT_EQ(sets_of(regions), (std::vector<LightSet>{{}, {0}}));
  EXPECT_NEAR(lit_area(regions[0].polygons), 3.0, 1e-12);
  EXPECT_NEAR(lit_area(regions[1].polygons), 93.0, 1e-12);
  // The lit region keeps the window as a hole or wraps around it: either way no point of
  // the window is inside it, and its area says the window is not counted.
  EXPECT_EQ(light_set_name(s.scene(), regions[0].lights), "shadow");
  EXPECT_EQ(light_set_name(s.scene(), regions[1].lights), "sun");
  EXPECT_EQ(ExpectPartition(s, 1e-12).invalid_lit, 0u);
}

TEST(LightRegions, TriangulatedNonPlanarFace) {
  // Two triangles of area sqrt(14); the roof shades 1/4 of the second (hand_scenes.h).
  const ShadowedScene s = generated(kDartUnderRoof);
  const std::size_t dart = face_index(s.scene(), "dart");
  ASSERT_EQ(s.scene().faces[dart].parts.size(), 2u);
  const std::vector<LightRegion> regions = light_regions(s, dart);
  ASSERT_EQ(sets_of(regions), (std::vector<LightSet>{{}, {0}}));
  const double triangle = std::sqrt(14.0);
  EXPECT_NEAR(lit_area(regions[0].polygons), triangle / 4, 1e-12);
  EXPECT_NEAR(lit_area(regions[1].polygons), triangle * 7 / 4, 1e-12);
  // The lit region has a piece in each triangle's plane, the shadow only in the second's.
  EXPECT_EQ(regions[0].polygons.size(), 1u);
  EXPECT_GE(regions[1].polygons.size(), 2u);
  EXPECT_EQ(ExpectPartition(s, 1e-12).invalid_lit, 0u);
}

TEST(LightRegions, HandBuiltNonPlanarFaceTakesEachLitPolygonToItsOwnPart) {
  // Two triangles of one face meeting along x = 0 at a right angle: "floor" in z = 0,
  // "wall" in x = 0. The lit polygons are given by hand, one per part, listed wall first,
  // each naming its part.
  Scene scene;
  const hsr::Polygon3 floor{{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, {}};
  const hsr::Polygon3 wall{{{0, 0, 0}, {0, 4, 0}, {0, 0, 4}}, {}};
  scene.faces = {Face{"bent", {floor, wall}, "hand.json"}};
  Light light;
  light.id = "sun";
  scene.lights = {light};
  const hsr::Polygon3 lit_floor{{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, {}};  // area 2
  const hsr::Polygon3 lit_wall{{{0, 0, 0}, {0, 4, 0}, {0, 0, 4}}, {}};   // all: 8
  ShadowedScene s(std::move(scene), LitTable({{{{1, lit_wall}, {0, lit_floor}}}}));
  const std::vector<LightRegion> regions = light_regions(s, 0);
  ASSERT_EQ(sets_of(regions), (std::vector<LightSet>{{}, {0}}));
  EXPECT_EQ(lit_area(regions[0].polygons), 6.0);
  EXPECT_EQ(lit_area(regions[1].polygons), 10.0);
  EXPECT_EQ(ExpectPartition(s, 0.0).invalid_lit, 0u);
}

TEST(LightRegions, OneLight) {
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
      {"id": "square", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]]}
    ],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })");
  const std::vector<LightRegion> ground = light_regions(s, 0);
  ASSERT_EQ(sets_of(ground), (std::vector<LightSet>{{}, {0}}));
  EXPECT_EQ(lit_area(ground[0].polygons), 16.0);
  EXPECT_EQ(lit_area(ground[1].polygons), 84.0);
  const std::vector<LightRegion> square = light_regions(s, 1);
  ASSERT_EQ(sets_of(square), (std::vector<LightSet>{{0}}));
  EXPECT_EQ(lit_area(square[0].polygons), 16.0);
  EXPECT_EQ(ExpectPartition(s, 1e-12).invalid_lit, 0u);
}

TEST(LightRegions, ZeroLightsGiveOneShadowRegionPerFace) {
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]],
       "holes": [[[4,4,0],[6,4,0],[6,6,0],[4,6,0]]]}
    ],
    "lights": []
  })");
  const std::vector<LightRegion> regions = light_regions(s, 0);
  ASSERT_EQ(sets_of(regions), (std::vector<LightSet>{{}}));
  ASSERT_EQ(regions[0].polygons.size(), 1u);
  EXPECT_EQ(regions[0].polygons[0].polygon.holes.size(), 1u);
  EXPECT_EQ(lit_area(regions[0].polygons), 96.0);
  EXPECT_EQ(light_set_name(s.scene(), regions[0].lights), "shadow");
}

TEST(LightRegions, FacesWithoutAreaGiveNoRegions) {
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
      {"id": "line", "outer": [[0,0,1],[1,1,1],[2,2,1]]}
    ],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })");
  EXPECT_TRUE(light_regions(s, 1).empty());
  EXPECT_EQ(sets_of(light_regions(s, 0)), (std::vector<LightSet>{{0}}));
}

TEST(LightRegions, BackFacingFaceIsAllShadow) {
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [{"id": "under", "outer": [[0,0,0],[0,1,0],[1,1,0],[1,0,0]]}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })");
  const std::vector<LightRegion> regions = light_regions(s, 0);
  ASSERT_EQ(sets_of(regions), (std::vector<LightSet>{{}}));
  EXPECT_EQ(lit_area(regions[0].polygons), 1.0);
  // Loops keep the face's front: the region's normal is the face's, -z.
  EXPECT_LT(hsr::plane_of(regions[0].polygons[0].polygon).normal.z, 0.0);
}

TEST(LightRegions, BadArgumentsThrow) {
  const ShadowedScene s = generated(kTwoLights);
  EXPECT_THROW(light_regions(s, 2), std::invalid_argument);
}

TEST(LightSetName, JoinsIdsInTheSetsOrder) {
  Scene scene;
  for (const char* id : {"sun", "lamp", "fill"}) {
    Light light;
    light.id = id;
    scene.lights.push_back(light);
  }
  EXPECT_EQ(light_set_name(scene, {}), "shadow");
  const std::vector<std::size_t> one{1}, three{0, 1, 2};
  EXPECT_EQ(light_set_name(scene, one), "lamp");
  EXPECT_EQ(light_set_name(scene, three), "sun+lamp+fill");
}

// Ground, axis-aligned boxes (five faces each, front sides out) at seeded places on a
// 1/8 grid, a tilted holed panel, and five lights: two directional, three point lights,
// one of them among the boxes.
Scene boxes_scene(unsigned seed) {
  std::mt19937 random(seed);
  auto grid = [&random](int lo, int hi) {
    return std::uniform_int_distribution<int>(lo * 8, hi * 8)(random) / 8.0;
  };
  Scene scene;
  auto add = [&scene](std::string id, hsr::Loop3 outer, std::vector<hsr::Loop3> holes = {}) {
    scene.faces.push_back(
        Face{std::move(id), {hsr::Polygon3{std::move(outer), std::move(holes)}}, "boxes.json"});
  };
  add("ground", {{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}});
  for (int b = 0; b < 6; ++b) {
    const double x0 = grid(1, 16), y0 = grid(1, 16);
    const double x1 = x0 + grid(1, 3), y1 = y0 + grid(1, 3), h = grid(1, 4);
    const std::string id = "box" + std::to_string(b);
    add(id + ".top", {{x0, y0, h}, {x1, y0, h}, {x1, y1, h}, {x0, y1, h}});
    add(id + ".x0", {{x0, y0, 0}, {x0, y0, h}, {x0, y1, h}, {x0, y1, 0}});
    add(id + ".x1", {{x1, y0, 0}, {x1, y1, 0}, {x1, y1, h}, {x1, y0, h}});
    add(id + ".y0", {{x0, y0, 0}, {x1, y0, 0}, {x1, y0, h}, {x0, y0, h}});
    add(id + ".y1", {{x0, y1, 0}, {x0, y1, h}, {x1, y1, h}, {x1, y1, 0}});
  }
  // In the plane z = 5 + x/8 + y/16 (exact on these dyadic points).
  auto panel_z = [](double x, double y) { return 5.0 + x / 8 + y / 16; };
  hsr::Loop3 outer, hole;
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{3, 3}, {15, 4}, {14, 12}, {4, 11}}) {
    outer.push_back({x, y, panel_z(x, y)});
  }
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{7, 6}, {7, 8}, {10, 8}, {10, 6}}) {
    hole.push_back({x, y, panel_z(x, y)});
  }
  add("panel", outer, {hole});
  auto light = [&scene](std::string id, LightType type, glm::dvec3 v) {
    Light l;
    l.id = std::move(id);
    l.type = type;
    (type == LightType::kDirectional ? l.direction : l.position) = v;
    scene.lights.push_back(l);
  };
  light("sun", LightType::kDirectional, {-0.3, 0.6, -1.0});
  light("sky", LightType::kDirectional, {0.5, 0.2, -1.0});
  light("lamp", LightType::kPoint, {10, 14, 9});
  light("low", LightType::kPoint, {grid(2, 18), grid(2, 18), 0.75});
  light("side", LightType::kPoint, {-3, 7, 2.5});
  return scene;
}

// The courtyard example (a directional sun and a ranged point lamp, a wall with two
// windows, a canopy with a hole), a room with a point light among the faces, and seeded
// box scenes with five lights.
TEST(LightRegions, PartitionInvariantsOnGeneratedScenes) {
  const ShadowedScene courtyard = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      { "id": "ground", "outer": [[0,0,0],[20,0,0],[20,20,0],[0,20,0]] },
      { "id": "wall-south", "outer": [[4,4,0],[16,4,0],[16,4,3],[4,4,3]],
        "holes": [ [[7,4,1],[9,4,1],[9,4,2],[7,4,2]], [[11,4,1],[13,4,1],[13,4,2],[11,4,2]] ] },
      { "id": "canopy", "outer": [[8,8,2.5],[12,8,2.5],[12,12,2.5],[8,12,2.5]],
        "holes": [ [[9.5,9.5,2.5],[10.5,9.5,2.5],[10.5,10.5,2.5],[9.5,10.5,2.5]] ] }
    ],
    "lights": [
      { "id": "sun", "type": "directional", "direction": [-0.3, 0.6, -1.0] },
      { "id": "lamp", "type": "point", "position": [10, 14, 4],
        "range": { "falloff_start": 5.0, "end": 40.0, "exponent": 2 } }
    ]
  })");
  const Worst a = ExpectPartition(courtyard, 1e-9);
  EXPECT_EQ(a.invalid_lit, 0u);
  const ShadowedScene room = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "floor", "outer": [[0,0,0],[8,0,0],[8,6,0],[0,6,0]]},
      {"id": "wall", "outer": [[0,6,0],[8,6,0],[8,6,4],[0,6,4]],
       "holes": [[[2,6,1],[3,6,1],[3,6,2],[2,6,2]]]},
      {"id": "table", "outer": [[2,2,1],[5,2,1],[5,4,1.2],[2,4,1]]},
      {"id": "shelf", "outer": [[1,5,2],[6,5,2],[6,6,2],[1,6,2]]},
      {"id": "post", "outer": [[6,1,0],[6.5,1,0],[6.5,1,3],[6,1,3]]}
    ],
    "lights": [
      {"id": "sun", "type": "directional", "direction": [0.4, 0.5, -1]},
      {"id": "bulb", "type": "point", "position": [4, 3, 3]},
      {"id": "low", "type": "point", "position": [7, 0.5, 0.5]}
    ]
  })");
  const Worst b = ExpectPartition(room, 1e-9);
  // Generation leaves some lit polygons of the room and of these scenes self-crossing by a
  // rounding (an open defect of the layers below, outside light_regions' contract): those
  // faces are left out and counted; every other face must keep the invariants.
  Worst c;
  for (unsigned seed : {1u, 2u, 3u}) {
    const Worst w = ExpectPartition(generate_shadows(boxes_scene(seed)).shadowed, 1e-9);
    c = {std::max(c.cover, w.cover), std::max(c.lit, w.lit), std::max(c.overlap, w.overlap),
         c.faces + w.faces, c.invalid_lit + w.invalid_lit};
  }
  EXPECT_GT(c.faces, 80u);
  std::printf(
      "worst relative errors: cover %.3g, lit %.3g, overlap %.3g; box scenes: %zu faces "
      "checked, %zu left out\n",
      std::max({a.cover, b.cover, c.cover}), std::max({a.lit, b.lit, c.lit}),
      std::max({a.overlap, b.overlap, c.overlap}), c.faces, c.invalid_lit);
}

}  // namespace
}  // namespace shadowgen
