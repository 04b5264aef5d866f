// Sums over groups of faces (shadowgen/output/group_sums.h) and the reports' group tables
// (report.h, sun_hours_report.h), on databases made by hand with known areas: each group's
// sums against the sums of its faces' own rows, taken apart here, and the tables to the
// byte.

#include "shadowgen/output/group_sums.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "shadowgen/output/report.h"
#include "shadowgen/output/sun_hours_report.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

using groups::FaceGroup;
using hsr::Polygon3;

Polygon3 rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}}, {}};
}

Light light(std::string id) {
  Light l;
  l.id = std::move(id);
  return l;
}

// a: 10 × 10, the sun lights 4 × 5 of it (20), the lamp nothing; b: 2 × 3, the sun lights
// it whole (6), the lamp 1 × 1; c/0: 4 × 4 less a 1 × 2 hole (14), the sun lights 3 × 2 (6),
// the lamp nothing.
ShadowedScene three_faces() {
  Scene scene;
  scene.file = "hand.json";
  Polygon3 c = rectangle(0, 20, 4, 24);
  c.holes.push_back({{1, 21, 0}, {1, 23, 0}, {2, 23, 0}, {2, 21, 0}});
  scene.faces = {Face{"a", {rectangle(0, 0, 10, 10)}, "hand.json"},
                 Face{"b", {rectangle(20, 0, 22, 3)}, "hand.json"}, Face{"c/0", {c}, "hand.json"}};
  scene.lights = {light("sun"), light("lamp")};
  ShadowedScene s(std::move(scene),
                  LitTable({{{{0, rectangle(0, 0, 4, 5)}}, {}},
                            {{{0, rectangle(20, 0, 22, 3)}}, {{0, rectangle(20, 0, 21, 1)}}},
                            {{{0, rectangle(2, 20, 4, 23)}}, {}}}));
  return s;
}

const std::vector<FaceGroup> kGroups{{"ab", {0, 1}}, {"all", {0, 1, 2}}, {"c", {2}}};

TEST(GroupLitRows, EachGroupSumsItsFacesRows) {
  const ShadowedScene s = three_faces();
  const std::vector<ReportRow> rows = report_rows(s);
  const std::vector<GroupLitRow> sums = group_lit_rows(rows, 2, kGroups);
  ASSERT_EQ(sums.size(), 6u);  // (group, light), groups first
  for (const GroupLitRow& sum : sums) {
    double area = 0.0, lit = 0.0;
    for (const std::size_t f : kGroups[sum.group].faces) {
      area += rows[f * 2 + sum.light].area;
      lit += rows[f * 2 + sum.light].lit_area;
    }
    EXPECT_EQ(sum.faces, kGroups[sum.group].faces.size());
    EXPECT_EQ(sum.area, area);
    EXPECT_EQ(sum.lit_area, lit);
    EXPECT_EQ(sum.lit_fraction, lit / area);
  }
  // The known areas: ab under the sun 26 of 106, under the lamp 1; all 32 and 1 of 120.
  EXPECT_EQ(sums[0].group, 0u);
  EXPECT_EQ(sums[0].light, 0u);
  EXPECT_EQ(sums[0].area, 106.0);
  EXPECT_EQ(sums[0].lit_area, 26.0);
  EXPECT_EQ(sums[1].lit_area, 1.0);
  EXPECT_EQ(sums[2].area, 120.0);
  EXPECT_EQ(sums[2].lit_area, 32.0);
  EXPECT_EQ(sums[3].lit_area, 1.0);
  EXPECT_EQ(sums[4].area, 14.0);
  EXPECT_EQ(sums[4].lit_area, 6.0);
  EXPECT_EQ(sums[5].lit_fraction, 0.0);
}

TEST(ReportCsv, GroupsFollowTheRowsAfterAnEmptyLine) {
  const std::vector<FaceGroup> ab{kGroups[0]};
  EXPECT_EQ(report_csv(three_faces(), CsvIds::kExact, ab),
            "face_id,light_id,area,lit_area,lit_fraction\n"
            "a,sun,100,20,0.20000000000000001\n"
            "a,lamp,100,0,0\n"
            "b,sun,6,6,1\n"
            "b,lamp,6,1,0.16666666666666666\n"
            "c/0,sun,14,6,0.42857142857142855\n"
            "c/0,lamp,14,0,0\n"
            "\n"
            "group_id,light_id,faces,area,lit_area,lit_fraction\n"
            "ab,sun,2,106,26,0.24528301886792453\n"
            "ab,lamp,2,106,1,0.009433962264150943\n");
  EXPECT_EQ(report_csv(three_faces()).find("group_id"), std::string::npos);
}

TEST(ReportJson, GroupsComeAfterTheTotalsOneEntryPerGroupAndLight) {
  const nlohmann::json json = nlohmann::json::parse(report_json(three_faces(), kGroups));
  ASSERT_EQ(json["groups"].size(), 6u);
  EXPECT_EQ(json["groups"][2],
            nlohmann::json::parse(R"({"group_id": "all", "light_id": "sun", "faces": 3,
                                      "area": 120.0, "lit_area": 32.0,
                                      "lit_fraction": 0.26666666666666666})"));
  EXPECT_FALSE(nlohmann::json::parse(report_json(three_faces())).contains("groups"));
}

TEST(ReportTable, AGroupBlockFollowsTheLightsTotals) {
  EXPECT_EQ(report_table(three_faces(), 0, kGroups),
            "light_id  faces  lit_faces  area  lit_area  lit_fraction\n"
            "sun           3          3   120        32        0.2667\n"
            "lamp          3          1   120         1        0.0083\n"
            "\n"
            "groups (each face counted once in each group it is in)\n"
            "group_id  light_id  faces  area  lit_area  lit_fraction\n"
            "ab        sun           2   106        26        0.2453\n"
            "ab        lamp          2   106         1        0.0094\n"
            "all       sun           3   120        32        0.2667\n"
            "all       lamp          3   120         1        0.0083\n"
            "c         sun           1    14         6        0.4286\n"
            "c         lamp          1    14         0        0.0000\n");
}

// test::sun_path_by_hand's face g (4 × 1: 0 h on 1, 1.5 h on 2, 2 h on 1) and a face h,
// 2 × 1: 1 h on one half, 2.5 h on the other.
ShadowedScene two_faces_in_the_sun() {
  ShadowedScene s = test::sun_path_by_hand();
  s.add_face({"h", {rectangle(0, 2, 2, 3)}, "test.json"});
  SunPathHours& path = s.sun_paths[0];
  path.lit_area.push_back({1, 1, 2, 1});
  path.part_lit_area.push_back({});
  path.regions.push_back(
      {{1.0, {{0, rectangle(0, 2, 1, 3)}}}, {2.5, {{0, rectangle(1, 2, 2, 3)}}}});
  return s;
}

TEST(GroupSunHoursRows, EachGroupSumsItsFacesAreasAndWeighsTheirMeans) {
  const std::vector<double> thresholds{1.5, 2};
  const ShadowedScene s = two_faces_in_the_sun();
  const std::vector<SunHoursRow> rows = sun_hours_rows(s, thresholds);
  const std::vector<FaceGroup> groups{{"gh", {0, 1}}, {"h", {1}}};
  const std::vector<GroupSunHoursRow> sums = group_sun_hours_rows(rows, 1, groups);
  ASSERT_EQ(sums.size(), 2u);
  const GroupSunHoursRow& gh = sums[0];
  EXPECT_EQ(gh.faces, 2u);
  EXPECT_EQ(gh.area, rows[0].area + rows[1].area);
  EXPECT_EQ(gh.area, 6.0);
  EXPECT_DOUBLE_EQ(gh.mean_hours, (rows[0].mean_hours * 4 + rows[1].mean_hours * 2) / 6);
  EXPECT_DOUBLE_EQ(gh.mean_hours, (1.25 * 4 + 1.75 * 2) / 6);
  EXPECT_EQ(gh.min_hours, 0.0);
  EXPECT_EQ(gh.max_hours, 2.5);
  EXPECT_EQ(gh.area_at_least,
            (std::vector<double>{rows[0].area_at_least[0] + rows[1].area_at_least[0],
                                 rows[0].area_at_least[1] + rows[1].area_at_least[1]}));
  EXPECT_EQ(gh.area_at_least, (std::vector<double>{4, 2}));
  EXPECT_EQ(gh.share_at_least, (std::vector<double>{4.0 / 6, 2.0 / 6}));
  EXPECT_EQ(sums[1].min_hours, 1.0);
  EXPECT_EQ(sums[1].mean_hours, 1.75);

  EXPECT_EQ(sun_hours_csv(s, thresholds, CsvIds::kExact, groups),
            "face_id,sun_path,area,mean_sun_hours,min_sun_hours,max_sun_hours,"
            "area_at_least_1.5h,area_at_least_2h\n"
            "g,p,4,1.25,0,2,3,1\n"
            "h,p,2,1.75,1,2.5,1,1\n"
            "\n"
            "group_id,sun_path,faces,area,mean_sun_hours,min_sun_hours,max_sun_hours,"
            "area_at_least_1.5h,area_at_least_2h,share_at_least_1.5h,share_at_least_2h\n"
            "gh,p,2,6,1.4166666666666667,0,2.5,4,2,0.66666666666666663,0.33333333333333331\n"
            "h,p,1,2,1.75,1,2.5,1,1,0.5,0.5\n");
}

}  // namespace
}  // namespace shadowgen
