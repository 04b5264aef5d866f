// Sun-hours maps (shadowgen/view/sun_hours_map.h): pieces where the regions are, with their
// hours and their band's colour, adding up to the database's region areas in views where
// nothing hides them; back sides as 0 hours; the same coverage as the lit picture from any
// eye; the legend.

#include "shadowgen/view/sun_hours_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "shadowgen/view/render.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/shadowgen/view/cameras.h"
#include "tests/support/relative_error.h"

namespace shadowgen {
namespace {

using test::generated;
using test::kCourtyard;
using test::kMarch21;
using test::looking_down;
using test::picture_size;
using test::relative_error;
using test::site_scene;
using test::sun_path_by_hand;

void ExpectColour(const Rgb& actual, const glm::dvec3& expected, const std::string& what) {
  EXPECT_EQ(actual.r, expected.r) << what;
  EXPECT_EQ(actual.g, expected.g) << what;
  EXPECT_EQ(actual.b, expected.b) << what;
}

// Area of the pieces by hours.
std::map<double, double> area_by_hours(const Picture& picture) {
  std::map<double, double> areas;
  for (const Piece& piece : picture.pieces) {
    EXPECT_TRUE(piece.sun_hours.has_value());
    areas[piece.sun_hours.value_or(-1.0)] += clipper::area(piece.shape);
  }
  return areas;
}

TEST(SunHoursMap, HandMadeRegionsSeenFromAbove) {
  const ShadowedScene shadowed = sun_path_by_hand();
  const SunPathHours& path = shadowed.sun_paths[0];
  const HourBands bands = hour_bands(path);  // 0.5, 1, 1.5, 2
  // 100 pixels a unit, centred on the strip's middle: x = 0 .. 4 is pixels 50 .. 450.
  const Picture picture = render_sun_hours(
      shadowed, path, bands, looking_down({2, 0.5, 5}, {2, 0.5, 0}, 100), picture_size(500, 200));
  // One piece per region: the 1.5 h region, the largest, gets what the others leave of the
  // strip, one piece over its two polygons.
  ASSERT_EQ(picture.pieces.size(), 3u);
  const std::map<double, double> expected_x{{0.0, 100.0}, {1.5, 250.0}, {2.0, 400.0}};
  const std::map<double, double> expected_area{{0.0, 1e4}, {1.5, 2e4}, {2.0, 1e4}};
  for (const Piece& piece : picture.pieces) {
    ASSERT_TRUE(piece.sun_hours.has_value());
    const double hours = *piece.sun_hours;
    ASSERT_EQ(expected_x.count(hours), 1u) << hours;
    EXPECT_EQ(piece.face_id, "g");
    EXPECT_FALSE(piece.back_side);
    EXPECT_TRUE(piece.lights.empty());
    EXPECT_EQ(piece.light_set, "");
    ExpectColour(piece.colour, bands.bands[bands.band_of(hours)].colour, std::to_string(hours));
    const clipper::Box2 box = clipper::box_of(piece.shape);
    EXPECT_NEAR(0.5 * (box.xmin + box.xmax), expected_x.at(hours), 1e-9) << hours;
    EXPECT_LE(relative_error(clipper::area(piece.shape), expected_area.at(hours)), 1e-12) << hours;
  }
  // The bands of 0, 1.5 and 2 hours are the ramp's dark end, three quarters and bright end.
  ExpectColour(picture.pieces[0].colour, sun_hours_ramp(0.0), "0 h");

  // The legend: the bands' caption, and each band's colour and label, least hours first.
  EXPECT_EQ(picture.legend.caption,
            (std::vector<std::string>{"Sun hours: p", "4 instants, every 30 min"}));
  ASSERT_EQ(picture.legend.entries.size(), 5u);
  std::vector<std::string> labels;
  for (std::size_t b = 0; b < 5; ++b) {
    labels.push_back(picture.legend.entries[b].label);
    ExpectColour(picture.legend.entries[b].colour, bands.bands[b].colour, labels.back());
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"0\u20130.5 h", "0.5\u20131 h", "1\u20131.5 h",
                                              "1.5\u20132 h", "\u2265 2 h"}));
}

TEST(SunHoursMap, BackSidesAreZeroHours) {
  const ShadowedScene shadowed = sun_path_by_hand();
  const SunPathHours& path = shadowed.sun_paths[0];
  const HourBands bands = hour_bands(path);
  // From below, looking up at the strip's back side.
  const Picture picture = render_sun_hours(
      shadowed, path, bands, looking_down({2, 0.5, -5}, {2, 0.5, 0}, 100), picture_size(500, 200));
  ASSERT_FALSE(picture.pieces.empty());
  double area = 0.0;
  for (const Piece& piece : picture.pieces) {
    EXPECT_TRUE(piece.back_side);
    EXPECT_EQ(piece.sun_hours, 0.0);
    ExpectColour(piece.colour, bands.bands[0].colour, "back");
    area += clipper::area(piece.shape);
  }
  EXPECT_LE(relative_error(area, 4e4), 1e-12);
  EXPECT_EQ(picture.stats.back_side_pieces, picture.pieces.size());
}

TEST(SunHoursMap, TopDownAreasByHoursAreTheDatabases) {
  const ShadowedScene shadowed = generated(site_scene(kCourtyard, kMarch21));
  const SunPathHours& path = shadowed.sun_paths.at(0);
  const HourBands bands = hour_bands(path);
  // Below the roof and the wall's top (z = 0.25), the walls edge-on: only the ground is
  // seen, all of it.
  const Camera camera = looking_down({0, 0, 0.25}, {0, 0, 0}, 10);
  const Picture picture = render_sun_hours(shadowed, path, bands, camera, picture_size(300, 300));
  std::map<double, double> expected;
  for (const SunHoursRegion& region : path.regions[0]) {
    expected[region.hours] += 100.0 * lit_area(region.polygons);
  }
  ASSERT_GE(expected.size(), 5u);
  const std::map<double, double> drawn = area_by_hours(picture);
  EXPECT_EQ(drawn.size(), expected.size());
  for (const auto& [hours, area] : expected) {
    EXPECT_LE(relative_error(drawn.count(hours) ? drawn.at(hours) : 0.0, area), 1e-9) << hours;
  }
  for (const Piece& piece : picture.pieces) {
    EXPECT_EQ(piece.face_id, "ground");
    ExpectColour(piece.colour, bands.bands[bands.band_of(*piece.sun_hours)].colour, "ground");
  }
  // The pieces never overlap.
  for (std::size_t a = 0; a < picture.pieces.size(); ++a) {
    for (std::size_t b = a + 1; b < picture.pieces.size(); ++b) {
      EXPECT_LE(clipper::area(
                    clipper::intersection({picture.pieces[a].shape}, {picture.pieces[b].shape})),
                1e-9 * 300 * 300)
          << a << ", " << b;
    }
  }
}

TEST(SunHoursMap, CoversWhatTheLitPictureCoversFromAnyEye) {
  const ShadowedScene shadowed = generated(site_scene(kCourtyard, kMarch21));
  const SunPathHours& path = shadowed.sun_paths.at(0);
  const HourBands bands = hour_bands(path);
  Camera camera;
  camera.eye = {-14, -18, 12};
  camera.target = {0, 2, 1};
  camera.fov_deg = 50;
  const RenderOptions options = picture_size(320, 240);
  const Picture map = render_sun_hours(shadowed, path, bands, camera, options);
  const Picture lit = render(shadowed, camera, options);
  std::vector<double> map_area(shadowed.scene().faces.size()), lit_area(map_area.size());
  for (const Piece& piece : map.pieces) map_area[piece.face] += clipper::area(piece.shape);
  for (const Piece& piece : lit.pieces) lit_area[piece.face] += clipper::area(piece.shape);
  std::size_t seen = 0;
  for (std::size_t f = 0; f < map_area.size(); ++f) {
    EXPECT_LE(relative_error(map_area[f], lit_area[f]), 1e-9) << shadowed.scene().faces[f].id;
    seen += map_area[f] > 0.0;
  }
  EXPECT_GE(seen, 4u);  // the ground, the wall, the roof and two sides
  // One hidden-surface pass from the eye, the same for both.
  EXPECT_EQ(map.stats.fragments, lit.stats.fragments);
}

TEST(SunHoursMap, RegionsNotShapedPerFaceAreRefused) {
  ShadowedScene shadowed = sun_path_by_hand();
  SunPathHours path = shadowed.sun_paths[0];
  path.regions.clear();
  EXPECT_THROW((void)render_sun_hours(shadowed, path, hour_bands(path),
                                      looking_down({2, 0.5, 5}, {2, 0.5, 0}, 100)),
               std::invalid_argument);
}

}  // namespace
}  // namespace shadowgen
