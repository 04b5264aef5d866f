// Thakur, Cheng and Miura's discretised shadow volumes in angular coordinates
// (shadowgen/view/angular_shadows.h) against Bergeron's shadow volumes counted per pixel
// (pixel_shadows.h, kVolumes: exact for practical purposes): RE loops of a cube; their own
// scene, a grid of closed cubes over a ground, under a point light and a directional light,
// the disagreement shrinking as the table's rows grow; a point light inside the grid (the
// papers' two hemispheres); a concave closed object shading itself; and the papers'
// limitation to closed objects, shown on open models.
//
// Agreement is counted per pixel seen from its front, off boundaries: a pixel is left out
// where its 3 × 3 neighbourhood (clamped at the picture's edge) is not uniform in the face
// seen or in volumes' lit state (view_comparison.h's rule).

#include "shadowgen/view/angular_shadows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowgen/shadows/light_scope.h"
#include "shadowgen/view/detail/angular_span_table.h"
#include "shadowgen/view/detail/ridge_edge_loops.h"
#include "shadowgen/view/pixel_shadows.h"
#include "shadowgen/view/pixel_surfaces.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/shadowgen/view/test_cameras.h"

namespace shadowgen {
namespace {

using test::generated;

constexpr int kWidth = 320;
constexpr int kHeight = 240;

std::string point_text(double x, double y, double z) {
  return "[" + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(z) + "]";
}

std::string polygon(const std::string& id, const std::vector<std::string>& points) {
  std::string text = R"({"id": ")" + id + R"(", "outer": [)";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) text += ",";
    text += points[i];
  }
  return text + "]}";
}

// A closed box [x0,x1] × [y0,y1] × [z0,z1], its six faces turned outward.
std::string box(const std::string& id, double x0, double y0, double z0, double x1, double y1,
                double z1) {
  auto p = point_text;
  return polygon(id + "-top", {p(x0, y0, z1), p(x1, y0, z1), p(x1, y1, z1), p(x0, y1, z1)}) +
         ",\n" +
         polygon(id + "-bottom", {p(x0, y0, z0), p(x0, y1, z0), p(x1, y1, z0), p(x1, y0, z0)}) +
         ",\n" +
         polygon(id + "-south", {p(x0, y0, z0), p(x1, y0, z0), p(x1, y0, z1), p(x0, y0, z1)}) +
         ",\n" +
         polygon(id + "-north", {p(x1, y1, z0), p(x0, y1, z0), p(x0, y1, z1), p(x1, y1, z1)}) +
         ",\n" +
         polygon(id + "-west", {p(x0, y1, z0), p(x0, y0, z0), p(x0, y0, z1), p(x0, y1, z1)}) +
         ",\n" +
         polygon(id + "-east", {p(x1, y0, z0), p(x1, y1, z0), p(x1, y1, z1), p(x1, y0, z1)});
}

std::string scene_json(const std::string& polygons, const std::string& lights) {
  return R"({"format": "shadowgen-scene/1", "polygons": [)" + polygons + R"(], "lights": [)" +
         lights + "]}";
}

const std::string kGround =
    R"({"id": "ground", "outer": [[-10,-10,0],[10,-10,0],[10,10,0],[-10,10,0]]})";

// Thakur's own test scene: a 4 × 4 × 2 grid of closed cubes (side 1.2, every 2.8 units; the
// upper layer floating 1.2 above the lower) over a ground.
std::string cube_grid() {
  std::string text = kGround;
  for (int layer = 0; layer < 2; ++layer) {
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        const double x = -5.0 + 2.8 * i, y = -5.0 + 2.8 * j, z = 2.4 * layer;
        text += ",\n";
        const std::string id = std::to_string(100 * layer + 10 * i + j);
        text += box(id, x, y, z, x + 1.2, y + 1.2, z + 1.2);
      }
    }
  }
  return text;
}

using test::perspective;

struct Figures {
  std::size_t compared = 0, disagreeing = 0, lit = 0, shadowed = 0, boundary = 0;
  std::size_t with_boundaries = 0;  // disagreeing, boundary pixels included
  double share() const {
    return compared ? static_cast<double>(disagreeing) / static_cast<double>(compared) : 0.0;
  }
};

// Angular weights of light `l` against volumes', boundaries left out; `keep` picks pixels.
template <typename Keep>
Figures compare(const Scene& scene, const PixelSurfaces& surfaces, const PixelLitWeights& volumes,
                std::size_t l, const std::vector<double>& angular, Keep&& keep) {
  const Light& light = scene.lights[l];
  Figures f;
  for (int y = 0; y < surfaces.height; ++y) {
    for (int x = 0; x < surfaces.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * surfaces.width + x;
      const PixelSurface& pixel = surfaces.pixels[i];
      if (!pixel.seen() || !pixel.front || !keep(pixel)) continue;
      // Only where the light reaches the front side can a shadow be told.
      const glm::dvec3 to_light =
          light.type == LightType::kPoint ? light.position - pixel.point : -light.direction;
      if (!(glm::dot(pixel.normal, to_light) > 0.0)) continue;
      const bool lit = volumes.at(i, l) >= 0.5;
      if (lit != (angular[i] >= 0.5)) ++f.with_boundaries;
      bool uniform = true;
      for (int dy = -1; dy <= 1 && uniform; ++dy) {
        for (int dx = -1; dx <= 1 && uniform; ++dx) {
          const int nx = std::clamp(x + dx, 0, surfaces.width - 1);
          const int ny = std::clamp(y + dy, 0, surfaces.height - 1);
          const std::size_t j = static_cast<std::size_t>(ny) * surfaces.width + nx;
          uniform = surfaces.pixels[j].face == pixel.face && (volumes.at(j, l) >= 0.5) == lit;
        }
      }
      if (!uniform) {
        ++f.boundary;
        continue;
      }
      ++f.compared;
      (lit ? f.lit : f.shadowed) += 1;
      if (lit != (angular[i] >= 0.5)) ++f.disagreeing;
    }
  }
  return f;
}

Figures compare(const Scene& scene, const PixelSurfaces& surfaces, const PixelLitWeights& volumes,
                std::size_t l, const std::vector<double>& angular) {
  return compare(scene, surfaces, volumes, l, angular, [](const PixelSurface&) { return true; });
}

void report(const std::string& what, const Figures& f) {
  std::printf(
      "[ figures  ] %s: %zu of %zu pixels disagree with volumes (%.3f%%), %zu lit, %zu "
      "shadowed, %zu on boundaries left out (%zu of %zu disagree with them)\n",
      what.c_str(), f.disagreeing, f.compared, 100.0 * f.share(), f.lit, f.shadowed, f.boundary,
      f.with_boundaries, f.compared + f.boundary);
}

TEST(AngularShadows, RidgeEdgeLoopOfACube) {
  // The sun travels (1, 0.6, −1.5): top, west and south visible; bottom, east, north hidden.
  const Scene scene =
      parse_scene(
          scene_json(kGround + ",\n" + box("c", 0, 0, 0, 1, 1, 1),
                     R"({"id": "sun", "type": "directional", "direction": [1, 0.6, -1.5]})"),
          "test.json")
          .scene;
  const ScenePartPlanes parts(scene);
  const std::vector<PartRole> roles = part_roles(parts.polygons, parts.planes, scene.lights[0]);
  const view::detail::RidgeEdgeLoops loops =
      view::detail::ridge_edge_loops(parts.polygons, parts.planes, roles, scene.lights[0]);
  EXPECT_EQ(loops.objects, 2u);  // the ground, the cube
  EXPECT_EQ(loops.count(view::detail::EdgeKind::kRidge), 6u);
  EXPECT_EQ(loops.count(view::detail::EdgeKind::kHidden), 3u);
  EXPECT_EQ(loops.count(view::detail::EdgeKind::kVisible), 3u);
  EXPECT_EQ(loops.count(view::detail::EdgeKind::kOpen), 4u);  // the ground's border
  ASSERT_EQ(loops.loops.size(), 1u);
  EXPECT_TRUE(loops.loops[0].closed);
  EXPECT_EQ(loops.loops[0].vertices.size(), 6u);
  EXPECT_EQ(loops.loops[0].object, loops.object_of_part[1]);

  // Every row of the table: the cube's spans begin and end at ridge crossings, hidden edge
  // crossings (in duplicate) only inside them.
  const view::detail::AngularFrame frame(scene.lights[0], glm::dvec3(0.0));
  const view::detail::AngularSpanTable table(frame, 1, loops, parts.polygons, 50);
  ASSERT_EQ(table.rows(), 50);
  std::size_t hidden_ends = 0;
  for (int k = 0; k < table.rows(); ++k) {
    const auto row = table.row(k);
    ASSERT_FALSE(row.empty()) << k;
    EXPECT_EQ(row.front().end0, view::detail::Crossing::kRidge) << k;
    EXPECT_EQ(row.back().end1, view::detail::Crossing::kRidge) << k;
    for (std::size_t i = 0; i + 1 < row.size(); ++i) {
      EXPECT_EQ(row[i].end1, view::detail::Crossing::kHidden);
      EXPECT_EQ(row[i + 1].end0, view::detail::Crossing::kHidden);
      EXPECT_NEAR(row[i].phi1, row[i + 1].phi0, 1e-12);
      ++hidden_ends;
    }
  }
  EXPECT_GT(hidden_ends, 0u);
}

TEST(AngularShadows, CubeGridAgreesWithVolumesMoreAsRowsGrow) {
  const ShadowedScene shadowed =
      generated(scene_json(cube_grid(),
                           R"({"id": "sun", "type": "directional", "direction": [1, 0.6, -0.9]},
                              {"id": "lamp", "type": "point", "position": [-7, 6, 10]})"));
  const PixelSurfaces surfaces =
      pixel_surfaces(shadowed.scene(), perspective({16, -18, 14}, {0, 0, 1}), kWidth, kHeight);
  const PixelLitWeights volumes =
      pixel_lit_weights(shadowed, surfaces, {PixelShadows::kVolumes, 0});
  for (std::size_t l = 0; l < 2; ++l) {
    double previous = 1.0;
    std::size_t previous_all = static_cast<std::size_t>(-1);
    for (const int resolution : {8, 32, 128, 512, 2048}) {
      const Figures f = compare(
          shadowed.scene(), surfaces, volumes, l,
          angular_lit_weights(shadowed.scene(), shadowed.scene().lights[l], surfaces, resolution));
      report("cube grid, " + shadowed.scene().lights[l].id + ", " + std::to_string(resolution) +
                 " rows",
             f);
      EXPECT_GT(f.lit, 3000u);
      EXPECT_GT(f.shadowed, 1500u);
      EXPECT_LE(f.share(), previous + 1e-12);
      previous = f.share();
      // Boundary pixels included, the disagreement keeps shrinking with the rows.
      EXPECT_LE(f.with_boundaries, previous_all);
      previous_all = f.with_boundaries;
      if (resolution == 32) {
        EXPECT_LE(f.share(), 0.05);
      }
      if (resolution >= 512) {
        EXPECT_LE(f.share(), 0.005);
      }
    }
  }
}

TEST(AngularShadows, PointLightInsideTheGridUsesBothHemispheres) {
  // The lamp between the layers, in the middle of the grid: cubes above and below it.
  const ShadowedScene shadowed = generated(
      scene_json(cube_grid(), R"({"id": "lamp", "type": "point", "position": [-0.8, -0.8, 1.8]})"));
  const PixelSurfaces surfaces =
      pixel_surfaces(shadowed.scene(), perspective({16, -18, 14}, {0, 0, 1}), kWidth, kHeight);
  const PixelLitWeights volumes =
      pixel_lit_weights(shadowed, surfaces, {PixelShadows::kVolumes, 0});
  for (const int resolution : {128, 2048}) {
    const Figures f = compare(
        shadowed.scene(), surfaces, volumes, 0,
        angular_lit_weights(shadowed.scene(), shadowed.scene().lights[0], surfaces, resolution));
    report("lamp inside the grid, " + std::to_string(resolution) + " rows", f);
    EXPECT_GT(f.shadowed, 1500u);
    EXPECT_LE(f.share(), resolution == 128 ? 0.03 : 0.005);
  }
}

TEST(AngularShadows, ConcaveObjectShadesItself) {
  // An L-shaped closed prism, [0,6] × [0,2] ∪ [0,2] × [0,6], 4 high. The sun travels +x and
  // −y as it falls: the arm along y shades the inner wall y = 2 (facing +y) and the roof
  // of the arm along x; nothing else stands in the way.
  auto p = point_text;
  const std::vector<std::array<double, 2>> outline = {{0, 0}, {6, 0}, {6, 2},
                                                      {2, 2}, {2, 6}, {0, 6}};
  std::vector<std::string> top, bottom;
  std::string walls;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % outline.size()];
    top.push_back(p(a[0], a[1], 4));
    bottom.insert(bottom.begin(), p(a[0], a[1], 0));
    walls += ",\n";
    walls += polygon("wall" + std::to_string(i),
                     {p(a[0], a[1], 0), p(b[0], b[1], 0), p(b[0], b[1], 4), p(a[0], a[1], 4)});
  }
  const ShadowedScene shadowed = generated(
      scene_json(kGround + ",\n" + polygon("roof", top) + ",\n" + polygon("floor", bottom) + walls,
                 R"({"id": "sun", "type": "directional", "direction": [1, -0.5, -0.6]})"));
  const Scene& scene = shadowed.scene();
  const ScenePartPlanes parts(scene);
  const std::vector<PartRole> roles = part_roles(parts.polygons, parts.planes, scene.lights[0]);
  const view::detail::RidgeEdgeLoops loops =
      view::detail::ridge_edge_loops(parts.polygons, parts.planes, roles, scene.lights[0]);
  EXPECT_EQ(loops.objects, 2u);
  for (const view::detail::RidgeLoop& loop : loops.loops) EXPECT_TRUE(loop.closed);

  // Seen from the north-east, where the inner walls show.
  const PixelSurfaces surfaces =
      pixel_surfaces(scene, perspective({14, 16, 12}, {2, 2, 1}), kWidth, kHeight);
  const PixelLitWeights volumes =
      pixel_lit_weights(shadowed, surfaces, {PixelShadows::kVolumes, 0});
  const std::vector<double> angular = angular_lit_weights(scene, scene.lights[0], surfaces, 1024);
  auto on_prism = [](const PixelSurface& pixel) { return pixel.face != 0; };
  const Figures self = compare(shadowed.scene(), surfaces, volumes, 0, angular, on_prism);
  report("L prism, its own faces, 1024 rows", self);
  EXPECT_GT(self.shadowed, 300u);  // it shades itself
  EXPECT_GT(self.lit, 300u);       // and does not shade its own lit faces
  EXPECT_LE(self.share(), 0.005);
  const Figures all = compare(shadowed.scene(), surfaces, volumes, 0, angular);
  report("L prism, all, 1024 rows", all);
  EXPECT_LE(all.share(), 0.005);
}

TEST(AngularShadows, OpenModelsFacingTheLightCastNoShadow) {
  // The papers' limitation: closed objects only. Two floating quads under a sun straight
  // down: one facing it (its own object, one visible face, no ridge edge, no hidden face)
  // casts no shadow here; one turned away (a hidden face, its open edges ending its spans)
  // shadows the ground below it as volumes do.
  const ShadowedScene shadowed =
      generated(scene_json(kGround + R"(,
        {"id": "facing", "outer": [[-7,-3,3],[-2,-3,3],[-2,3,3],[-7,3,3]]},
        {"id": "turned-away", "outer": [[2,-3,3],[2,3,3],[7,3,3],[7,-3,3]]})",
                           R"({"id": "sun", "type": "directional", "direction": [0.2, 0.1, -1]})"));
  const PixelSurfaces surfaces =
      pixel_surfaces(shadowed.scene(), perspective({3, -22, 16}, {0, 0, 0}), kWidth, kHeight);
  const PixelLitWeights volumes =
      pixel_lit_weights(shadowed, surfaces, {PixelShadows::kVolumes, 0});
  const std::vector<double> angular =
      angular_lit_weights(shadowed.scene(), shadowed.scene().lights[0], surfaces, 1024);
  auto ground_east = [](const PixelSurface& pixel) { return pixel.face == 0 && pixel.point.x > 0; };
  auto ground_west = [](const PixelSurface& pixel) { return pixel.face == 0 && pixel.point.x < 0; };
  const Figures east = compare(shadowed.scene(), surfaces, volumes, 0, angular, ground_east);
  const Figures west = compare(shadowed.scene(), surfaces, volumes, 0, angular, ground_west);
  report("open quad turned away, ground below", east);
  report("open quad facing the light, ground below", west);
  EXPECT_GT(east.shadowed, 500u);
  EXPECT_EQ(east.disagreeing, 0u);
  // Every shadowed ground pixel under the facing quad is lit here.
  EXPECT_GT(west.shadowed, 500u);
  EXPECT_EQ(west.disagreeing, west.shadowed);
}

TEST(AngularShadows, NoSurfaceBackSideOrTurnedAwayGetZero) {
  const ShadowedScene shadowed =
      generated(scene_json(kGround + ",\n" + box("b", -2, -2, 0, 2, 2, 3),
                           R"({"id": "sun", "type": "directional", "direction": [1, 0.6, -1.5]})"));
  const PixelSurfaces surfaces = pixel_surfaces(
      shadowed.scene(), perspective({16, -18, 14}, {0, 0, 1}, 90.0), kWidth, kHeight);
  const std::vector<double> angular =
      angular_lit_weights(shadowed.scene(), shadowed.scene().lights[0], surfaces, 256);
  std::size_t background = 0;
  for (std::size_t i = 0; i < angular.size(); ++i) {
    const PixelSurface& pixel = surfaces.pixels[i];
    if (!pixel.seen()) ++background;
    // The east face (turned away) is seen from this eye.
    if (!pixel.seen() || !pixel.front || pixel.normal.x > 0.5) {
      EXPECT_EQ(angular[i], 0.0) << i;
    }
  }
  EXPECT_GT(background, 0u);
  EXPECT_THROW(angular_lit_weights(shadowed.scene(), shadowed.scene().lights[0], surfaces, 0),
               std::invalid_argument);
}

}  // namespace
}  // namespace shadowgen
