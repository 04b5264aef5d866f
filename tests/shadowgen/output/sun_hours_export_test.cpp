// OBJ + MTL export of a sun path's sun-hours regions by band (shadowgen/output/
// sun_hours_export.h), read back with the tests' own plain reader (tests/support/
// obj_text.h): one group per face and band holding regions, its triangles adding up to the
// regions of that band, a face's groups to its area; one material per band in the band's
// colour; names escaped and reversible.

#include "shadowgen/output/sun_hours_export.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "hsr/area.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/support/obj_text.h"
#include "tests/support/relative_error.h"

namespace shadowgen {
namespace {

using test::generated;
using test::kCourtyard;
using test::kMarch21;
using test::relative_error;
using test::site_scene;
using test::sun_path_by_hand;

std::vector<std::string> group_names(const test::ObjText& obj) {
  std::vector<std::string> names;
  for (const test::ObjGroup& group : obj.groups) names.push_back(group.name);
  return names;
}

double group_area(const test::ObjGroup& group) {
  double sum = 0.0;
  for (const test::ObjTriangle& t : group.triangles) sum += test::area(t);
  return sum;
}

TEST(SunHoursExport, HandMadeRegionsByBand) {
  const ShadowedScene shadowed = sun_path_by_hand();
  const SunPathHours& path = shadowed.sun_paths[0];
  const HourBands bands = hour_bands(path);  // 0.5, 1, 1.5, 2
  const ObjFiles files = sun_hours_obj_export(shadowed, path, bands, "m.mtl");
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_TRUE(obj.errors.empty()) << obj.errors.front();
  EXPECT_EQ(obj.mtllib, "m.mtl");
  EXPECT_EQ(files.obj.rfind("# shadowgen OBJ export: sun hours of sun path 'p', by band\n", 0), 0u);
  // 0 h in the first band, 1.5 h in the fourth, 2 h in the last; the middle bands hold none.
  EXPECT_EQ(group_names(obj), (std::vector<std::string>{"g@0-0.5h", "g@1.5-2h", "g@2h+"}));
  ASSERT_EQ(obj.groups.size(), 3u);
  EXPECT_EQ(group_area(obj.groups[0]), 1.0);
  EXPECT_EQ(group_area(obj.groups[1]), 2.0);  // both polygons of the 1.5 h region
  EXPECT_EQ(group_area(obj.groups[2]), 1.0);
  const std::vector<std::string> materials{"0-0.5h", "1.5-2h", "2h+"};
  for (std::size_t g = 0; g < obj.groups.size(); ++g) {
    for (const test::ObjTriangle& t : obj.groups[g].triangles) {
      EXPECT_EQ(t.material, materials[g]);
      EXPECT_EQ(t.normals[0], (test::Vec3{0, 0, 1}));
      EXPECT_GT(test::area_vector(t)[2], 0.0);  // counter-clockwise from the front
    }
  }

  // Every band has its material, in order, in the band's colour bit for bit.
  const test::MtlText mtl = test::parse_mtl(files.mtl);
  ASSERT_TRUE(mtl.errors.empty()) << mtl.errors.front();
  EXPECT_EQ(mtl.order, (std::vector<std::string>{"0-0.5h", "0.5-1h", "1-1.5h", "1.5-2h", "2h+"}));
  for (const HourBand& band : bands.bands) {
    EXPECT_EQ(mtl.kd.at(band.name), (test::Vec3{band.colour.r, band.colour.g, band.colour.b}))
        << band.name;
  }
  EXPECT_NE(files.mtl.find("# band: 1.5\u20132 h\nnewmtl 1.5-2h\n"), std::string::npos)
      << files.mtl;
}

TEST(SunHoursExport, GroupNamesEscapeTheFaceIdAndSplitAtTheLastAt) {
  ShadowedScene shadowed = sun_path_by_hand();
  shadowed.edit_face(0, [&](Face& face) { face.id = "the ground@2#"; });
  const SunPathHours& path = shadowed.sun_paths[0];
  const std::vector<double> edges{1};
  const ObjFiles files = sun_hours_obj_export(shadowed, path, hour_bands(path, edges), "m.mtl");
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_TRUE(obj.errors.empty()) << obj.errors.front();
  EXPECT_EQ(group_names(obj),
            (std::vector<std::string>{"the%20ground@2%23@0-1h", "the%20ground@2%23@1h+"}));
}

TEST(SunHoursExport, AFaceWithoutRegionsGetsTheFirstBandsEmptyGroup) {
  ShadowedScene shadowed = sun_path_by_hand();
  shadowed.add_face({"dot", {{{{5, 0, 0}, {5, 0, 0}, {5, 0, 0}}, {}}}, "test.json"});
  SunPathHours& path = shadowed.sun_paths[0];
  path.regions.emplace_back();
  path.lit_area.push_back({0, 0, 0, 0});
  const ObjFiles files = sun_hours_obj_export(shadowed, path, hour_bands(path), "m.mtl");
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_TRUE(obj.errors.empty()) << obj.errors.front();
  ASSERT_EQ(obj.groups.size(), 4u);
  EXPECT_EQ(obj.groups[3].name, "dot@0-0.5h");
  EXPECT_TRUE(obj.groups[3].triangles.empty());

  path.regions.pop_back();
  EXPECT_THROW((void)sun_hours_obj_export(shadowed, path, hour_bands(path), "m.mtl"),
               std::invalid_argument);
}

TEST(SunHoursExport, EachGroupsAreaIsItsBandsRegionsAndAFacesGroupsItsArea) {
  const ShadowedScene shadowed = generated(site_scene(kCourtyard, kMarch21));
  ASSERT_EQ(shadowed.sun_paths.size(), 1u);
  const SunPathHours& path = shadowed.sun_paths[0];
  const HourBands bands = hour_bands(path);
  ASSERT_GE(bands.bands.size(), 5u);
  const ObjFiles files = sun_hours_obj_export(shadowed, path, bands, "m.mtl");
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_TRUE(obj.errors.empty()) << obj.errors.front();

  // The database's side: region areas summed by face and band.
  std::map<std::string, double> expected;  // by group name
  std::map<std::string, std::size_t> face_of;
  for (std::size_t f = 0; f < shadowed.scene().faces.size(); ++f) {
    for (const SunHoursRegion& region : path.regions[f]) {
      const std::string name =
          shadowed.scene().faces[f].id + "@" + bands.bands[bands.band_of(region.hours)].name;
      expected[name] += lit_area(region.polygons);
      face_of[name] = f;
    }
  }
  std::vector<double> face_sums(shadowed.scene().faces.size(), 0.0);
  double worst = 0.0;
  std::size_t with_several = 0;
  for (const test::ObjGroup& group : obj.groups) {
    ASSERT_EQ(expected.count(group.name), 1u) << group.name;
    const double area = group_area(group);
    const double error = relative_error(area, expected.at(group.name));
    EXPECT_LE(error, 1e-9) << group.name << ": " << area << " vs " << expected.at(group.name);
    worst = std::max(worst, error);
    face_sums[face_of.at(group.name)] += area;
    const std::string band = group.name.substr(group.name.rfind('@') + 1);
    for (const test::ObjTriangle& t : group.triangles) EXPECT_EQ(t.material, band);
  }
  EXPECT_EQ(obj.groups.size(), expected.size());
  for (std::size_t f = 0; f < face_sums.size(); ++f) {
    const double area = hsr::area(shadowed.scene().faces[f].parts);
    EXPECT_LE(relative_error(face_sums[f], area), 1e-9) << shadowed.scene().faces[f].id;
    with_several += path.regions[f].size() > 1;
  }
  EXPECT_GE(with_several, 2u);  // the ground and the wall, at least, are shaded in part
  std::printf("%zu groups, areas within %.3g of the regions'\n", obj.groups.size(), worst);
}

}  // namespace
}  // namespace shadowgen
