// Pictures of the shadowed database (shadowgen/render.h): the pieces' areas against the
// database's lit areas in top-down orthographic views, pieces that never overlap and
// cover the image of the visible faces, cameras inside a closed box and next to a face
// crossing the near plane, back sides, and the shading formula.

#include "shadowgen/view/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "clipper/clip.h"
#include "shadowgen/output/report.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/picture_raster.h"
#include "shadowgen/view/raster_render.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/shadowgen/view/cameras.h"
#include "tests/support/cgal_oracle.h"
#include "tests/support/relative_error.h"

namespace shadowgen {
namespace {

using test::generated;
using test::looking_down;
using test::picture_size;
using test::relative_error;

bool contains(const std::vector<std::size_t>& set, std::size_t light) {
  return std::find(set.begin(), set.end(), light) != set.end();
}

double pieces_area(const Picture& picture) {
  double sum = 0.0;
  for (const Piece& piece : picture.pieces) sum += clipper::area(piece.shape);
  return sum;
}

// Every pair of pieces overlaps by no more than `tolerance` square pixels.
void ExpectNoOverlap(const Picture& picture, double tolerance) {
  const std::vector<Piece>& pieces = picture.pieces;
  for (std::size_t a = 0; a < pieces.size(); ++a) {
    for (std::size_t b = a + 1; b < pieces.size(); ++b) {
      const double overlap =
          clipper::area(clipper::intersection({pieces[a].shape}, {pieces[b].shape}));
      EXPECT_LE(overlap, tolerance)
          << "pieces " << a << " (" << pieces[a].face_id << ", " << pieces[a].light_set << ") and "
          << b << " (" << pieces[b].face_id << ", " << pieces[b].light_set << ")";
    }
  }
}

// Every piece vertex lies within the picture.
void ExpectInsidePicture(const Picture& picture) {
  const double slack = 1e-9 * std::max(picture.width, picture.height);
  for (const Piece& piece : picture.pieces) {
    for (const clipper::Point2& p : piece.shape.outer) {
      EXPECT_GE(p.x, -slack);
      EXPECT_GE(p.y, -slack);
      EXPECT_LE(p.x, picture.width + slack);
      EXPECT_LE(p.y, picture.height + slack);
    }
  }
}

// A perspective camera as camera.h documents it, written out here so that the expected
// pictures owe nothing to hsr's view or hsr::project_polygon: a pinhole at `eye` looking
// along forward = normalize(target − eye), right = normalize(forward × up), the image's up
// = right × forward. A point at offset d from the eye lands at
// (right·d, up·d) / (forward·d) on the image plane at distance 1, whose
// |y| <= tan(fov/2) spans the picture's height; pixels are square, pixel y points down
// and (0, 0) is the top-left corner.
class Pinhole {
 public:
  Pinhole(const Camera& camera, int width, int height)
      : eye_(camera.eye),
        forward_(glm::normalize(camera.target - camera.eye)),
        right_(glm::normalize(glm::cross(forward_, camera.up))),
        up_(glm::cross(right_, forward_)),
        scale_(0.5 * height / std::tan(0.5 * camera.fov_deg * std::numbers::pi / 180.0)),
        centre_{0.5 * width, 0.5 * height} {}

  const glm::dvec3& eye() const { return eye_; }
  double depth(const glm::dvec3& p) const { return glm::dot(forward_, p - eye_); }

  clipper::Point2 pixel(const glm::dvec3& p) const {
    const glm::dvec3 d = p - eye_;
    const double z = glm::dot(forward_, d);
    return {centre_.x + scale_ * glm::dot(right_, d) / z,
            centre_.y - scale_ * glm::dot(up_, d) / z};
  }

  // The direction of the ray from the eye through a pixel: its points are
  // eye + t · ray(pixel), t > 0, and every one of them lands on that pixel.
  glm::dvec3 ray(const clipper::Point2& pixel) const {
    return forward_ + ((pixel.x - centre_.x) / scale_) * right_ -
           ((pixel.y - centre_.y) / scale_) * up_;
  }

 private:
  glm::dvec3 eye_, forward_, right_, up_;
  double scale_;
  clipper::Point2 centre_;
};

// Even-odd point-in-polygon over every loop (so holes count).
bool covers(const clipper::PolygonWithHoles2& polygon, const clipper::Point2& q) {
  bool inside = false;
  auto cross_loop = [&](const clipper::Loop2& loop) {
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      const clipper::Point2& a = loop[i];
      const clipper::Point2& b = loop[j];
      if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
        inside = !inside;
      }
    }
  };
  cross_loop(polygon.outer);
  for (const clipper::Loop2& hole : polygon.holes) cross_loop(hole);
  return inside;
}

double distance_to_segment(const clipper::Point2& q, const clipper::Point2& a,
                           const clipper::Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  const double t =
      length2 > 0.0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(q.x - (a.x + t * dx), q.y - (a.y + t * dy));
}

double distance_to_boundary(const clipper::PolygonWithHoles2& polygon, const clipper::Point2& q) {
  double best = std::numeric_limits<double>::infinity();
  auto visit = [&](const clipper::Loop2& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      best = std::min(best, distance_to_segment(q, loop[i], loop[(i + 1) % loop.size()]));
    }
  };
  visit(polygon.outer);
  for (const clipper::Loop2& hole : polygon.holes) visit(hole);
  return best;
}

// Where the ray eye + t·direction (t > 0) first meets the planar part, if it does.
std::optional<double> ray_hits(const glm::dvec3& eye, const glm::dvec3& direction,
                               const hsr::Polygon3& part) {
  const hsr::Loop3& outer = part.outer;
  glm::dvec3 normal(0.0);  // Newell's normal
  for (std::size_t i = 0; i < outer.size(); ++i) {
    normal += glm::cross(outer[i], outer[(i + 1) % outer.size()]);
  }
  const double along = glm::dot(normal, direction);
  if (along == 0.0) return std::nullopt;
  const double t = glm::dot(normal, outer[0] - eye) / along;
  if (!(t > 0.0)) return std::nullopt;
  const glm::dvec3 hit = eye + t * direction;
  // Drop the normal's largest coordinate: the part's loops stay polygons in the plane.
  const glm::dvec3 n = glm::abs(normal);
  const int drop = n.z >= n.x && n.z >= n.y ? 2 : (n.y >= n.x ? 1 : 0);
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  auto flat = [&](const hsr::Loop3& loop) {
    clipper::Loop2 out;
    for (const glm::dvec3& p : loop) out.push_back({p[i], p[j]});
    return out;
  };
  clipper::PolygonWithHoles2 chart{flat(outer), {}};
  for (const hsr::Loop3& hole : part.holes) chart.holes.push_back(flat(hole));
  if (!covers(chart, {hit[i], hit[j]})) return std::nullopt;
  return t;
}

// A 10 × 10 ground, a horizontal 4 × 4 occluder at z = 1 and a tilted one, a slanting sun
// and a lamp with a range: shadows of both lights overlap on the ground.
constexpr const char* kGroundScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "roof", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]],
     "holes": [[[3,4,1],[3,5,1],[4,5,1],[4,4,1]]]},
    {"id": "slab", "outer": [[6,6,0.5],[9,6,0.8],[9,9,1.4],[6,9,0.9]]}
  ],
  "lights": [
    {"id": "sun", "type": "directional", "direction": [0.3, 0.2, -1]},
    {"id": "lamp", "type": "point", "position": [7, 2, 3],
     "range": {"falloff_start": 2, "end": 30, "exponent": 2}}
  ]
})";

TEST(Render, TopDownOrthographicLitAreasEqualTheDatabase) {
  const ShadowedScene shadowed = generated(kGroundScene);
  const std::vector<ReportRow> rows = report_rows(shadowed);
  // Below the occluders (z = 0.25), so that nothing hides the ground: its visible image is
  // all of it, and the lit pieces must add up to its lit area.
  const Camera camera = looking_down({5, 5, 0.25}, {5, 5, 0}, 37.5);
  const RenderOptions options = picture_size(400, 400);
  const Picture picture = render(shadowed, camera, options);
  const double s2 = camera.pixels_per_unit * camera.pixels_per_unit;
  ASSERT_FALSE(picture.pieces.empty());
  EXPECT_EQ(picture.stats.hsr.input_polygons, 1u);  // the occluders are cut away

  double ground = 0.0;
  for (const Piece& piece : picture.pieces) {
    EXPECT_EQ(piece.face_id, "ground");
    EXPECT_FALSE(piece.back_side);
    ground += clipper::area(piece.shape);
  }
  EXPECT_LE(relative_error(ground / s2, 100.0), 1e-12);
  for (const ReportRow& row : rows) {
    if (shadowed.scene().faces[row.face].id != "ground") continue;
    double lit = 0.0;
    for (const Piece& piece : picture.pieces) {
      if (contains(piece.lights, row.light)) lit += clipper::area(piece.shape);
    }
    ASSERT_GT(row.lit_area, 0.0);
    ASSERT_LT(row.lit_area, 100.0);
    EXPECT_LE(relative_error(lit / s2, row.lit_area), 1e-9)
        << shadowed.scene().lights[row.light].id << ": " << lit / s2 << " vs " << row.lit_area;
  }
  ExpectNoOverlap(picture, 1e-9 * options.width * options.height);
  ExpectInsidePicture(picture);
}

// A ground lit around a hole per occluder (test::ground_under_slabs): the sun's region on
// the ground is one polygon of over 256 vertices, whose image the picture cuts into tiles
// before clipping the ground's fragments by it. The pieces' lit area is the database's,
// and every pixel is lit or shadowed as the exact lit polygons say there (render_raster,
// which never reads the picture's pieces).
TEST(Render, AGroundWithAHolePerOccluderIsDrawnAsItsLitPolygonSays) {
  const ShadowedScene shadowed = generated(test::ground_under_slabs());
  ASSERT_EQ(shadowed.scene().faces[0].id, "ground");
  const std::vector<LitPolygon>& lit = shadowed.lit().at(0, 0);
  ASSERT_EQ(lit.size(), 1u);
  std::size_t vertices = lit[0].polygon.outer.size();
  for (const hsr::Loop3& hole : lit[0].polygon.holes) vertices += hole.size();
  ASSERT_EQ(lit[0].polygon.holes.size(), 144u);
  ASSERT_GT(vertices, 256u);

  // Below the slabs, so that nothing hides the ground, which the picture holds whole with
  // a border of background; a scale that puts no pixel's centre on a shadow's edge.
  const Camera camera = looking_down({18, 18, 1}, {18, 18, 0}, 9.73);
  const RenderOptions options = picture_size(352, 352);
  const Picture picture = render(shadowed, camera, options);
  const double s2 = camera.pixels_per_unit * camera.pixels_per_unit;
  double lit_area = 0.0;
  for (const Piece& piece : picture.pieces) {
    if (!piece.lights.empty()) lit_area += clipper::area(piece.shape);
  }
  EXPECT_LE(relative_error(lit_area / s2, report_rows(shadowed)[0].lit_area), 1e-9);
  ExpectNoOverlap(picture, 1e-9 * options.width * options.height);

  RasterOptions raster;
  raster.picture = options;
  const RgbImage exact = render_raster(shadowed, camera, raster);
  const RgbImage drawn = rasterize_picture(picture);
  ASSERT_EQ(drawn.rgb.size(), exact.rgb.size());
  // The ground's two colours, the sun's and the shadow's, as 8-bit values.
  auto bytes = [&](const std::vector<std::size_t>& lights) {
    const Rgb c = shade(shadowed.scene(), lights, {0, 0, 0}, {0, 0, 1}, options);
    return std::array<long, 3>{std::lround(255.0 * c.r), std::lround(255.0 * c.g),
                               std::lround(255.0 * c.b)};
  };
  const std::array<long, 3> sunlit = bytes({0}), shaded = bytes({});
  std::size_t differing = 0, in_sun = 0, in_shadow = 0, background = 0;
  for (std::size_t i = 0; i < exact.rgb.size(); i += 3) {
    const std::array<long, 3> e{exact.rgb[i], exact.rgb[i + 1], exact.rgb[i + 2]};
    const std::array<long, 3> d{drawn.rgb[i], drawn.rgb[i + 1], drawn.rgb[i + 2]};
    differing += e != d;
    in_sun += d == sunlit;
    in_shadow += d == shaded;
    background += d == std::array<long, 3>{255, 255, 255};
  }
  EXPECT_EQ(differing, 0u);
  // 144 shadows of 1.2 × 1.1 at 9.73² pixels a square unit, the rest in the sun.
  EXPECT_NEAR(static_cast<double>(in_shadow), 144 * 1.32 * 9.73 * 9.73, 144 * 4 * 12);
  EXPECT_EQ(in_sun + in_shadow + background, 352u * 352u);
  EXPECT_LT(background, 4u * 352u);
}

// Layers by light against the light sets' picture from a perspective camera: per face,
// the base covers what the light-set pieces cover, each light's layer what the pieces of
// sets holding it cover; base and layers each do not overlap among themselves; the
// layers' colours add up to the light-set pieces' (the sun is directional, so a face's
// colour does not depend on the point; the lamp's term does, so only the sun's is
// checked there); pieces come base first, then light by light.
TEST(Render, LayersByLightAddUpToTheLightSetsPicture) {
  const ShadowedScene shadowed = generated(kGroundScene);
  Camera camera;
  camera.eye = {14, -9, 8};
  camera.target = {5, 5, 0};
  camera.fov_deg = 40;
  const RenderOptions options = picture_size(320, 240);
  const Picture sets = render(shadowed, camera, options);
  const Picture layers = render_by_light(shadowed, camera, options);
  EXPECT_FALSE(sets.layered);
  EXPECT_TRUE(layers.layered);
  const Scene& scene = shadowed.scene();
  const std::size_t lights = scene.lights.size();
  // [face][0]: all; [face][1 + L]: lit by L.
  auto areas = [&](const Picture& picture, bool by_layer) {
    std::vector<std::vector<double>> a(scene.faces.size(), std::vector<double>(1 + lights, 0.0));
    for (const Piece& piece : picture.pieces) {
      const double area = clipper::area(piece.shape);
      if (by_layer) {
        a[piece.face][piece.layer] += area;
        continue;
      }
      a[piece.face][0] += area;
      for (const std::size_t l : piece.lights) a[piece.face][1 + l] += area;
    }
    return a;
  };
  const auto expected = areas(sets, false), got = areas(layers, true);
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t k = 0; k <= lights; ++k) {
      EXPECT_NEAR(got[f][k], expected[f][k], 1e-9 * options.width * options.height)
          << scene.faces[f].id << ", layer " << k;
    }
  }
  std::size_t previous = 0;
  std::vector<std::vector<Piece>> by_layer(1 + lights);
  for (const Piece& piece : layers.pieces) {
    EXPECT_GE(piece.layer, previous);
    previous = piece.layer;
    by_layer[piece.layer].push_back(piece);
    if (piece.layer == 0) {
      EXPECT_TRUE(piece.lights.empty());
      EXPECT_EQ(piece.light_set, "shadow");
    } else {
      EXPECT_EQ(piece.lights, std::vector<std::size_t>{piece.layer - 1});
      EXPECT_EQ(piece.light_set, scene.lights[piece.layer - 1].id);
    }
  }
  for (std::vector<Piece>& pieces : by_layer) {
    ASSERT_FALSE(pieces.empty());
    Picture one;
    one.pieces = std::move(pieces);
    ExpectNoOverlap(one, 1e-9 * options.width * options.height);
  }
  // Colours on the ground, which is seen from its front: shadow, and shadow plus the sun's
  // layer where the sun alone reaches.
  const std::size_t ground = 0, sun = 0;
  const Piece* base = nullptr;
  const Piece* sun_layer = nullptr;
  for (const Piece& piece : layers.pieces) {
    if (piece.face != ground) continue;
    if (piece.layer == 0 && base == nullptr) base = &piece;
    if (piece.layer == 1 + sun && sun_layer == nullptr) sun_layer = &piece;
  }
  ASSERT_NE(base, nullptr);
  ASSERT_NE(sun_layer, nullptr);
  for (const Piece& piece : sets.pieces) {
    if (piece.face != ground) continue;
    if (piece.lights.empty()) {
      EXPECT_EQ(piece.colour.r, base->colour.r);
    } else if (piece.lights == std::vector<std::size_t>{sun}) {
      EXPECT_NEAR(piece.colour.r, base->colour.r + sun_layer->colour.r, 1e-15);
      EXPECT_NEAR(piece.colour.g, base->colour.g + sun_layer->colour.g, 1e-15);
    }
  }
}

TEST(Render, OrthographicUpAndFittedScale) {
  const ShadowedScene shadowed = generated(kGroundScene);
  const Camera camera = looking_down({5, 5, 0.25}, {5, 5, 0}, 0.0);  // 0: fit
  const RenderOptions options = picture_size(300, 200);
  const Picture picture = render(shadowed, camera, options);
  // The scene spans 10 × 10 around the target: the height is the tighter side.
  EXPECT_DOUBLE_EQ(picture.pixels_per_unit, 0.95 * 200.0 / 10.0);
  // World +x is right, world +y is up (pixel y down): the ground's corner (0, 0) is at the
  // bottom left.
  const double s = picture.pixels_per_unit;
  double min_x = INFINITY, max_y = -INFINITY;
  for (const Piece& piece : picture.pieces) {
    for (const clipper::Point2& p : piece.shape.outer) {
      min_x = std::min(min_x, p.x);
      max_y = std::max(max_y, p.y);
    }
  }
  EXPECT_NEAR(min_x, 150.0 - 5.0 * s, 1e-9);
  EXPECT_NEAR(max_y, 100.0 + 5.0 * s, 1e-9);
}

// What a perspective picture of kGroundScene showed against the camera's pinhole.
struct PinholeComparison {
  double image_area = 0.0;    // of the faces' images, all of them
  double beyond_frame = 0.0;  // of the images outside the picture
  std::vector<int> seen;      // sample pixels showing each face
  int background = 0;         // sample pixels showing no face
};

// The picture's pieces cover exactly the union of the faces' images within the picture,
// each point showing the face nearest the eye along its ray. Both expectations come from
// the camera's documented pinhole (Pinhole above), not from hsr's projection: the region
// from the faces' corners projected by hand and measured with CGAL's exact kernel, the
// faces from rays cast through pixel centres.
PinholeComparison ExpectPiecesMatchThePinhole(const ShadowedScene& shadowed, const Camera& camera) {
  PinholeComparison out;
  const RenderOptions options = picture_size(320, 240);
  const Picture picture = render(shadowed, camera, options);
  EXPECT_FALSE(picture.pieces.empty());
  ExpectNoOverlap(picture, 1e-9 * options.width * options.height);
  ExpectInsidePicture(picture);

  // Every vertex lies in front of the eye, so no face is cut at the near plane and each
  // part's image is the polygon of its projected corners.
  const Pinhole pinhole(camera, options.width, options.height);
  clipper::PolygonSet2 images;
  for (const Face& face : shadowed.scene().faces) {
    for (const hsr::Polygon3& part : face.parts) {
      auto project = [&](const hsr::Loop3& loop) {
        clipper::Loop2 projected;
        for (const glm::dvec3& p : loop) {
          EXPECT_GT(pinhole.depth(p), 1.0) << face.id;
          projected.push_back(pinhole.pixel(p));
        }
        return projected;
      };
      clipper::PolygonWithHoles2 image{project(part.outer), {}};
      for (const hsr::Loop3& hole : part.holes) image.holes.push_back(project(hole));
      images.push_back(std::move(image));
    }
  }
  clipper::PolygonSet2 drawn;
  for (const Piece& piece : picture.pieces) drawn.push_back(piece.shape);
  const double w = options.width, h = options.height;
  const clipper::PolygonSet2 frame{{{{0, 0}, {w, 0}, {w, h}, {0, h}}, {}}};

  // Exact areas of the unions: D (drawn pieces), I (images), D Δ I, I ∪ F (F the frame).
  // The pieces lie within F (ExpectInsidePicture), so D Δ (I ∩ F) = (D Δ I) − (I − F),
  // and |I − F| = |I ∪ F| − |F|.
  const test::ExactUnionComparison unions =
      test::compare_exact_unions(std::span(&drawn, 1), std::span(&images, 1));
  const std::array<clipper::PolygonSet2, 2> images_and_frame{images, frame};
  out.image_area = unions.b_union;
  out.beyond_frame = test::exact_union_area(images_and_frame) - w * h;
  const double covered = unions.b_union - out.beyond_frame;
  const double region_error = unions.symmetric_difference - out.beyond_frame;
  std::printf(
      "[ perspective, fov %g ] image %.6f px² (%.6f beyond the frame), drawn %.6f, "
      "area(drawn Δ image in frame) %.3g px²\n",
      camera.fov_deg, unions.b_union, out.beyond_frame, unions.a_union, region_error);
  EXPECT_LE(relative_error(pieces_area(picture), covered), 1e-9)
      << pieces_area(picture) << " vs " << covered;
  EXPECT_LE(region_error, 1e-9 * w * h) << "drawn " << unions.a_union << " vs " << covered;

  // Pixel centres on a grid of every 4th pixel, each ray cast against every part: the
  // piece under the centre belongs to the nearest face hit, and no piece lies where no
  // face is. Centres within 1e-6 px of a part's image edge are left out: only there can
  // rounding tip the answer.
  out.seen.assign(shadowed.scene().faces.size(), 0);
  int checked = 0, mismatches = 0;
  std::string first_mismatches;
  for (int py = 0; py < options.height; py += 4) {
    for (int px = 0; px < options.width; px += 4) {
      const clipper::Point2 centre{px + 0.5, py + 0.5};
      bool near_edge = false;
      for (const clipper::PolygonWithHoles2& image : images) {
        near_edge = near_edge || distance_to_boundary(image, centre) < 1e-6;
      }
      if (near_edge) continue;
      std::optional<std::size_t> nearest;
      double nearest_t = std::numeric_limits<double>::infinity();
      for (std::size_t f = 0; f < shadowed.scene().faces.size(); ++f) {
        for (const hsr::Polygon3& part : shadowed.scene().faces[f].parts) {
          const std::optional<double> t = ray_hits(pinhole.eye(), pinhole.ray(centre), part);
          if (t && *t < nearest_t) {
            nearest_t = *t;
            nearest = f;
          }
        }
      }
      std::string under;
      int pieces_under = 0;
      for (const Piece& piece : picture.pieces) {
        if (covers(piece.shape, centre)) {
          under += (pieces_under++ == 0 ? "" : ", ") + piece.face_id;
        }
      }
      ++checked;
      const std::string expected = nearest ? shadowed.scene().faces[*nearest].id : "";
      if (nearest) {
        ++out.seen[*nearest];
      } else {
        ++out.background;
      }
      if (under != expected) {
        if (++mismatches <= 5) {
          first_mismatches += "\n  pixel (" + std::to_string(px) + ", " + std::to_string(py) +
                              ") shows [" + under + "], the nearest face is [" + expected + "]";
        }
      }
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << checked << " pixels; the first:" << first_mismatches;
  EXPECT_GT(checked, 4000);
  return out;
}

TEST(Render, PerspectivePiecesNeverOverlapAndCoverTheVisibleImage) {
  const ShadowedScene shadowed = generated(kGroundScene);
  Camera camera;
  camera.eye = {14, -9, 8};
  camera.target = {5, 5, 0};
  camera.fov_deg = 40;  // the whole scene, with background all round
  const PinholeComparison wide = ExpectPiecesMatchThePinhole(shadowed, camera);
  EXPECT_GT(wide.image_area, 0.1 * 320 * 240);
  EXPECT_EQ(wide.beyond_frame, 0.0);
  EXPECT_GT(wide.background, 0);
  // Every face shows.
  for (std::size_t f = 0; f < wide.seen.size(); ++f) {
    EXPECT_GT(wide.seen[f], 0) << shadowed.scene().faces[f].id;
  }

  camera.fov_deg = 15;  // the picture's edges cut the faces
  const PinholeComparison narrow = ExpectPiecesMatchThePinhole(shadowed, camera);
  EXPECT_GT(narrow.beyond_frame, 0.1 * narrow.image_area);
}

// A closed 10-unit box, faces turned inward, a lamp inside and a small table under it.
constexpr const char* kBoxScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "floor",   "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "ceiling", "outer": [[0,0,10],[0,10,10],[10,10,10],[10,0,10]]},
    {"id": "west",    "outer": [[0,0,0],[0,10,0],[0,10,10],[0,0,10]]},
    {"id": "east",    "outer": [[10,0,0],[10,0,10],[10,10,10],[10,10,0]]},
    {"id": "south",   "outer": [[0,0,0],[0,0,10],[10,0,10],[10,0,0]]},
    {"id": "north",   "outer": [[0,10,0],[10,10,0],[10,10,10],[0,10,10]]},
    {"id": "table",   "outer": [[4,4,3],[6,4,3],[6,6,3],[4,6,3]]}
  ],
  "lights": [{"id": "lamp", "type": "point", "position": [5, 5, 8]}]
})";

TEST(Render, ViewFromInsideAClosedBox) {
  const ShadowedScene shadowed = generated(kBoxScene);
  Camera camera;
  camera.eye = {2, 2, 5};
  camera.target = {8, 7, 2};
  camera.fov_deg = 90;
  const RenderOptions options = picture_size(200, 150);
  const Picture picture = render(shadowed, camera, options);
  // Walls all round: the pieces cover the whole picture.
  EXPECT_LE(relative_error(pieces_area(picture), 200.0 * 150.0), 1e-9);
  ExpectNoOverlap(picture, 1e-9 * 200 * 150);
  ExpectInsidePicture(picture);
  bool shadow_on_floor = false, lit_floor = false;
  for (const Piece& piece : picture.pieces) {
    EXPECT_FALSE(piece.back_side) << piece.face_id;
    if (piece.face_id == "floor") {
      (piece.lights.empty() ? shadow_on_floor : lit_floor) = true;
    }
    if (piece.lights.empty()) {
      EXPECT_EQ(piece.light_set, "shadow");
      EXPECT_NEAR(piece.colour.r, options.albedo.r * options.ambient, 1e-15);
    } else {
      EXPECT_EQ(piece.light_set, "lamp");
      EXPECT_GT(piece.colour.r, options.albedo.r * options.ambient);
    }
  }
  EXPECT_TRUE(shadow_on_floor);  // the table's shadow
  EXPECT_TRUE(lit_floor);
}

// A wall at y = 1, x in [-10, 10], z in [-10, 10], beside an eye at the origin looking
// along +x with a 90-degree field of view: the wall reaches behind the eye, through the
// near plane. Its image is u in [-1, -0.1] (x from the near plane to 10), v in [-1, 1]:
// 0.45 of the square picture.
std::string wall_scene(bool facing_the_eye) {
  const std::string outer = facing_the_eye ? "[[-10,1,-10],[10,1,-10],[10,1,10],[-10,1,10]]"
                                           : "[[-10,1,-10],[-10,1,10],[10,1,10],[10,1,-10]]";
  return R"({"format": "shadowgen-scene/1",
    "polygons": [{"id": "wall", "outer": )" +
         outer + R"(}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0.2, 1, -0.1]}]})";
}

Camera beside_the_wall() {
  Camera camera;
  camera.eye = {0, 0, 0};
  camera.target = {1, 0, 0};
  camera.fov_deg = 90;
  return camera;
}

TEST(Render, FaceCrossingTheNearPlane) {
  const ShadowedScene shadowed = generated(wall_scene(true));
  ASSERT_EQ(shadowed.lit()[0][0].size(), 1u);
  const RenderOptions options = picture_size(200, 200);
  const Picture picture = render(shadowed, beside_the_wall(), options);
  ASSERT_FALSE(picture.pieces.empty());
  EXPECT_LE(relative_error(pieces_area(picture), 0.45 * 200 * 200), 1e-9);
  ExpectInsidePicture(picture);
  double min_x = INFINITY, max_x = -INFINITY;
  for (const Piece& piece : picture.pieces) {
    EXPECT_EQ(piece.light_set, "sun");
    EXPECT_FALSE(piece.back_side);
    for (const clipper::Point2& p : piece.shape.outer) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
    }
  }
  // The wall is on the eye's left (right = forward × up = −y).
  EXPECT_NEAR(min_x, 0.0, 1e-9);
  EXPECT_NEAR(max_x, 90.0, 1e-9);
}

TEST(Render, BackSidesGetTheAmbientColourAndNoLight) {
  const ShadowedScene front = generated(wall_scene(true));
  const ShadowedScene back = generated(wall_scene(false));
  EXPECT_TRUE(back.lit()[0][0].empty());  // turned away from the sun
  const RenderOptions options = picture_size(200, 200);
  const Picture picture = render(back, beside_the_wall(), options);
  ASSERT_FALSE(picture.pieces.empty());
  EXPECT_LE(relative_error(pieces_area(picture), 0.45 * 200 * 200), 1e-9);
  for (const Piece& piece : picture.pieces) {
    EXPECT_TRUE(piece.back_side);
    EXPECT_TRUE(piece.lights.empty());
    EXPECT_EQ(piece.light_set, "shadow");
    EXPECT_DOUBLE_EQ(piece.colour.g, options.albedo.g * options.ambient);
  }
  EXPECT_EQ(picture.stats.back_side_pieces, picture.pieces.size());

  // A face lit on its front side shows nothing of it from behind: from y = 2 the lit wall
  // is seen from its back.
  Camera behind = beside_the_wall();
  behind.eye = {0, 2, 0};
  behind.target = {1, 2, 0};
  const Picture from_behind = render(front, behind, options);
  ASSERT_FALSE(from_behind.pieces.empty());
  for (const Piece& piece : from_behind.pieces) EXPECT_TRUE(piece.back_side);
}

// Render reads the lit polygons from the database, whatever they are: a database whose
// sun lights only the ground's left half (no occluder) is drawn so.
TEST(Render, DrawsTheDatabaseNotAShadowPass) {
  Scene scene;
  scene.faces = {
      Face{"ground", {hsr::Polygon3{{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}, {}}}, "x"}};
  Light sun;
  sun.id = "sun";
  scene.lights = {sun};
  const ShadowedScene shadowed(
      std::move(scene),
      LitTable({{{{0, hsr::Polygon3{{{0, 0, 0}, {5, 0, 0}, {5, 10, 0}, {0, 10, 0}}, {}}}}}}));
  const Camera camera = looking_down({5, 5, 10}, {5, 5, 0}, 10.0);
  const RenderOptions options = picture_size(120, 120);
  const Picture picture = render(shadowed, camera, options);
  double lit = 0.0, shadow = 0.0;
  for (const Piece& piece : picture.pieces) {
    (piece.lights.empty() ? shadow : lit) += clipper::area(piece.shape);
  }
  EXPECT_DOUBLE_EQ(lit, 5000.0);
  EXPECT_DOUBLE_EQ(shadow, 5000.0);
}

TEST(Render, ShadingFormula) {
  Scene scene;
  Light sun;
  sun.id = "sun";
  sun.direction = {0, 0, -2};
  Light lamp;
  lamp.id = "lamp";
  lamp.type = LightType::kPoint;
  lamp.position = {0, 0, 4};
  lamp.intensity = {1, 0.5, 0};
  lamp.range = LightRange{1.0, 7.0, 2.0};
  scene.lights = {sun, lamp};
  RenderOptions options;
  options.albedo = {0.5, 0.5, 0.5};
  options.ambient = 0.2;
  const glm::dvec3 up(0, 0, 1);
  // Sun head-on: 0.5 · (0.2 + 0.8 · 1/2 · 1).
  EXPECT_DOUBLE_EQ(shade(scene, {0}, {3, 3, 0}, up, options).r, 0.5 * (0.2 + 0.4));
  // Shadow: albedo · ambient.
  EXPECT_DOUBLE_EQ(shade(scene, {}, {3, 3, 0}, up, options).b, 0.1);
  // Lamp straight above at d = 4: f = (1 − 3/6)² = 1/4; green intensity 0.5.
  const Rgb lamp_only = shade(scene, {1}, {0, 0, 0}, up, options);
  EXPECT_DOUBLE_EQ(lamp_only.r, 0.5 * (0.2 + 0.4 * 0.25));
  EXPECT_DOUBLE_EQ(lamp_only.g, 0.5 * (0.2 + 0.4 * 0.5 * 0.25));
  EXPECT_DOUBLE_EQ(lamp_only.b, 0.1);
  // Inside falloff_start full, beyond end nothing, tilted by the cosine.
  EXPECT_DOUBLE_EQ(shade(scene, {1}, {0, 0, 3.5}, up, options).r, 0.5 * (0.2 + 0.4));
  EXPECT_DOUBLE_EQ(shade(scene, {1}, {0, 8, -4}, up, options).r, 0.1);
  const Rgb tilted = shade(scene, {1}, {0, 0, 3}, glm::normalize(glm::dvec3(1, 0, 1)), options);
  EXPECT_NEAR(tilted.r, 0.5 * (0.2 + 0.4 * std::sqrt(0.5)), 1e-15);
  // A light behind the face gives nothing.
  EXPECT_DOUBLE_EQ(shade(scene, {0}, {0, 0, 0}, -up, options).r, 0.1);
}

TEST(Render, BadCamerasAreRejected) {
  const ShadowedScene shadowed = generated(kGroundScene);
  Camera same;
  same.eye = same.target = {1, 2, 3};
  EXPECT_THROW(render(shadowed, same), std::invalid_argument);
  Camera wide;
  wide.fov_deg = 180;
  EXPECT_THROW(render(shadowed, wide), std::invalid_argument);
  RenderOptions empty;
  empty.width = 0;
  EXPECT_THROW(render(shadowed, Camera{}, empty), std::invalid_argument);
}

}  // namespace
}  // namespace shadowgen
