// Sun-hours regions (shadowgen/shadows/sun_hours.h) against what they sum: the time the
// sun stands in front of a lone wall, the instants' lit areas, and, point by point, the
// instants at which a shadow ray from the point reaches the sun.

#include "shadowgen/shadows/sun_hours.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <random>
#include <string>
#include <vector>

#include "hsr/area.h"
#include "hsr/plane_chart.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/scene/database_reader.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

using test::generated;
using test::kCourtyard;
using test::kMarch21;
using test::site_scene;

double relative(double a, double b) {
  const double scale = std::max(std::fabs(a), std::fabs(b));
  return scale == 0.0 ? 0.0 : std::fabs(a - b) / scale;
}

TEST(SunHours, ASouthWallInAnEmptySiteHasTheHoursTheSunStandsInFrontOfIt) {
  // Facing -y, due south (north_axis_deg 0: +y is north), over the longest day.
  const ShadowedScene shadowed =
      generated(site_scene(R"({"id": "wall", "outer": [[0,0,0],[4,0,0],[4,0,3],[0,0,3]]})",
                           R"("from": "2026-06-21T00:00", "to": "2026-06-21T23:59",
                              "step_min": 10)"));
  ASSERT_EQ(shadowed.sun_paths.size(), 1u);
  const SunPathHours& path = shadowed.sun_paths[0];
  // From the sun's positions alone: the sun is up at every instant of the path (the others
  // are dropped), and in front of the wall where its azimuth points south of east-west.
  std::size_t in_front = 0;
  for (const std::size_t l : path.instants) {
    const SunInstant& sun = *shadowed.scene().lights[l].sun;
    ASSERT_GT(sun.elevation_deg, 0.0);
    if (std::cos(sun.azimuth_deg * M_PI / 180.0) < 0.0) ++in_front;
  }
  ASSERT_GT(in_front, 30u);                   // most of the day...
  ASSERT_LT(in_front, path.instants.size());  // ...but not before 6 and after 18
  const double expected = static_cast<double>(in_front) * 10.0 / 60.0;
  ASSERT_EQ(path.regions[0].size(), 1u);
  EXPECT_NEAR(path.regions[0][0].hours, expected, 1e-9 * expected);
  EXPECT_NEAR(lit_area(path.regions[0][0].polygons), 12.0, 1e-9 * 12.0);
  // The instants' polygons are not kept: the table holds no room for them.
  EXPECT_FALSE(shadowed.lit().kept(path.instants[0]));
  EXPECT_TRUE(shadowed.lit()[0][path.instants[0]].empty());
}

TEST(SunHours, RegionsTileEachFaceAndSumItsInstantsLitAreas) {
  const ShadowedScene shadowed = generated(site_scene(kCourtyard, kMarch21));
  const SunPathHours& path = shadowed.sun_paths.at(0);
  ASSERT_EQ(path.instants.size(), 24u);  // 06:00 is before sunrise at 51.5 N
  for (std::size_t f = 0; f < shadowed.scene().faces.size(); ++f) {
    const std::vector<SunHoursRegion>& regions = path.regions[f];
    double area = 0.0, hours_area = 0.0, lit_hours = 0.0;
    for (std::size_t r = 0; r < regions.size(); ++r) {
      if (r > 0) {
        EXPECT_LT(regions[r - 1].hours, regions[r].hours);
      }
      area += lit_area(regions[r].polygons);
      hours_area += regions[r].hours * lit_area(regions[r].polygons);
    }
    for (const double a : path.lit_area[f]) lit_hours += a * 30.0 / 60.0;
    const std::string& id = shadowed.scene().faces[f].id;
    EXPECT_LE(relative(area, hsr::area(shadowed.scene().faces[f].parts)), 1e-9) << id;
    EXPECT_LE(relative(hours_area, lit_hours), 1e-9) << id;
  }
  EXPECT_GE(path.regions[0].size(), 10u);  // the ground: many different hours
}

// Whether a ray from q crosses `loop` an odd number of times (the even-odd rule); `near` is
// set where q lies within `margin` of the loop, where rounding could decide either way.
bool odd_crossings(const clipper::Loop2& loop, const clipper::Point2& q, double margin,
                   bool& near) {
  bool odd = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const clipper::Point2 a = loop[j], b = loop[i];
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    const double s = std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / (len * len), 0.0, 1.0);
    if (std::hypot(q.x - a.x - s * dx, q.y - a.y - s * dy) < margin) near = true;
    if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / dy * dx) odd = !odd;
  }
  return odd;
}

// A face of one part without holes, charted once for the point tests below.
struct ChartedFace {
  hsr::Plane3 plane;
  hsr::PlaneChart chart;
  clipper::Loop2 outer;  // in `chart`
  clipper::Box2 box;
};

ChartedFace charted(const Face& face) {
  const hsr::Polygon3& polygon = face.parts.at(0);
  const hsr::Plane3 plane = hsr::plane_of(polygon);
  const hsr::PlaneChart chart = hsr::chart_facing(plane.normal);
  clipper::Loop2 outer = chart.flatten(polygon.outer);
  const clipper::Box2 box = clipper::box_of(outer);
  return {plane, chart, std::move(outer), box};
}

// Whether p on face `face` is lit by a sun travelling along `direction`: the face's front
// turned to the sun, and a segment from p against `direction` crossing no other face's
// interior. `near` is set where the segment passes within `margin` of an occluder's
// boundary, or the sun stands within `margin` of the face's plane: such points are left
// out.
bool sun_reaches(const std::vector<ChartedFace>& faces, std::size_t face, const glm::dvec3& p,
                 const glm::dvec3& direction, double margin, bool& near) {
  const double facing = glm::dot(faces[face].plane.normal, -direction);
  if (std::fabs(facing) < margin) near = true;
  if (!(facing > 0.0)) return false;
  for (std::size_t o = 0; o < faces.size(); ++o) {
    if (o == face) continue;
    const ChartedFace& occluder = faces[o];
    const double along = glm::dot(occluder.plane.normal, -direction);
    if (along == 0.0) continue;
    const double t = occluder.plane.signed_distance(p) / -along;
    if (!(t > margin)) continue;
    const clipper::Point2 q = occluder.chart(p - t * direction);
    if (q.x < occluder.box.xmin - margin || q.x > occluder.box.xmax + margin ||
        q.y < occluder.box.ymin - margin || q.y > occluder.box.ymax + margin) {
      continue;
    }
    if (odd_crossings(occluder.outer, q, margin, near)) return false;
  }
  return true;
}

// The regions of one face, charted once: per polygon its loops and box.
struct ChartedRegion {
  double hours = 0.0;
  std::vector<std::vector<clipper::Loop2>> polygons;  // outer loop, then holes
  std::vector<clipper::Box2> boxes;
};

std::vector<ChartedRegion> charted(const std::vector<SunHoursRegion>& regions,
                                   const hsr::PlaneChart& chart) {
  std::vector<ChartedRegion> out;
  for (const SunHoursRegion& region : regions) {
    ChartedRegion& r = out.emplace_back();
    r.hours = region.hours;
    for (const LitPolygon& polygon : region.polygons) {
      std::vector<clipper::Loop2>& loops = r.polygons.emplace_back();
      loops.push_back(chart.flatten(polygon.polygon.outer));
      for (const hsr::Loop3& hole : polygon.polygon.holes) loops.push_back(chart.flatten(hole));
      r.boxes.push_back(clipper::box_of(loops.front()));
    }
  }
  return out;
}

// Whether chart point q lies in the region (even-odd over all its loops); `near` is set
// where it lies within `margin` of a loop.
bool contains(const ChartedRegion& region, const clipper::Point2& q, double margin, bool& near) {
  bool inside = false;
  for (std::size_t i = 0; i < region.polygons.size(); ++i) {
    const clipper::Box2& box = region.boxes[i];
    if (q.x < box.xmin - margin || q.x > box.xmax + margin || q.y < box.ymin - margin ||
        q.y > box.ymax + margin) {
      continue;
    }
    for (const clipper::Loop2& loop : region.polygons[i]) {
      inside ^= odd_crossings(loop, q, margin, near);
    }
  }
  return inside;
}

// 100,000 random points on every face of the courtyard (rectangles: p = a + u (b - a) +
// v (d - a)): the region holding each point has the hours of the instants at which a
// shadow ray from the point reaches the sun, exactly, but for points within 1e-7 of a
// region's or an occluder's boundary.
TEST(SunHours, EveryPointHasTheHoursOfTheInstantsWhoseShadowRaysReachTheSun) {
  const ShadowedScene shadowed = generated(site_scene(kCourtyard, kMarch21));
  const Scene& scene = shadowed.scene();
  const SunPathHours& path = shadowed.sun_paths.at(0);
  std::vector<ChartedFace> faces;
  for (const Face& face : scene.faces) faces.push_back(charted(face));
  std::mt19937_64 random(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr double kMargin = 1e-7;
  constexpr int kPointsPerFace = 100'000;
  std::size_t partly_lit_faces = 0;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const hsr::Loop3& corners = scene.faces[f].parts[0].outer;
    ASSERT_EQ(corners.size(), 4u);
    const std::vector<ChartedRegion> regions = charted(path.regions[f], faces[f].chart);
    std::size_t checked = 0, partly = 0;
    for (int i = 0; i < kPointsPerFace; ++i) {
      const double u = unit(random), v = unit(random);
      const glm::dvec3 p =
          corners[0] + u * (corners[1] - corners[0]) + v * (corners[3] - corners[0]);
      bool near = false;
      std::size_t lit = 0;
      for (const std::size_t l : path.instants) {
        lit += sun_reaches(faces, f, p, scene.lights[l].direction, kMargin, near) ? 1 : 0;
      }
      std::vector<double> hours;
      const clipper::Point2 q = faces[f].chart(p);
      for (const ChartedRegion& region : regions) {
        if (contains(region, q, kMargin, near)) hours.push_back(region.hours);
      }
      if (near) continue;
      ++checked;
      if (lit > 0 && lit < path.instants.size()) ++partly;
      ASSERT_EQ(hours.size(), 1u) << scene.faces[f].id << " point " << p.x << ", " << p.y << ", "
                                  << p.z;
      ASSERT_EQ(hours[0], static_cast<double>(lit) * 30.0 / 60.0)
          << scene.faces[f].id << " point " << p.x << ", " << p.y << ", " << p.z;
    }
    EXPECT_GT(checked, 99'000u) << scene.faces[f].id;
    if (partly > 1000) ++partly_lit_faces;
  }
  EXPECT_GE(partly_lit_faces, 2u);  // the ground and a wall at least: shadows sweep them
}

TEST(SunHours, SameOnAnyThreadCountAndWithTheInstantsPolygonsKept) {
  const Scene scene = parse_scene(site_scene(kCourtyard, kMarch21), "test.json").scene;
  GenerateOptions one, two, kept;
  one.threads = 1;
  two.threads = 2;
  kept.keep_instant_polygons = true;
  const ShadowedScene a = generate_shadows(scene, one).shadowed;
  EXPECT_EQ(database_json(a), database_json(generate_shadows(scene, two).shadowed));
  const ShadowedScene k = generate_shadows(scene, kept).shadowed;
  ASSERT_TRUE(k.sun_paths.at(0).lit_polygons_kept);
  const std::size_t noon = k.sun_paths[0].instants[12];
  EXPECT_FALSE(k.lit()[0][noon].empty());
  EXPECT_EQ(lit_area(k.lit()[0][noon]), a.sun_paths[0].lit_area[0][12]);
  // The same sums: the regions of both, written alike.
  std::vector<bool> kept_lights(k.lit().lights(), true);
  for (const std::size_t l : k.sun_paths[0].instants) kept_lights[l] = false;
  ShadowedScene without_polygons(k.scene(),
                                 LitTable(k.lit().size(), k.lit().lights(), kept_lights));
  without_polygons.sun_paths = k.sun_paths;
  for (std::size_t f = 0; f < k.lit().size(); ++f) {
    for (std::size_t l = 0; l < k.lit().lights(); ++l) {
      if (kept_lights[l]) without_polygons.lit_at(f, l) = k.lit().at(f, l);
    }
  }
  without_polygons.sun_paths[0].lit_polygons_kept = false;
  EXPECT_EQ(database_json(without_polygons), database_json(a));
}

// generate --areas-only: the same lit areas, no regions; the database says so and reads
// back; what needs the regions refuses it, naming the file.
TEST(SunHours, AreasAloneKeepEveryInstantsLitAreaAndNoRegions) {
  const Scene scene = parse_scene(site_scene(kCourtyard, kMarch21), "test.json").scene;
  GenerateOptions both, areas;
  both.threads = areas.threads = 1;
  areas.sun_hours_regions = false;
  const ShadowedScene a = generate_shadows(scene, both).shadowed;
  const ShadowedScene b = generate_shadows(scene, areas).shadowed;
  ASSERT_FALSE(b.sun_paths.at(0).regions_kept);
  EXPECT_TRUE(b.sun_paths[0].regions.empty());
  EXPECT_EQ(b.sun_paths[0].lit_area, a.sun_paths[0].lit_area);
  const std::string text = database_json(b);
  EXPECT_NE(text.find(R"("instant_polygons":"dropped","regions":"dropped")"), std::string::npos);
  EXPECT_EQ(text.find("\"hours\""), std::string::npos);
  const ShadowedScene read = parse_database(text, "areas.json");
  EXPECT_FALSE(read.sun_paths.at(0).regions_kept);
  EXPECT_EQ(database_json(read), text);
  try {
    require_regions(read.sun_paths[0], read.scene().file, "a sun-hours map");
    ADD_FAILURE() << "regions required of a path of lit areas alone";
  } catch (const InputError& e) {
    // Named by the database read, not by the scene its faces came from.
    EXPECT_EQ(std::string(e.what()),
              "areas.json: sun path 'day' was summed into lit areas alone (generate "
              "--areas-only), without the sun-hours regions a sun-hours map needs: generate "
              "without --areas-only");
  }
  // A lit area above the face's is caught as with regions.
  std::string tampered = text;
  const std::string key = "\"lit_area\": [";
  const std::size_t at = tampered.find(key);
  ASSERT_NE(at, std::string::npos);
  const std::size_t first = at + key.size();  // the ground's (400) at the first instant
  tampered.replace(first, tampered.find_first_of(",]", first) - first, "1000.0");
  try {
    parse_database(tampered, "areas.json");
    ADD_FAILURE() << "a lit area above the face's read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a lit area of 1000, more than the face's area of 400"),
              std::string::npos)
        << e.what();
  }
}

TEST(SunHours, PathsAreTheSunEntriesWithASpanAndTheirInstantsInOrder) {
  const Scene scene = parse_scene(R"({"format": "shadowgen-scene/1",
        "polygons": [{"id": "g", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
        "site": {"latitude_deg": 0, "longitude_deg": 0, "utc_offset_h": 0},
        "lights": [{"id": "noon", "type": "sun", "time": "2026-03-21T12:00"},
                   {"id": "lamp", "type": "point", "position": [0,0,5]},
                   {"id": "am", "type": "sun", "from": "2026-03-21T09:00",
                    "to": "2026-03-21T10:00", "step_min": 20}]})",
                                  "test.json")
                          .scene;
  const std::vector<SunPathHours> paths = sun_paths_of(scene);
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(paths[0].id, "am");
  EXPECT_EQ(paths[0].step_min, 20);
  EXPECT_EQ(paths[0].instants, (std::vector<std::size_t>{2, 3, 4, 5}));
}

}  // namespace
}  // namespace shadowgen
