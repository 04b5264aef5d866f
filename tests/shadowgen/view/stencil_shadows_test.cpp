// Heidmann's stencil shadow volumes on OpenGL (OSMesa) against the exact answer per pixel:
// a box on a ground under a sun and under a lamp, seen in perspective and orthographic
// views. The reference is computed here, in doubles, with no GL: the 3D point each pixel
// centre's ray (CameraView's own) hits first, and whether the segment from it to the light
// crosses another part. Pixels within one pixel of a change of that answer (a shadow
// boundary, a silhouette, an edge between faces) are not compared; every other pixel must
// agree. The eye in a shadow volume shows Heidmann's z-pass failing and the automatic choice
// (z-fail) right. The paper's own volumes, from silhouette edges only, agree on the closed
// box and lose the shadows of open models, which the per-polygon volumes keep.

#include "shadowgen/view/stencil_shadows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/sampled/part_triangles.h"
#include "shadowgen/view/camera.h"

namespace shadowgen {
namespace {

using glm::dvec3;

Face quad_face(const std::string& id, dvec3 a, dvec3 b, dvec3 c, dvec3 d) {
  Face face;
  face.id = id;
  face.parts.push_back(hsr::Polygon3{{a, b, c, d}, {}});
  return face;
}

// Ground [-6, 6]² at z = 0 facing up; a box [-1, 1]² × [0, 2] on it, faces outward.
Scene box_on_ground() {
  Scene scene;
  const double g = 6.0, s = 1.0, top = 2.0;
  scene.faces.push_back(quad_face("ground", {-g, -g, 0}, {g, -g, 0}, {g, g, 0}, {-g, g, 0}));
  scene.faces.push_back(quad_face("top", {-s, -s, top}, {s, -s, top}, {s, s, top}, {-s, s, top}));
  scene.faces.push_back(quad_face("bottom", {-s, -s, 0}, {-s, s, 0}, {s, s, 0}, {s, -s, 0}));
  scene.faces.push_back(quad_face("east", {s, -s, 0}, {s, s, 0}, {s, s, top}, {s, -s, top}));
  scene.faces.push_back(quad_face("west", {-s, -s, 0}, {-s, -s, top}, {-s, s, top}, {-s, s, 0}));
  scene.faces.push_back(quad_face("north", {-s, s, 0}, {-s, s, top}, {s, s, top}, {s, s, 0}));
  scene.faces.push_back(quad_face("south", {-s, -s, 0}, {s, -s, 0}, {s, -s, top}, {-s, -s, top}));
  return scene;
}

// A ground and a one-sided roof [-2, 2]² at z = 1.5 with a square hole [-0.7, 0.7]²,
// facing down: a part with a hole, an open model, a face turned away from the light.
Scene holed_roof() {
  Scene scene;
  const double g = 6.0;
  scene.faces.push_back(quad_face("ground", {-g, -g, 0}, {g, -g, 0}, {g, g, 0}, {-g, g, 0}));
  Face roof;
  roof.id = "roof";
  // Facing down: the lights above reach its back side only.
  roof.parts.push_back(
      hsr::Polygon3{{{-2, -2, 1.5}, {-2, 2, 1.5}, {2, 2, 1.5}, {2, -2, 1.5}},
                    {{{-0.7, -0.7, 1.5}, {0.7, -0.7, 1.5}, {0.7, 0.7, 1.5}, {-0.7, 0.7, 1.5}}}});
  scene.faces.push_back(roof);
  return scene;
}

// The six faces of the box [lo, hi], outward, their ids `name` and a side.
std::vector<Face> box_faces(const std::string& name, dvec3 lo, dvec3 hi) {
  const dvec3 a{lo.x, lo.y, lo.z}, b{hi.x, lo.y, lo.z}, c{hi.x, hi.y, lo.z}, d{lo.x, hi.y, lo.z};
  const dvec3 e{lo.x, lo.y, hi.z}, f{hi.x, lo.y, hi.z}, g{hi.x, hi.y, hi.z}, h{lo.x, hi.y, hi.z};
  return {quad_face(name + "-top", e, f, g, h),   quad_face(name + "-bottom", a, d, c, b),
          quad_face(name + "-east", b, c, g, f),  quad_face(name + "-west", a, e, h, d),
          quad_face(name + "-north", d, h, g, c), quad_face(name + "-south", a, b, f, e)};
}

// The scene with its ground quad replaced by a closed slab [-6, 6]² × [-0.5, 0]: the
// same picture, and no open model left but what the scene adds.
Scene on_slab(Scene scene) {
  std::erase_if(scene.faces, [](const Face& face) { return face.id == "ground"; });
  const std::vector<Face> slab = box_faces("slab", {-6, -6, -0.5}, {6, 6, 0});
  scene.faces.insert(scene.faces.begin(), slab.begin(), slab.end());
  return scene;
}

// A ground and one quad [-2, 2]² at z = 1.5 facing up, toward the lights: an open model
// whose every edge is a border.
Scene floating_quad() {
  Scene scene;
  const double g = 6.0, s = 2.0, z = 1.5;
  scene.faces.push_back(quad_face("ground", {-g, -g, 0}, {g, -g, 0}, {g, g, 0}, {-g, g, 0}));
  scene.faces.push_back(quad_face("quad", {-s, -s, z}, {s, -s, z}, {s, s, z}, {-s, s, z}));
  return scene;
}

// The box of box_on_ground lifted to [-1, 1]² × [1, 2] and without its bottom: an open
// model, its sides' lower edges borders.
Scene open_box() {
  Scene scene = box_on_ground();
  std::erase_if(scene.faces, [](const Face& face) { return face.id == "bottom"; });
  for (Face& face : scene.faces) {
    if (face.id == "ground") continue;
    for (dvec3& v : face.parts[0].outer) v.z = v.z == 0.0 ? 1.0 : v.z;
  }
  return scene;
}

Light sun(dvec3 direction) {
  Light light;
  light.id = "sun";
  light.type = LightType::kDirectional;
  light.direction = direction;
  return light;
}

Light lamp(dvec3 position) {
  Light light;
  light.id = "lamp";
  light.type = LightType::kPoint;
  light.position = position;
  return light;
}

Camera perspective(dvec3 eye, dvec3 target, double fov) {
  Camera camera;
  camera.eye = eye;
  camera.target = target;
  camera.up = {0, 0, 1};
  camera.fov_deg = fov;
  return camera;
}

Camera orthographic(dvec3 eye, dvec3 target, double pixels_per_unit) {
  Camera camera = perspective(eye, target, 45.0);
  camera.orthographic = true;
  camera.pixels_per_unit = pixels_per_unit;
  return camera;
}

// ---- The exact reference ---------------------------------------------------------------

struct Part {
  std::vector<sampled::Triangle3> triangles;
  dvec3 normal;
};

std::vector<Part> parts_of(const Scene& scene) {
  std::vector<Part> parts;
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& polygon : face.parts) {
      const sampled::PartTriangles t = sampled::part_triangles(polygon);
      parts.push_back({t.triangles, hsr::plane_of(polygon).normal});
    }
  }
  return parts;
}

// The t at which origin + t·direction meets triangle abc, if it does (edges included).
std::optional<double> ray_hits(const dvec3& origin, const dvec3& direction,
                               const sampled::Triangle3& tri) {
  const dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
  const dvec3 h = glm::cross(direction, e2);
  const double det = glm::dot(e1, h);
  if (std::fabs(det) < 1e-14) return std::nullopt;
  const dvec3 s = origin - tri.a;
  const double u = glm::dot(s, h) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  return glm::dot(e2, q) / det;
}

// Per pixel: −1 where no part is seen, else 2·part + lit. Without `shadows` a part facing
// the light is lit whole: the picture of a method that casts no shadow.
std::vector<int> exact_classes(const Scene& scene, const Light& light, const CameraView& view,
                               double t_min, bool shadows = true) {
  const std::vector<Part> parts = parts_of(scene);
  std::vector<int> classes(static_cast<std::size_t>(view.width()) * view.height(), -1);
  for (int y = 0; y < view.height(); ++y) {
    for (int x = 0; x < view.width(); ++x) {
      const hsr::Ray3 ray = view.view().ray_through(view.from_pixels({x + 0.5, y + 0.5}));
      double best = std::numeric_limits<double>::infinity();
      int seen = -1;
      for (std::size_t i = 0; i < parts.size(); ++i) {
        for (const sampled::Triangle3& tri : parts[i].triangles) {
          const std::optional<double> t = ray_hits(ray.origin, ray.direction, tri);
          if (t && *t >= t_min && *t < best) {
            best = *t;
            seen = static_cast<int>(i);
          }
        }
      }
      if (seen < 0) continue;
      const dvec3 p = ray.origin + best * ray.direction;
      const bool point = light.type == LightType::kPoint;
      const dvec3 to_light = point ? light.position - p : -1e4 * glm::normalize(light.direction);
      bool lit = glm::dot(parts[seen].normal, to_light) > 0.0;
      for (std::size_t i = 0; shadows && lit && i < parts.size(); ++i) {
        if (static_cast<int>(i) == seen) continue;
        for (const sampled::Triangle3& tri : parts[i].triangles) {
          const std::optional<double> t = ray_hits(p, to_light, tri);
          if (t && *t > 0.0 && *t <= 1.0) {
            lit = false;
            break;
          }
        }
      }
      classes[static_cast<std::size_t>(y) * view.width() + x] = 2 * seen + (lit ? 1 : 0);
    }
  }
  return classes;
}

struct Comparison {
  int compared = 0, lit = 0, shadowed = 0, wrong = 0;
  int read_lit = 0, read_dark = 0;        // the wrong ones by what the mask says
  std::vector<int> seeing, wrong_seeing;  // compared and wrong, by the part seen
  int first_x = -1, first_y = -1;         // the first pixel wrong
  bool first_expected_lit = false;
};

Comparison compare(const StencilResult& mask, const std::vector<int>& classes) {
  Comparison c;
  const int w = mask.width, h = mask.height;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int mine = classes[static_cast<std::size_t>(y) * w + x];
      bool near_change = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u < 0 || v < 0 || u >= w || v >= h) continue;
          if (classes[static_cast<std::size_t>(v) * w + u] != mine) near_change = true;
        }
      }
      if (near_change) continue;
      ++c.compared;
      if (mine >= 0) {
        c.seeing.resize(std::max<std::size_t>(c.seeing.size(), mine / 2 + 1));
        c.wrong_seeing.resize(c.seeing.size());
        ++c.seeing[mine / 2];
      }
      const bool expected = mine >= 0 && mine % 2 == 1;
      (expected ? c.lit : c.shadowed) += 1;
      if ((mask.lit[static_cast<std::size_t>(y) * w + x] == 1) != expected) {
        (expected ? c.read_dark : c.read_lit) += 1;
        if (mine >= 0) ++c.wrong_seeing[mine / 2];
        if (c.wrong++ == 0) {
          c.first_x = x;
          c.first_y = y;
          c.first_expected_lit = expected;
        }
      }
    }
  }
  return c;
}

constexpr int kWidth = 80, kHeight = 60;

struct Measured {
  StencilResult mask;
  Comparison c;           // against the exact shadows
  Comparison unshadowed;  // against the picture without shadows
};

// The mask of `light` from `camera`, compared with the reference.
Measured measure(const Scene& scene, const Light& light, const Camera& camera, StencilMethod method,
                 StencilVolumes volumes = StencilVolumes::kPerPolygon) {
  const CameraView view(camera, scene, kWidth, kHeight);
  StencilOptions options;
  options.method = method;
  options.volumes = volumes;
  double t_min = view.view().near();
  if (camera.orthographic) {
    options.eye = camera.eye;
    t_min = glm::dot(camera.eye - view.view().eye(), view.view().forward());
  }
  Measured m;
  m.mask = stencil_lit_mask(scene, light, view, options);
  m.c = compare(m.mask, exact_classes(scene, light, view, t_min));
  m.unshadowed = compare(m.mask, exact_classes(scene, light, view, t_min, false));
  return m;
}

// The mask of `light` from `camera` against the reference: every pixel away from a change
// agrees, and the picture has enough of both to mean something.
void expect_exact(const Scene& scene, const Light& light, const Camera& camera,
                  StencilMethod method, bool expect_zfail,
                  StencilVolumes volumes = StencilVolumes::kPerPolygon) {
  const Measured m = measure(scene, light, camera, method, volumes);
  const StencilResult& mask = m.mask;
  ASSERT_EQ(mask.width, kWidth);
  ASSERT_EQ(mask.height, kHeight);
  ASSERT_EQ(mask.lit.size(), static_cast<std::size_t>(kWidth * kHeight));
  EXPECT_EQ(mask.zfail_used, expect_zfail);
  const Comparison& c = m.c;
  EXPECT_GT(c.compared, kWidth * kHeight / 2);
  EXPECT_GT(c.lit, 200);
  EXPECT_GT(c.shadowed, 200);
  EXPECT_EQ(c.wrong, 0) << "of " << c.compared << " compared; first (" << c.first_x << ", "
                        << c.first_y << "), expected " << (c.first_expected_lit ? "lit" : "dark");
}

const dvec3 kSunDirection{1.0, 0.6, -1.2};
const dvec3 kLampPosition{-2.5, -1.5, 4.0};

TEST(StencilShadows, SunInPerspectiveMatchesTheExactShadow) {
  const Scene scene = box_on_ground();
  const Camera camera = perspective({7, -9, 6}, {0.5, 0.5, 0.5}, 50.0);
  expect_exact(scene, sun(kSunDirection), camera, StencilMethod::kAutomatic, false);
  expect_exact(scene, sun(kSunDirection), camera, StencilMethod::kZFail, true);
}

TEST(StencilShadows, LampInPerspectiveMatchesTheExactShadow) {
  const Scene scene = box_on_ground();
  const Camera camera = perspective({7, -9, 6}, {0.5, 0.5, 0.5}, 50.0);
  expect_exact(scene, lamp(kLampPosition), camera, StencilMethod::kAutomatic, false);
  expect_exact(scene, lamp(kLampPosition), camera, StencilMethod::kZFail, true);
}

TEST(StencilShadows, OrthographicViewsMatchTheExactShadow) {
  const Scene scene = box_on_ground();
  const Camera camera = orthographic({6, -8, 10}, {0, 0, 0}, 6.0);
  expect_exact(scene, sun(kSunDirection), camera, StencilMethod::kAutomatic, false);
  expect_exact(scene, lamp(kLampPosition), camera, StencilMethod::kAutomatic, false);
  expect_exact(scene, lamp(kLampPosition), camera, StencilMethod::kZFail, true);
}

TEST(StencilShadows, HolesAndOpenModelsCastTheirShadows) {
  // The roof's hole lets a patch of light onto the ground, and the one-sided roof, turned
  // away from the lights above it, still shadows (as the exact generator has it).
  const Scene scene = holed_roof();
  const Camera camera = perspective({6, -7, 5}, {0, 0, 0}, 60.0);
  expect_exact(scene, sun({0.3, 0.2, -1.0}), camera, StencilMethod::kAutomatic, false);
  expect_exact(scene, lamp({0.2, 0.1, 3.0}), camera, StencilMethod::kAutomatic, false);
}

TEST(StencilShadows, EyeInShadowNeedsZFail) {
  // The sun travels +x as it falls: the box's shadow covers the ground from x = 1 to 3.
  // The eye at (1.8, 0, 0.5) stands in it, looking along +x at the ground: z-pass counts
  // start inside two volumes (the top's and the east side's), so lit and shadowed swap.
  const Scene scene = box_on_ground();
  const Light light = sun({1.0, 0.0, -1.0});
  const Camera camera = perspective({1.8, 0.0, 0.5}, {4.0, 0.0, 0.0}, 60.0);
  expect_exact(scene, light, camera, StencilMethod::kAutomatic, true);

  const CameraView view(camera, scene, kWidth, kHeight);
  StencilOptions zpass;
  zpass.method = StencilMethod::kZPass;
  const StencilResult wrong = stencil_lit_mask(scene, light, view, zpass);
  EXPECT_FALSE(wrong.zfail_used);
  const Comparison c = compare(wrong, exact_classes(scene, light, view, view.view().near()));
  EXPECT_GT(c.wrong, c.compared / 4) << "Heidmann's z-pass with the eye in shadow";
}

TEST(StencilShadows, EyeInALampsShadowNeedsZFail) {
  const Scene scene = box_on_ground();
  const Light light = lamp({-3.0, 0.0, 3.0});
  // The segment from the eye to the lamp crosses the box: the eye is in its volume.
  const Camera camera = perspective({2.0, 0.3, 0.6}, {2.0, -5.0, 0.0}, 60.0);
  expect_exact(scene, light, camera, StencilMethod::kAutomatic, true);

  const CameraView view(camera, scene, kWidth, kHeight);
  StencilOptions zpass;
  zpass.method = StencilMethod::kZPass;
  const Comparison c = compare(stencil_lit_mask(scene, light, view, zpass),
                               exact_classes(scene, light, view, view.view().near()));
  EXPECT_GT(c.wrong, c.compared / 4) << "Heidmann's z-pass with the eye in shadow";
}

// ---- Heidmann's volumes from silhouette edges only ---------------------------------------

// The box alone: six quads sharing their corners, outward normals.
Scene cube() {
  Scene scene = box_on_ground();
  std::erase_if(scene.faces, [](const Face& face) { return face.id == "ground"; });
  return scene;
}

// The vector area of the directed edges seen from the direction `toward`; expects them to
// form closed loops (every vertex left as often as entered).
double loop_area_toward(const std::vector<StencilEdge>& edges, const dvec3& toward) {
  for (const StencilEdge& e : edges) {
    int balance = 0;
    for (const StencilEdge& f : edges) balance += (f.a == e.a) - (f.b == e.a);
    EXPECT_EQ(balance, 0) << e.a.x << ", " << e.a.y << ", " << e.a.z;
  }
  dvec3 area(0.0);
  for (const StencilEdge& e : edges) area += 0.5 * glm::cross(e.a, e.b);
  return glm::dot(area, glm::normalize(toward));
}

TEST(StencilSilhouettes, EdgesOfACube) {
  // From straight above the top faces the sun and the sides see it edge-on: the top's four
  // edges, counter-clockwise seen from the sun, enclosing the top's area 4.
  const std::vector<StencilEdge> above = stencil_silhouette_edges(cube(), sun({0, 0, -1}));
  ASSERT_EQ(above.size(), 4u);
  for (const StencilEdge& e : above) {
    EXPECT_EQ(e.a.z, 2.0);
    EXPECT_EQ(e.b.z, 2.0);
  }
  EXPECT_DOUBLE_EQ(loop_area_toward(above, {0, 0, 1}), 4.0);
  // From a corner the top, east and north faces face it: a skew hexagon, whose area seen
  // from the sun is the cube's shadow outline's, 4 · (1 + 1 + 1) / √3 for sides of 2.
  const dvec3 corner{-1, -1, -1};
  const std::vector<StencilEdge> hexagon = stencil_silhouette_edges(cube(), sun(corner));
  EXPECT_EQ(hexagon.size(), 6u);
  EXPECT_NEAR(loop_area_toward(hexagon, -corner), 12.0 / std::sqrt(3.0), 1e-12);
  // A lamp above the top sees only the top's front: its four edges again.
  EXPECT_EQ(stencil_silhouette_edges(cube(), lamp({0.3, 0.2, 5})).size(), 4u);
  // The ground's edges are borders (one part each), never silhouettes.
  EXPECT_EQ(stencil_silhouette_edges(box_on_ground(), sun(corner)).size(), 6u);
  // Open models: no edge of a lone quad or of a holed roof is shared.
  EXPECT_TRUE(stencil_silhouette_edges(floating_quad(), sun(kSunDirection)).empty());
  EXPECT_TRUE(stencil_silhouette_edges(holed_roof(), sun(kSunDirection)).empty());
  // The bottomless box under a sun from west-south-above: the top's edges to the east and
  // north sides, and the two vertical edges where a side facing the sun (west, south) meets
  // one turned away. The lower edges are borders: an open chain of 4, no loop.
  const std::vector<StencilEdge> open = stencil_silhouette_edges(open_box(), sun(kSunDirection));
  EXPECT_EQ(open.size(), 4u);
  std::size_t vertical = 0;
  for (const StencilEdge& e : open) vertical += e.a.z != e.b.z;
  EXPECT_EQ(vertical, 2u);
}

TEST(StencilSilhouettes, ClosedBoxMatchesTheExactShadow) {
  // The box on a closed slab: no open model in the scene. (The ground quad of
  // box_on_ground is one: see AnOpenGroundSwapsLitAndShadowUnderZFail.)
  const Scene scene = on_slab(box_on_ground());
  const Camera camera = perspective({7, -9, 6}, {0.5, 0.5, 0.5}, 50.0);
  const Camera ortho = orthographic({6, -8, 10}, {0, 0, 0}, 6.0);
  const StencilVolumes kSil = StencilVolumes::kSilhouettes;
  for (const Light& light : {sun(kSunDirection), lamp(kLampPosition)}) {
    SCOPED_TRACE(light.id);
    expect_exact(scene, light, camera, StencilMethod::kAutomatic, false, kSil);
    expect_exact(scene, light, camera, StencilMethod::kZFail, true, kSil);
    expect_exact(scene, light, ortho, StencilMethod::kAutomatic, false, kSil);
    expect_exact(scene, light, ortho, StencilMethod::kZFail, true, kSil);
  }
}

TEST(StencilSilhouettes, EyeInAClosedBoxsShadowNeedsZFail) {
  const Scene scene = on_slab(box_on_ground());
  const StencilVolumes kSil = StencilVolumes::kSilhouettes;
  const Light light = sun({1.0, 0.0, -1.0});
  const Camera camera = perspective({1.8, 0.0, 0.5}, {4.0, 0.0, 0.0}, 60.0);
  expect_exact(scene, light, camera, StencilMethod::kAutomatic, true, kSil);
  const Measured zpass = measure(scene, light, camera, StencilMethod::kZPass, kSil);
  EXPECT_GT(zpass.c.wrong, zpass.c.compared / 4) << "Heidmann's z-pass with the eye in shadow";

  const Camera in_lamp_shadow = perspective({2.0, 0.3, 0.6}, {2.0, -5.0, 0.0}, 60.0);
  expect_exact(scene, lamp({-3.0, 0.0, 3.0}), in_lamp_shadow, StencilMethod::kAutomatic, true,
               kSil);
}

// The index of face `id`'s part among the scene's parts (one part per face).
int part_of(const Scene& scene, const std::string& id) {
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    if (scene.faces[f].id == id) return static_cast<int>(f);
  }
  return -1;
}

// The open models below, seen from the south, low enough to look under the floating ones.
const Camera kOpenModelCamera = perspective({1, -7, 3}, {1, 0.5, 0.5}, 50.0);

std::string counts(const Measured& m) {
  return "wrong " + std::to_string(m.c.wrong) + " (read lit " + std::to_string(m.c.read_lit) +
         ", read dark " + std::to_string(m.c.read_dark) + ") of " + std::to_string(m.c.compared) +
         "; against no shadows " + std::to_string(m.unshadowed.wrong);
}

TEST(StencilSilhouettes, ALoneQuadCastsNoShadow) {
  // A quad facing the lights, over a closed slab: none of its edges is shared, so there is
  // no silhouette edge and no side. z-pass draws nothing: the picture is the one without
  // shadows, the quad's whole shadow reads lit. z-fail draws its caps alone, which leaves
  // the count at -1 on the quad itself (its near cap lies behind it, pushed back, with no
  // side behind to close it): the shadow reads lit and the quad dark, and under the lamp
  // the far cap, drawn at infinity, darkens the pixels it covers elsewhere too.
  const Scene scene = on_slab(floating_quad());
  const int quad = part_of(scene, "quad");
  for (const Light& light : {sun(kSunDirection), lamp(kLampPosition)}) {
    SCOPED_TRACE(light.id);
    for (const StencilMethod method : {StencilMethod::kZPass, StencilMethod::kZFail}) {
      EXPECT_EQ(measure(scene, light, kOpenModelCamera, method).c.wrong, 0);
    }
    const Measured zpass = measure(scene, light, kOpenModelCamera, StencilMethod::kZPass,
                                   StencilVolumes::kSilhouettes);
    EXPECT_EQ(zpass.unshadowed.wrong, 0) << counts(zpass);
    EXPECT_EQ(zpass.c.read_dark, 0) << counts(zpass);
    EXPECT_GT(zpass.c.read_lit, 100) << counts(zpass);

    const Measured zfail = measure(scene, light, kOpenModelCamera, StencilMethod::kZFail,
                                   StencilVolumes::kSilhouettes);
    EXPECT_EQ(zfail.c.read_lit, zpass.c.read_lit) << counts(zfail);
    ASSERT_GT(zfail.unshadowed.wrong_seeing.size(), static_cast<std::size_t>(quad));
    EXPECT_GT(zfail.unshadowed.wrong_seeing[quad], 100) << counts(zfail);
    EXPECT_EQ(zfail.unshadowed.read_lit, 0) << counts(zfail);
    if (light.type == LightType::kDirectional) {
      EXPECT_EQ(zfail.unshadowed.wrong, zfail.unshadowed.wrong_seeing[quad]) << counts(zfail);
    } else {
      EXPECT_GT(zfail.unshadowed.wrong, zfail.unshadowed.wrong_seeing[quad]) << counts(zfail);
    }
  }
}

TEST(StencilSilhouettes, ATurnedAwayRoofCastsNoShadow) {
  // The holed roof faces down, away from the lights above it: no front part, so neither
  // sides nor caps, in z-pass and z-fail alike. The per-polygon volumes take turned-away
  // parts too.
  const Scene scene = on_slab(holed_roof());
  const Camera camera = perspective({6, -7, 5}, {0, 0, 0}, 60.0);
  for (const Light& light : {sun({0.3, 0.2, -1.0}), lamp({0.2, 0.1, 3.0})}) {
    SCOPED_TRACE(light.id);
    for (const StencilMethod method : {StencilMethod::kZPass, StencilMethod::kZFail}) {
      EXPECT_EQ(measure(scene, light, camera, method).c.wrong, 0);
      const Measured m = measure(scene, light, camera, method, StencilVolumes::kSilhouettes);
      EXPECT_EQ(m.unshadowed.wrong, 0) << counts(m);
      EXPECT_EQ(m.c.read_dark, 0) << counts(m);
      EXPECT_GT(m.c.read_lit, 50) << counts(m);
    }
  }
}

TEST(StencilSilhouettes, ABottomlessBoxLosesPartOfItsShadow) {
  // The lifted box without its bottom: its silhouette is an open chain (EdgesOfACube), and
  // the sides its open lower edges would have cast are missing. z-pass counts wrong where
  // an eye ray enters the volume through that gap, so part of the shadow reads lit and the
  // rest stays.
  const Scene scene = on_slab(open_box());
  for (const Light& light : {sun(kSunDirection), lamp(kLampPosition)}) {
    SCOPED_TRACE(light.id);
    EXPECT_EQ(measure(scene, light, kOpenModelCamera, StencilMethod::kZPass).c.wrong, 0);
    const Measured m = measure(scene, light, kOpenModelCamera, StencilMethod::kZPass,
                               StencilVolumes::kSilhouettes);
    EXPECT_EQ(m.c.read_dark, 0) << counts(m);
    EXPECT_GT(m.c.read_lit, 40) << counts(m);
    EXPECT_GT(m.unshadowed.wrong, 40) << counts(m);  // shadowed pixels that stay dark
  }
}

TEST(StencilSilhouettes, AnOpenGroundSwapsLitAndShadowUnderZFail) {
  // The ground quad of box_on_ground faces the sun and has no shared edge. z-pass draws no
  // side for it and is right. z-fail draws its near cap and, under a sun in perspective, no
  // far cap (a point at infinity): every pixel whose ray reaches the ground has its count
  // lowered by one, so on the ground every lit pixel reads dark and the box's shadow lit
  // (and so do the box's faces in front of the ground).
  const Scene scene = box_on_ground();
  const Light light = sun(kSunDirection);
  const StencilVolumes kSil = StencilVolumes::kSilhouettes;
  expect_exact(scene, light, kOpenModelCamera, StencilMethod::kZPass, false, kSil);
  EXPECT_EQ(measure(scene, light, kOpenModelCamera, StencilMethod::kZFail).c.wrong, 0);
  const Measured zfail = measure(scene, light, kOpenModelCamera, StencilMethod::kZFail, kSil);
  const int ground = part_of(scene, "ground");
  EXPECT_GT(zfail.c.read_lit, 40) << counts(zfail);
  EXPECT_GT(zfail.c.seeing[ground], 1000);
  EXPECT_EQ(zfail.c.wrong_seeing[ground], zfail.c.seeing[ground]) << counts(zfail);
}

// ---- The GL transform against CameraView ------------------------------------------------

std::array<double, 4> multiply(const std::array<double, 16>& m, const std::array<double, 4>& v) {
  std::array<double, 4> out{};
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) out[row] += m[col * 4 + row] * v[col];
  }
  return out;
}

void expect_same_pixels(const Scene& scene, const Camera& camera, const Light& light) {
  const CameraView view(camera, scene, kWidth, kHeight);
  StencilOptions options;
  if (camera.orthographic) options.eye = camera.eye;
  const StencilGlCamera gl = stencil_gl_camera(scene, light, view, options);
  const std::vector<dvec3> points{{0, 0, 0},    {1, 1, 2},    {-1, -1, 2},    {-5.5, 4, 0},
                                  {3, -2, 0.7}, {1, -1, 0.1}, {-1.5, 2, 1.5}, {0.3, 0.2, 1.9}};
  for (const dvec3& p : points) {
    const clipper::Point2 expected = view.to_pixels(view.view().project(p));
    const dvec3 d = p - gl.origin;
    const std::array<double, 4> eye = multiply(gl.modelview, {d.x, d.y, d.z, 1.0});
    const std::array<double, 4> clip = multiply(gl.projection, eye);
    ASSERT_GT(clip[3], 0.0);
    const double nx = clip[0] / clip[3], ny = clip[1] / clip[3], nz = clip[2] / clip[3];
    const double wx = 0.5 * (nx + 1.0) * kWidth, wy = 0.5 * (ny + 1.0) * kHeight;
    EXPECT_NEAR(wx, expected.x, 1e-9) << p.x << ", " << p.y << ", " << p.z;
    EXPECT_NEAR(kHeight - wy, expected.y, 1e-9) << p.x << ", " << p.y << ", " << p.z;
    EXPECT_GT(nz, -1.0);  // between the near and far planes
    EXPECT_LT(nz, 1.0);
  }
  EXPECT_TRUE(gl.front_ccw);
  if (!camera.orthographic) {
    // Fitted to the scene, not CameraView's 1e-5 of the diagonal: the depth buffer's bits
    // are spent where the scene is.
    EXPECT_GT(gl.near, 100.0 * view.view().near());
    EXPECT_TRUE(std::isinf(gl.far));
  }
}

TEST(StencilShadows, GlMatricesPutPointsOnCameraViewsPixels) {
  const Scene scene = box_on_ground();
  expect_same_pixels(scene, perspective({7, -9, 6}, {0.5, 0.5, 0.5}, 50.0), sun(kSunDirection));
  expect_same_pixels(scene, orthographic({6, -8, 10}, {0, 0, 0}, 6.0), lamp(kLampPosition));
  // A top-down view with up = +z: CameraView replaces up by +y.
  expect_same_pixels(scene, perspective({0.2, 0.1, 12}, {0.2, 0.1, 0}, 70.0), sun(kSunDirection));
  expect_same_pixels(scene, orthographic({0, 0, 12}, {0.5, 0, 0}, 0.0), sun(kSunDirection));
}

TEST(StencilShadows, AFarOffsetSceneKeepsItsPixels) {
  // The same scene and camera 1e6 away: vertices go to GL relative to the eye.
  Scene scene = box_on_ground();
  const dvec3 shift{1e6, -2e6, 5e5};
  for (Face& face : scene.faces) {
    for (hsr::Polygon3& part : face.parts) {
      for (dvec3& v : part.outer) v += shift;
    }
  }
  Light light = lamp(kLampPosition + shift);
  const Camera camera = perspective(dvec3(7, -9, 6) + shift, dvec3(0.5, 0.5, 0.5) + shift, 50.0);
  expect_exact(scene, light, camera, StencilMethod::kAutomatic, false);
}

TEST(StencilShadows, NothingSeenIsNothingLit) {
  const Scene scene = box_on_ground();
  const CameraView view(perspective({0, 0, 20}, {0, 0, 40}, 40.0), scene, 16, 12);
  const StencilResult mask = stencil_lit_mask(scene, sun(kSunDirection), view);
  for (std::uint8_t v : mask.lit) EXPECT_EQ(v, 0);
}

}  // namespace
}  // namespace shadowgen
