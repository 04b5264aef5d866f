// Heidmann's stencil shadow volumes on OpenGL (OSMesa) against the exact answer per pixel:
// a box on a ground under a sun and under a lamp, seen in perspective and orthographic
// views. The reference is computed here, in doubles, with no GL: the 3D point each pixel
// centre's ray (CameraView's own) hits first, and whether the segment from it to the light
// crosses another part. Pixels within one pixel of a change of that answer (a shadow
// boundary, a silhouette, an edge between faces) are not compared; every other pixel must
// agree. The eye in a shadow volume shows Heidmann's z-pass failing and the automatic choice
// (z-fail) right.

#include "shadowgen/view/stencil_shadows.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
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

// Per pixel: −1 where no part is seen, else 2·part + lit.
std::vector<int> exact_classes(const Scene& scene, const Light& light, const CameraView& view,
                               double t_min) {
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
      for (std::size_t i = 0; lit && i < parts.size(); ++i) {
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
  int first_x = -1, first_y = -1;  // the first pixel wrong
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
      const bool expected = mine >= 0 && mine % 2 == 1;
      (expected ? c.lit : c.shadowed) += 1;
      if ((mask.lit[static_cast<std::size_t>(y) * w + x] == 1) != expected) {
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

// The mask of `light` from `camera` against the reference: every pixel away from a change
// agrees, and the picture has enough of both to mean something.
void expect_exact(const Scene& scene, const Light& light, const Camera& camera,
                  StencilMethod method, bool expect_zfail) {
  const CameraView view(camera, scene, kWidth, kHeight);
  StencilOptions options;
  options.method = method;
  double t_min = view.view().near();
  if (camera.orthographic) {
    options.eye = camera.eye;
    t_min = glm::dot(camera.eye - view.view().eye(), view.view().forward());
  }
  const StencilResult mask = stencil_lit_mask(scene, light, view, options);
  ASSERT_EQ(mask.width, kWidth);
  ASSERT_EQ(mask.height, kHeight);
  ASSERT_EQ(mask.lit.size(), static_cast<std::size_t>(kWidth * kHeight));
  EXPECT_EQ(mask.zfail_used, expect_zfail);
  const Comparison c = compare(mask, exact_classes(scene, light, view, t_min));
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
