// Reports (shadowgen/report.h): the spec's CSV to the byte, the JSON totals, and the
// table for people to the byte. Scenes are built by hand so that these tests do not depend
// on shadow generation.

#include "shadowgen/output/report.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "hsr/area.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen {
namespace {

using hsr::Polygon3;

Polygon3 rectangle(double x0, double y0, double x1, double y1, double z = 0.0) {
  return {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, {}};
}

// Holes run clockwise, as the scene reader normalises them.
hsr::Loop3 hole(double x0, double y0, double x1, double y1, double z = 0.0) {
  return {{x0, y0, z}, {x0, y1, z}, {x1, y1, z}, {x1, y0, z}};
}

Light directional(std::string id) {
  Light light;
  light.id = std::move(id);
  return light;
}

std::string g17(double x) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.17g", x);
  return buffer.data();
}

// ground: 10 × 10 with a 1 × 2 hole (area 98); sliver: collinear, area 0;
// roof: 4 × 4 at z = 3 (area 16). Lights "sun" and "lamp".
ShadowedScene scene_with_ids(const std::string& ground, const std::string& sun) {
  Scene scene;
  Polygon3 ground_polygon = rectangle(0, 0, 10, 10);
  ground_polygon.holes.push_back(hole(1, 1, 2, 3));
  scene.faces = {Face{ground, {ground_polygon}, "scene.json"},
                 Face{"sliver", {Polygon3{{{0, 0, 1}, {1, 1, 1}, {2, 2, 1}}, {}}}, "scene.json"},
                 Face{"roof", {rectangle(0, 0, 4, 4, 3)}, "scene.json"}};
  scene.lights = {directional(sun), directional("lamp")};
  // ground: the sun lights all but a 4 × 4 shadow (82); the lamp lights a 1 × 1 square.
  Polygon3 ground_lit = ground_polygon;
  ground_lit.holes.push_back(hole(4, 4, 8, 8));
  ShadowedScene s(std::move(scene),
                  LitTable({{{{0, ground_lit}}, {{0, rectangle(9, 9, 10, 10)}}},
                            {{}, {}},
                            {{{0, rectangle(0, 0, 4, 4, 3)}},
                             {{0, rectangle(0, 0, 2, 4, 3)}, {0, rectangle(2, 0, 4, 1, 3)}}}}));
  return s;
}

TEST(ReportCsv, MatchesTheSpecToTheByte) {
  const ShadowedScene s = scene_with_ids("ground", "sun");
  EXPECT_EQ(report_csv(s),
            "face_id,light_id,area,lit_area,lit_fraction\n"
            "ground,sun,98,82,0.83673469387755106\n"
            "ground,lamp,98,1,0.01020408163265306\n"
            "sliver,sun,0,0,0\n"
            "sliver,lamp,0,0,0\n"
            "roof,sun,16,16,1\n"
            "roof,lamp,16,10,0.625\n");
}

TEST(ReportCsv, NumbersArePrintedWithSeventeenDigits) {
  Scene scene;
  scene.faces = {Face{"thin", {rectangle(0, 0, 0.1, 1.0 / 3.0)}, "scene.json"}};
  scene.lights = {directional("sun")};
  ShadowedScene s(std::move(scene), LitTable({{{{0, rectangle(0, 0, 0.1, 0.2)}}}}));
  const double area_value = hsr::area(s.scene().faces[0].parts);
  const double lit_value = lit_area(s.lit()[0][0]);
  EXPECT_EQ(report_csv(s), "face_id,light_id,area,lit_area,lit_fraction\nthin,sun," +
                               g17(area_value) + "," + g17(lit_value) + "," +
                               g17(lit_value / area_value) + "\n");
  // Every number reads back to the same double.
  const std::vector<ReportRow> rows = report_rows(s);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(std::strtod(g17(rows[0].lit_fraction).c_str(), nullptr), rows[0].lit_fraction);
}

TEST(ReportCsv, IdsAreQuotedAsRfc4180Says) {
  const std::string expected_header = "face_id,light_id,area,lit_area,lit_fraction\n";
  auto first_row = [](const std::string& csv) {
    const std::size_t start = csv.find('\n') + 1;
    return csv.substr(start, csv.find(",98,") - start);
  };
  EXPECT_EQ(first_row(report_csv(scene_with_ids("a,b", "sun"))), "\"a,b\",sun");
  EXPECT_EQ(first_row(report_csv(scene_with_ids("say \"hi\"", "sun"))), "\"say \"\"hi\"\"\",sun");
  EXPECT_EQ(first_row(report_csv(scene_with_ids("two\nlines", "sun"))), "\"two\nlines\",sun");
  EXPECT_EQ(first_row(report_csv(scene_with_ids("cr\rhere", "sun"))), "\"cr\rhere\",sun");
  EXPECT_EQ(first_row(report_csv(scene_with_ids("plain id; 'single' quotes", "sun, noon"))),
            "plain id; 'single' quotes,\"sun, noon\"");
  EXPECT_EQ(report_csv(scene_with_ids("a,b", "sun")).substr(0, expected_header.size()),
            expected_header);
}

// Ids a spreadsheet would run as formulas: kept exact by default (the spec's CSV reads
// back byte for byte), guarded with a leading "'" under CsvIds::kSpreadsheetSafe.
TEST(ReportCsv, SpreadsheetSafeIdsCannotStartAFormula) {
  auto first_row = [](const std::string& csv) {
    const std::size_t start = csv.find('\n') + 1;
    return csv.substr(start, csv.find(",98,") - start);
  };
  const ShadowedScene formula = scene_with_ids("=HYPERLINK(\"x\")", "+sun");
  EXPECT_EQ(first_row(report_csv(formula)), "\"=HYPERLINK(\"\"x\"\")\",+sun");
  EXPECT_EQ(first_row(report_csv(formula, CsvIds::kSpreadsheetSafe)),
            "\"'=HYPERLINK(\"\"x\"\")\",'+sun");
  for (const char* id : {"-1", "@cmd", "\tx", "\rx"}) {
    const std::string row =
        first_row(report_csv(scene_with_ids(id, "sun"), CsvIds::kSpreadsheetSafe));
    EXPECT_TRUE(row.rfind("'", 0) == 0 || row.rfind("\"'", 0) == 0) << row;
  }
  // Ids that cannot start a formula are written as they are.
  EXPECT_EQ(first_row(report_csv(scene_with_ids("a-b", "sun="), CsvIds::kSpreadsheetSafe)),
            "a-b,sun=");
}

TEST(ReportRows, OrderAndValues) {
  const std::vector<ReportRow> rows = report_rows(scene_with_ids("ground", "sun"));
  ASSERT_EQ(rows.size(), 6u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].face, i / 2);
    EXPECT_EQ(rows[i].light, i % 2);
  }
  EXPECT_EQ(rows[0].area, 98.0);
  EXPECT_EQ(rows[0].lit_area, 82.0);
  EXPECT_EQ(rows[0].lit_fraction, 82.0 / 98.0);
  EXPECT_EQ(rows[2].lit_fraction, 0.0);  // zero-area face
}

// The face of a point light's seam case: its lit polygons are the face up to rounding,
// a hair over its area. The report clamps such an excess; a real one stays visible.
TEST(ReportRows, LitAreaARoundingOverTheAreaIsClampedALargerExcessIsNot) {
  Scene scene;
  const Polygon3 face = rectangle(0, 0, 0.34, 0.04);
  scene.faces = {Face{"side", {face}, "scene.json"}, Face{"bad", {face}, "scene.json"}};
  scene.lights = {directional("lamp")};
  Polygon3 hair_over = face;
  // A rounding outside the face: its right side an ulp further out.
  hair_over.outer[1].x = hair_over.outer[2].x = std::nextafter(0.34, 1.0);
  ShadowedScene s(std::move(scene),
                  LitTable({{{{0, hair_over}}}, {{{0, rectangle(0, 0, 0.35, 0.04)}}}}));
  ASSERT_GT(hsr::area(hair_over), hsr::area(face));
  const std::vector<ReportRow> rows = report_rows(s);
  EXPECT_EQ(rows[0].lit_area, rows[0].area);
  EXPECT_EQ(rows[0].lit_fraction, 1.0);
  EXPECT_GT(rows[1].lit_fraction, 1.02);  // a defect, not rounding: shown as it is
}

TEST(ReportRows, NoLightsNoRows) {
  ShadowedScene s = scene_with_ids("ground", "sun");
  s.keep_lights({false, false});
  EXPECT_TRUE(report_rows(s).empty());
  EXPECT_EQ(report_csv(s), "face_id,light_id,area,lit_area,lit_fraction\n");
}

// No report holds inf or nan (docs/scene-format.md). A face 1e100 across, at the top of
// the supported coordinate range, has an area of 1e200, which every report gives as it
// is (the Newell vector's length once squared 1e200 and overflowed).
TEST(ReportRows, AFaceAtTheTopOfTheRangeHasItsFiniteArea) {
  Scene scene;
  scene.faces = {Face{"huge", {rectangle(0, 0, 1e100, 1e100)}, "big.json"}};
  scene.lights = {directional("sun")};
  ShadowedScene s(std::move(scene), LitTable({{{{0, rectangle(0, 0, 1e100, 5e99)}}}}));
  const std::vector<ReportRow> rows = report_rows(s);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_DOUBLE_EQ(rows[0].area, 1e200);
  EXPECT_DOUBLE_EQ(rows[0].lit_area, 5e199);
  EXPECT_DOUBLE_EQ(rows[0].lit_fraction, 0.5);
  for (const std::string& text : {report_csv(s), report_json(s), report_table(s)}) {
    EXPECT_EQ(text.find("inf"), std::string::npos) << text;
    EXPECT_EQ(text.find("nan"), std::string::npos) << text;
    EXPECT_NE(text.find("e+"), std::string::npos) << text;
  }
}

// One row per line, numbers in their shortest round-trip form.
TEST(ReportJson, LayoutToTheByte) {
  const ShadowedScene s = scene_with_ids("ground", "sun");
  EXPECT_EQ(report_json(s), R"({
  "format": "shadowgen-report/1",
  "method": {"name":"exact"},
  "rows": [
    {"face_id":"ground","light_id":"sun","area":98.0,"lit_area":82.0,"lit_fraction":0.8367346938775511},
    {"face_id":"ground","light_id":"lamp","area":98.0,"lit_area":1.0,"lit_fraction":0.01020408163265306},
    {"face_id":"sliver","light_id":"sun","area":0.0,"lit_area":0.0,"lit_fraction":0.0},
    {"face_id":"sliver","light_id":"lamp","area":0.0,"lit_area":0.0,"lit_fraction":0.0},
    {"face_id":"roof","light_id":"sun","area":16.0,"lit_area":16.0,"lit_fraction":1.0},
    {"face_id":"roof","light_id":"lamp","area":16.0,"lit_area":10.0,"lit_fraction":0.625}
  ],
  "lights": [
    {"light_id":"sun","area":114.0,"lit_area":98.0,"lit_fraction":0.8596491228070176},
    {"light_id":"lamp","area":114.0,"lit_area":11.0,"lit_fraction":0.09649122807017543}
  ],
  "totals": {"area":228.0,"lit_area":109.0,"lit_fraction":0.4780701754385965}
}
)");
}

TEST(ReportJson, AModelFileFacesOriginFollowsItsId) {
  ShadowedScene s = scene_with_ids("ground", "sun");
  s.edit_face(2, [&](Face& face) { face.origin = {"cityjson", "b1-part", "b1", "RoofSurface"}; });
  const std::string text = report_json(s);
  EXPECT_NE(
      text.find(
          R"({"face_id":"roof","origin":{"format":"cityjson","object":"b1-part","group":"b1","semantic":"RoofSurface"},"light_id":"sun",)"),
      std::string::npos)
      << text;
  EXPECT_EQ(text.find(R"({"face_id":"ground","origin")"), std::string::npos);
}

TEST(ReportJson, RowsAndTotals) {
  const ShadowedScene s = scene_with_ids("ground", "sun");
  const nlohmann::json json = nlohmann::json::parse(report_json(s));
  EXPECT_EQ(json["format"], "shadowgen-report/1");

  const nlohmann::json& rows = json["rows"];
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0]["face_id"], "ground");
  EXPECT_EQ(rows[0]["light_id"], "sun");
  EXPECT_EQ(rows[0]["area"], 98.0);
  EXPECT_EQ(rows[0]["lit_area"], 82.0);
  EXPECT_EQ(rows[0]["lit_fraction"], 82.0 / 98.0);
  EXPECT_EQ(rows[3]["face_id"], "sliver");
  EXPECT_EQ(rows[3]["lit_fraction"], 0.0);
  EXPECT_EQ(rows[5]["lit_area"], 10.0);

  const nlohmann::json& lights = json["lights"];
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0]["light_id"], "sun");
  EXPECT_EQ(lights[0]["area"], 114.0);
  EXPECT_EQ(lights[0]["lit_area"], 98.0);
  EXPECT_EQ(lights[0]["lit_fraction"], 98.0 / 114.0);
  EXPECT_EQ(lights[1]["light_id"], "lamp");
  EXPECT_EQ(lights[1]["area"], 114.0);
  EXPECT_EQ(lights[1]["lit_area"], 11.0);
  EXPECT_EQ(lights[1]["lit_fraction"], 11.0 / 114.0);

  EXPECT_EQ(json["totals"]["area"], 228.0);
  EXPECT_EQ(json["totals"]["lit_area"], 109.0);
  EXPECT_EQ(json["totals"]["lit_fraction"], 109.0 / 228.0);
}

TEST(ReportJson, TotalsAreCompensatedSums) {
  // 1 + 1e-16 × 1000: a naive running sum stays at 1, the compensated one does not.
  Scene scene;
  scene.lights = {directional("sun")};
  scene.faces.push_back(Face{"big", {rectangle(0, 0, 1, 1)}, "scene.json"});
  const double side = 1e-8;  // area about 1e-16, below half an ulp of 1
  for (int i = 0; i < 1000; ++i) {
    scene.faces.push_back(
        Face{"tiny" + std::to_string(i), {rectangle(0, 0, side, side)}, "scene.json"});
  }
  LitTable lit(scene.faces.size(), 1);
  ShadowedScene s(std::move(scene), std::move(lit));
  const double tiny = hsr::area(s.scene().faces[1].parts);
  const nlohmann::json json = nlohmann::json::parse(report_json(s));
  const double total = json["totals"]["area"].get<double>();
  EXPECT_GT(total, 1.0);
  EXPECT_NEAR(total, 1.0 + 1000.0 * tiny, 1e-15);
}

TEST(ReportJson, SpecialIdsAndEmptyScenes) {
  const nlohmann::json json =
      nlohmann::json::parse(report_json(scene_with_ids("say \"hi\",\nthere", "s\\un")));
  EXPECT_EQ(json["rows"][0]["face_id"], "say \"hi\",\nthere");
  EXPECT_EQ(json["lights"][0]["light_id"], "s\\un");

  const nlohmann::json empty = nlohmann::json::parse(report_json(ShadowedScene{}));
  EXPECT_TRUE(empty["rows"].empty());
  EXPECT_TRUE(empty["lights"].empty());
  EXPECT_EQ(empty["totals"]["area"], 0.0);
  EXPECT_EQ(empty["totals"]["lit_fraction"], 0.0);
}

TEST(ReportTable, TotalsPerLightThenTheMostShadowedFaces) {
  // sun: 114 in all, 98 lit; lamp: 11 lit. The sliver (area 0) is counted among the faces
  // but has nothing to shadow, so it is not listed.
  EXPECT_EQ(report_table(scene_with_ids("ground", "sun")),
            "light_id  faces  lit_faces  area  lit_area  lit_fraction\n"
            "sun           3          2   114        98        0.8596\n"
            "lamp          3          2   114        11        0.0965\n"
            "\n"
            "most shadowed faces under sun (lowest lit fraction first, 2 of 2)\n"
            "face_id  area  lit_area  lit_fraction\n"
            "ground     98        82        0.8367\n"
            "roof       16        16        1.0000\n"
            "\n"
            "most shadowed faces under lamp (lowest lit fraction first, 2 of 2)\n"
            "face_id  area  lit_area  lit_fraction\n"
            "ground     98         1        0.0102\n"
            "roof       16        10        0.6250\n");
}

TEST(ReportTable, TopLimitsTheListsAndZeroLeavesThemOut) {
  const ShadowedScene s = scene_with_ids("ground", "sun");
  const std::string one = report_table(s, 1);
  EXPECT_NE(one.find("most shadowed faces under lamp (lowest lit fraction first, 1 of 2)\n"
                     "face_id  area  lit_area  lit_fraction\n"
                     "ground     98         1        0.0102\n"),
            std::string::npos)
      << one;
  EXPECT_EQ(one.find("roof"), std::string::npos) << one;

  EXPECT_EQ(report_table(s, 0),
            "light_id  faces  lit_faces  area  lit_area  lit_fraction\n"
            "sun           3          2   114        98        0.8596\n"
            "lamp          3          2   114        11        0.0965\n");
}

TEST(ReportTable, TiesKeepSceneOrder) {
  Scene scene;
  scene.lights = {directional("sun")};
  ShadowedScene s(std::move(scene), LitTable(0, 1));
  for (const char* id : {"c", "a", "b"}) {
    s.add_face(Face{id, {rectangle(0, 0, 2, 2)}, "scene.json"});
    s.lit_at(s.scene().faces.size() - 1, 0) = {{0, rectangle(0, 0, 1, 2)}};  // each half lit
  }
  const std::string table = report_table(s);
  EXPECT_NE(table.find("face_id  area  lit_area  lit_fraction\n"
                       "c           4         2        0.5000\n"
                       "a           4         2        0.5000\n"
                       "b           4         2        0.5000\n"),
            std::string::npos)
      << table;
}

TEST(ReportTable, IdsStayOnOneLineAndLineUp) {
  // A line break is shown escaped; "é" (two bytes) takes one column, like "e".
  ShadowedScene s = scene_with_ids("two\nlines", "sol\xc3\xa9il");
  const std::string table = report_table(s, 0);
  EXPECT_EQ(table,
            "light_id  faces  lit_faces  area  lit_area  lit_fraction\n"
            "sol\xc3\xa9il        3          2   114        98        0.8596\n"
            "lamp          3          2   114        11        0.0965\n");
  const std::string lists = report_table(s, 1);
  EXPECT_NE(lists.find("most shadowed faces under sol\xc3\xa9il"), std::string::npos) << lists;
  EXPECT_NE(lists.find("two\\nlines    98        82        0.8367\n"), std::string::npos) << lists;
}

TEST(ReportTable, AreasHaveSixSignificantDigits) {
  Scene scene;
  scene.lights = {directional("sun")};
  scene.faces = {Face{"big", {rectangle(0, 0, 1000, 1234.5678)}, "scene.json"},
                 Face{"small", {rectangle(0, 0, 1e-4, 1e-4)}, "scene.json"}};
  ShadowedScene s(std::move(scene), LitTable({{{{0, rectangle(0, 0, 1000, 1000)}}}, {{}}}));
  const std::string table = report_table(s);
  EXPECT_NE(table.find("sun           2          1  1.23457e+06     1e+06        0.8100\n"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("face_id         area  lit_area  lit_fraction\n"
                       "small          1e-08         0        0.0000\n"
                       "big      1.23457e+06     1e+06        0.8100\n"),
            std::string::npos)
      << table;
}

TEST(ReportTable, NoLights) {
  EXPECT_EQ(report_table(ShadowedScene{}),
            "light_id  faces  lit_faces  area  lit_area  lit_fraction\n(no lights)\n");
}

}  // namespace
}  // namespace shadowgen
