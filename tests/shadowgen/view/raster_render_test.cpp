// Pictures made pixel by pixel (shadowgen/view/raster_render.h): the three view methods
// against each other on closed boxes under a sun and a lamp, from a perspective and an
// orthographic camera; the eye inside a box's shadow volume (Bergeron's case); an open
// model (floating quads, one facing the sun and one turned away); the surfaces the
// pixels see; the PNG read back with libpng.
//
// Agreement is measured on the lit state per light, pixels within one pixel of a boundary
// left out, by shadowgen/view/view_comparison.h's rule.

#include "shadowgen/view/raster_render.h"

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "shadowgen/view/detail/shadow_volumes.h"
#include "shadowgen/view/pixel_shadows.h"
#include "shadowgen/view/pixel_surfaces.h"
#include "shadowgen/view/png_writer.h"
#include "shadowgen/view/render.h"
#include "shadowgen/view/view_comparison.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/shadowgen/view/cameras.h"
#include "tests/shadowgen/view/test_cameras.h"

namespace shadowgen {
namespace {

using test::generated;

constexpr int kWidth = 96;
constexpr int kHeight = 72;

// A closed box [x0,x1] × [y0,y1] × [z0,z1], its six faces turned outward, as JSON
// polygons "<id>-top", ...
std::string box(const std::string& id, double x0, double y0, double z0, double x1, double y1,
                double z1) {
  auto p = [](double x, double y, double z) {
    return "[" + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(z) + "]";
  };
  auto face = [&](const std::string& name, const std::string& a, const std::string& b,
                  const std::string& c, const std::string& d) {
    return R"({"id": ")" + id + "-" + name + R"(", "outer": [)" + a + "," + b + "," + c + "," + d +
           "]}";
  };
  return face("top", p(x0, y0, z1), p(x1, y0, z1), p(x1, y1, z1), p(x0, y1, z1)) + ",\n" +
         face("bottom", p(x0, y0, z0), p(x0, y1, z0), p(x1, y1, z0), p(x1, y0, z0)) + ",\n" +
         face("south", p(x0, y0, z0), p(x1, y0, z0), p(x1, y0, z1), p(x0, y0, z1)) + ",\n" +
         face("north", p(x1, y1, z0), p(x0, y1, z0), p(x0, y1, z1), p(x1, y1, z1)) + ",\n" +
         face("west", p(x0, y1, z0), p(x0, y0, z0), p(x0, y0, z1), p(x0, y1, z1)) + ",\n" +
         face("east", p(x1, y0, z0), p(x1, y1, z0), p(x1, y1, z1), p(x1, y0, z1));
}

std::string scene_json(const std::string& polygons, const std::string& lights) {
  return R"({"format": "shadowgen-scene/1", "polygons": [)" + polygons + R"(], "lights": [)" +
         lights + "]}";
}

const std::string kGround =
    R"({"id": "ground", "outer": [[-10,-10,0],[10,-10,0],[10,10,0],[-10,10,0]]})";
const std::string kSunAndLamp =
    R"({"id": "sun", "type": "directional", "direction": [1, 0.6, -1.5]},
       {"id": "lamp", "type": "point", "position": [-6, 5, 7]})";

// Closed boxes on a ground under a sun and a lamp.
const ShadowedScene& boxes() {
  static const ShadowedScene shadowed = generated(scene_json(
      kGround + ",\n" + box("a", -5, -4, 0, -1, -1, 3) + ",\n" + box("b", 1, 1, 0, 4, 5, 5),
      kSunAndLamp));
  return shadowed;
}

using test::perspective;

using Agreement = LitAgreement;

// `method`'s lit states against exact's (shadowgen/view/view_comparison.h's rule).
Agreement agreement(const ShadowedScene& shadowed, const PixelSurfaces& surfaces,
                    PixelShadows method, int resolution = 1024) {
  const PixelLitWeights exact = pixel_lit_weights(shadowed, surfaces, {PixelShadows::kExact, 0});
  const PixelLitWeights other = pixel_lit_weights(shadowed, surfaces, {method, resolution});
  return lit_agreement(shadowed, surfaces, exact, other);
}

void Report(const char* what, const Agreement& a) {
  std::printf(
      "[ figures  ] %s: %zu of %zu (pixel, light) pairs disagree (%.4f%%), %zu lit, "
      "%zu shadowed, %zu on boundaries left out\n",
      what, a.disagreeing, a.compared, 100.0 * a.share(), a.lit, a.shadowed, a.boundary);
}

TEST(PixelSurfaces, PixelCentresSeeTheGroundWhereItIs) {
  // Straight down, orthographic, 1 pixel per unit over the 20 × 20 ground: pixel (x, y)'s
  // centre is the ground point (x − 9.5, 9.5 − y) (image y down, world y up).
  Camera camera;
  camera.eye = {0, 0, 10};
  camera.target = {0, 0, 0};
  camera.up = {0, 1, 0};
  camera.orthographic = true;
  camera.pixels_per_unit = 1.0;
  const ShadowedScene shadowed = generated(scene_json(kGround, kSunAndLamp));
  const PixelSurfaces surfaces = pixel_surfaces(shadowed.scene(), camera, 20, 20);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 20; ++x) {
      const PixelSurface& pixel = surfaces.at(x, y);
      ASSERT_TRUE(pixel.seen());
      EXPECT_EQ(pixel.face, 0u);
      EXPECT_TRUE(pixel.front);
      EXPECT_NEAR(pixel.point.x, x - 9.5, 1e-12);
      EXPECT_NEAR(pixel.point.y, 9.5 - y, 1e-12);
      EXPECT_EQ(pixel.point.z, 0.0);
      EXPECT_NEAR(pixel.depth, 10.0, 1e-12);
      EXPECT_EQ(pixel.normal, glm::dvec3(0, 0, 1));
    }
  }
  // From below, the back side.
  camera.eye = {0, 0, -10};
  const PixelSurfaces below = pixel_surfaces(shadowed.scene(), camera, 4, 4);
  EXPECT_TRUE(below.at(1, 1).seen());
  EXPECT_FALSE(below.at(1, 1).front);
}

TEST(PixelSurfaces, SharedEdgeGoesToTheLowerFace) {
  // Two squares meeting along x = 0, pixel centres on that line: the first face wins.
  const ShadowedScene shadowed = generated(scene_json(
      R"({"id": "right", "outer": [[0,-2,0],[2,-2,0],[2,2,0],[0,2,0]]},
         {"id": "left", "outer": [[-2,-2,0],[0,-2,0],[0,2,0],[-2,2,0]]})",
      R"({"id": "sun", "type": "directional", "direction": [0, 0, -1]})"));
  Camera camera;
  camera.eye = {0, 0, 10};  // pixel column 1 has its centres on x = 0
  camera.target = {0, 0, 0};
  camera.up = {0, 1, 0};
  camera.orthographic = true;
  camera.pixels_per_unit = 1.0;
  const PixelSurfaces surfaces = pixel_surfaces(shadowed.scene(), camera, 3, 4);
  for (int y = 0; y < 4; ++y) {
    EXPECT_EQ(surfaces.at(1, y).point.x, 0.0);
    EXPECT_EQ(surfaces.at(1, y).face, 0u) << y;
    EXPECT_EQ(surfaces.at(0, y).face, 1u);
    EXPECT_EQ(surfaces.at(2, y).face, 0u);
  }
}

TEST(PixelShadows, VolumesAndShadowMapsAgreeWithExactOnBoxes) {
  const ShadowedScene& shadowed = boxes();
  const PixelSurfaces surfaces =
      pixel_surfaces(shadowed.scene(), perspective({16, -18, 14}, {0, 0, 1}), kWidth, kHeight);
  const Agreement volumes = agreement(shadowed, surfaces, PixelShadows::kVolumes);
  const Agreement stencil = agreement(shadowed, surfaces, PixelShadows::kStencil);
  Report("boxes, perspective, stencil", stencil);
  EXPECT_EQ(stencil.disagreeing, 0u);
  const Agreement angular = agreement(shadowed, surfaces, PixelShadows::kAngular, 2048);
  Report("boxes, perspective, angular 2048", angular);
  EXPECT_EQ(angular.disagreeing, 0u);
  const Agreement map = agreement(shadowed, surfaces, PixelShadows::kShadowMap, 1024);
  Report("boxes, perspective, volumes", volumes);
  Report("boxes, perspective, shadow-map 1024", map);
  const Agreement coarse = agreement(shadowed, surfaces, PixelShadows::kShadowMap, 128);
  Report("boxes, perspective, shadow-map 128", coarse);
  EXPECT_LE(coarse.share(), 0.05);
  EXPECT_GT(volumes.lit, 1000u);
  EXPECT_GT(volumes.shadowed, 500u);
  EXPECT_EQ(volumes.disagreeing, 0u);
  EXPECT_LE(map.share(), 0.005);
}

TEST(PixelShadows, OrthographicCameraCountsFromEachRaysStart) {
  const ShadowedScene& shadowed = boxes();
  Camera camera;
  camera.eye = {12, -14, 16};
  camera.target = {0, 0, 0};
  camera.orthographic = true;
  const PixelSurfaces surfaces = pixel_surfaces(shadowed.scene(), camera, kWidth, kHeight);
  const Agreement volumes = agreement(shadowed, surfaces, PixelShadows::kVolumes);
  const Agreement map = agreement(shadowed, surfaces, PixelShadows::kShadowMap, 1024);
  const Agreement stencil = agreement(shadowed, surfaces, PixelShadows::kStencil);
  Report("boxes, orthographic, stencil", stencil);
  EXPECT_EQ(stencil.disagreeing, 0u);
  Report("boxes, orthographic, volumes", volumes);
  Report("boxes, orthographic, shadow-map 1024", map);
  EXPECT_GT(volumes.shadowed, 300u);
  EXPECT_EQ(volumes.disagreeing, 0u);
  EXPECT_LE(map.share(), 0.005);
}

TEST(PixelShadows, EyeInsideAShadowVolume) {
  // The sun travels +x and down at 45°; a box 2 wide and 6 tall shades the ground from
  // x = 0 to 6. The eye stands in that shadow, at (1.5, 0, 1), looking at the lit ground
  // beyond it and at the shadow's end.
  const ShadowedScene shadowed =
      generated(scene_json(kGround + ",\n" + box("tower", -2, -1, 0, 0, 1, 6),
                           R"({"id": "sun", "type": "directional", "direction": [1, 0, -1]})"));
  const glm::dvec3 eye(1.5, 0, 1);
  const PixelSurfaces surfaces =
      pixel_surfaces(shadowed.scene(), perspective(eye, {8, 0, 0}, 70), kWidth, kHeight);

  // Bergeron's start count: the eye is inside the volumes of the tower's parts the ray
  // to the sun crosses (its east wall, facing away, and its west wall, facing the sun).
  std::vector<hsr::Polygon3> parts;
  std::vector<hsr::Plane3> planes;
  for (const Face& face : shadowed.scene().faces) {
    parts.push_back(face.parts[0]);
    planes.push_back(hsr::plane_of(face.parts[0]));
  }
  const std::vector<PartRole> roles = part_roles(parts, planes, shadowed.scene().lights[0]);
  const view::detail::ShadowVolumes volumes(shadowed.scene().lights[0], parts, planes, roles,
                                            {{-10, -10, 0}, {10, 10, 6}});
  std::vector<std::string> holding;
  for (const std::size_t part : volumes.holding(eye)) {
    holding.push_back(shadowed.scene().faces[part].id);
  }
  EXPECT_EQ(holding, (std::vector<std::string>{"tower-west", "tower-east"}));

  const Agreement a = agreement(shadowed, surfaces, PixelShadows::kVolumes);
  Report("eye in shadow, volumes", a);
  const Agreement stencil = agreement(shadowed, surfaces, PixelShadows::kStencil);
  Report("eye in shadow, stencil (z-fail)", stencil);
  EXPECT_EQ(stencil.disagreeing, 0u);
  EXPECT_GT(a.lit, 500u);
  EXPECT_GT(a.shadowed, 500u);
  EXPECT_EQ(a.disagreeing, 0u);
}

TEST(PixelShadows, OpenModelFloatingQuads) {
  // No closed solid: a quad facing the sun and one turned away from it, floating.
  const ShadowedScene shadowed =
      generated(scene_json(kGround + R"(,
        {"id": "up", "outer": [[-6,-3,3],[-2,-3,3],[-2,1,3],[-6,1,3]]},
        {"id": "down", "outer": [[2,-2,2],[2,3,2.5],[6,3,2.5],[6,-2,2]]})",
                           R"({"id": "sun", "type": "directional", "direction": [0.5, 0.3, -1]},
         {"id": "lamp", "type": "point", "position": [1, -1, 6]})"));
  const PixelSurfaces surfaces =
      pixel_surfaces(shadowed.scene(), perspective({4, -20, 16}, {0, 0, 0}), kWidth, kHeight);
  const Agreement volumes = agreement(shadowed, surfaces, PixelShadows::kVolumes);
  const Agreement map = agreement(shadowed, surfaces, PixelShadows::kShadowMap, 1024);
  Report("open model, volumes", volumes);
  Report("open model, shadow-map 1024", map);
  const Agreement stencil = agreement(shadowed, surfaces, PixelShadows::kStencil);
  Report("open model, stencil", stencil);
  EXPECT_EQ(stencil.disagreeing, 0u);
  EXPECT_GT(volumes.shadowed, 300u);
  EXPECT_EQ(volumes.disagreeing, 0u);
  EXPECT_LE(map.share(), 0.005);
}

TEST(PixelShadows, NonPlanarPolygonCastsItsTrianglesShadow) {
  // A floating quad with one corner raised 1.5 out of the others' plane: read as two
  // triangles (Bergeron: any polygon, planar or not, bounds a shadow volume of its own).
  const ShadowedScene shadowed =
      generated(scene_json(kGround + R"(,
        {"id": "bent", "outer": [[-4,-3,3],[2,-3,3],[2,2,4.5],[-4,2,3]]})",
                           R"({"id": "sun", "type": "directional", "direction": [0.4, 0.3, -1]},
         {"id": "lamp", "type": "point", "position": [-1, 0, 8]})"));
  ASSERT_EQ(shadowed.scene().faces.back().parts.size(), 2u);
  const PixelSurfaces surfaces =
      pixel_surfaces(shadowed.scene(), perspective({4, -20, 16}, {0, 0, 0}), kWidth, kHeight);
  for (const PixelShadows method : {PixelShadows::kVolumes, PixelShadows::kStencil}) {
    const Agreement a = agreement(shadowed, surfaces, method);
    Report((std::string("non-planar, ") + std::string(pixel_shadows_name(method))).c_str(), a);
    EXPECT_GT(a.shadowed, 300u);
    EXPECT_EQ(a.disagreeing, 0u);
  }
}

TEST(RasterRender, ExactShadesAsTheSvgPictureDoes) {
  const ShadowedScene& shadowed = boxes();
  RasterOptions options;
  options.picture = test::picture_size(kWidth, kHeight);
  const Camera camera = perspective({16, -18, 14}, {0, 0, 1});
  const RgbImage image = render_raster(shadowed, camera, options);
  ASSERT_EQ(image.rgb.size(), 3u * kWidth * kHeight);
  const PixelSurfaces surfaces = pixel_surfaces(shadowed.scene(), camera, kWidth, kHeight);
  const PixelLitWeights lit = pixel_lit_weights(shadowed, surfaces, {});
  std::size_t background = 0, shaded = 0;
  for (std::size_t i = 0; i < surfaces.pixels.size(); ++i) {
    const PixelSurface& pixel = surfaces.pixels[i];
    const std::uint8_t* rgb = image.rgb.data() + 3 * i;
    if (!pixel.seen()) {
      EXPECT_EQ(rgb[0], 255);  // white, the SVG's background
      ++background;
      continue;
    }
    std::vector<std::size_t> lights;
    for (std::size_t l = 0; l < lit.lights; ++l) {
      if (pixel.front && lit.at(i, l) == 1.0) lights.push_back(l);
    }
    const Rgb colour = shade(shadowed.scene(), lights, pixel.point, pixel.normal, options.picture);
    EXPECT_EQ(rgb[0], std::lround(255.0 * colour.r));
    EXPECT_EQ(rgb[1], std::lround(255.0 * colour.g));
    EXPECT_EQ(rgb[2], std::lround(255.0 * colour.b));
    ++shaded;
  }
  EXPECT_GT(background, 100u);
  EXPECT_GT(shaded, 1500u);
}

// The PNG read back with libpng's simplified API.
RgbImage read_png(const std::string& bytes) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  EXPECT_TRUE(png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) << png.message;
  png.format = PNG_FORMAT_RGB;
  RgbImage image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  EXPECT_TRUE(png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr)) << png.message;
  return image;
}

TEST(PngWriter, ReadsBackPixelForPixel) {
  RasterOptions options;
  options.picture = test::picture_size(kWidth, kHeight);
  options.shadows.method = PixelShadows::kVolumes;
  const RgbImage image = render_raster(boxes(), perspective({16, -18, 14}, {0, 0, 1}), options);
  const std::string bytes = png_bytes(image);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const RgbImage back = read_png(bytes);
  EXPECT_EQ(back.width, kWidth);
  EXPECT_EQ(back.height, kHeight);
  EXPECT_EQ(back.rgb, image.rgb);

  RgbImage wrong = image;
  wrong.rgb.pop_back();
  EXPECT_THROW(png_bytes(wrong), std::invalid_argument);
}

TEST(PixelShadows, MethodNames) {
  for (const PixelShadows method :
       {PixelShadows::kExact, PixelShadows::kShadowMap, PixelShadows::kVolumes,
        PixelShadows::kStencil, PixelShadows::kAngular, PixelShadows::kStencilSilhouettes}) {
    EXPECT_EQ(pixel_shadows_named(pixel_shadows_name(method)), method);
  }
  EXPECT_EQ(pixel_shadows_name(PixelShadows::kStencilSilhouettes), "stencil-silhouettes");
  EXPECT_FALSE(pixel_shadows_named("rays"));
}

}  // namespace
}  // namespace shadowgen
