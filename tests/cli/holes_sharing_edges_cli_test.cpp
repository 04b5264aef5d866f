// End to end, a face whose holes share edges with its outer loop and with each other: a
// wall 10 × 3 with a window across its whole width (2 to 2.5 high) and a door below it,
// from the floor to the window, which leave three coplanar parts of the one face 'wall'.
// Every output about it must be that of the same three regions written as three plain
// polygons without holes: the report, the database read back, sun hours, the EnergyPlus
// shading schedule, the OBJ export and the SVG picture.

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"
#include "tests/shadowgen/weather/epw_text.h"
#include "tests/support/obj_text.h"

namespace shadowgen::test {
namespace {

// The wall at y = 0, front side south (-y), under an eave and beside a fin, lit by a sun
// path of 21 March at Greenwich and by a sun of its own; `wall` is its polygon(s).
std::string scene_with(const std::string& wall) {
  return R"({"format": "shadowgen-scene/1",
  "polygons": [)" +
         wall + R"(,
    {"id": "eave", "outer": [[0,-1,3],[10,-1,3],[10,0,3],[0,0,3]]},
    {"id": "fin", "outer": [[7,-1.5,0],[7,0,0],[7,0,3],[7,-1.5,3]]}
  ],
  "site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "utc_offset_h": 0},
  "lights": [{"id": "march21", "type": "sun", "from": "2026-03-21T06:00",
              "to": "2026-03-21T18:30", "step_min": 30},
             {"id": "sun", "type": "directional", "direction": [0.375, 0.75, -0.625]}]
})";
}

const std::string kWithHoles = scene_with(R"(
    {"id": "wall", "outer": [[0,0,0],[10,0,0],[10,0,3],[0,0,3]],
     "holes": [[[0,0,2],[10,0,2],[10,0,2.5],[0,0,2.5]], [[4,0,0],[5,0,0],[5,0,2],[4,0,2]]]})");

const std::string kPlain = scene_with(R"(
    {"id": "left", "outer": [[0,0,0],[4,0,0],[4,0,2],[0,0,2]]},
    {"id": "right", "outer": [[5,0,0],[10,0,0],[10,0,2],[5,0,2]]},
    {"id": "top", "outer": [[0,0,2.5],[10,0,2.5],[10,0,3],[0,0,3]]})");

const std::vector<std::string> kPieces = {"left", "right", "top"};
constexpr double kArea = 30.0 - 5.0 - 2.0;
constexpr double kTolerance = 1e-9;

class HolesSharingEdgesCli : public CliFolderTest<> {
 protected:
  HolesSharingEdgesCli() : CliFolderTest("shadowgen-shared-edges") {}

  // Generates both scenes into databases.
  void SetUp() override {
    CliFolderTest::SetUp();
    holes_ = write("holes.json", kWithHoles);
    plain_ = write("plain.json", kPlain);
    for (const fs::path& scene : {holes_, plain_}) {
      const Outcome generated = run({"generate", scene.string(), "-o",
                                     fs::path(scene).replace_extension(".db.json").string()});
      ASSERT_EQ(generated.code, 0) << generated.err;
      EXPECT_EQ(generated.err, "");
    }
  }

  // `shadowgen report` with `args` after the input, on both databases.
  std::pair<std::string, std::string> reports(const std::vector<std::string>& args) const {
    std::pair<std::string, std::string> out;
    for (const bool with_holes : {true, false}) {
      std::vector<std::string> all{"report", db(with_holes).string()};
      all.insert(all.end(), args.begin(), args.end());
      const Outcome report = run(all);
      EXPECT_EQ(report.code, 0) << report.err;
      (with_holes ? out.first : out.second) = report.out;
    }
    return out;
  }

  fs::path db(bool with_holes) const {
    return fs::path(with_holes ? holes_ : plain_).replace_extension(".db.json");
  }

  fs::path holes_, plain_;
};

TEST_F(HolesSharingEdgesCli, TheReportIsThatOfThePlainPolygons) {
  const auto [holes, plain] = reports({});
  std::map<std::string, double> wall_lit, pieces_lit;
  for (const ReportRow& row : parse_report(holes)) {
    if (row.face != "wall") continue;
    EXPECT_EQ(row.area, kArea);
    wall_lit[row.light] = row.lit_area;
  }
  for (const ReportRow& row : parse_report(plain)) {
    if (row.face == "left" || row.face == "right" || row.face == "top") {
      pieces_lit[row.light] += row.lit_area;
    }
  }
  ASSERT_EQ(wall_lit.size(), pieces_lit.size());
  ASSERT_GT(wall_lit.size(), 20u);  // the path's instants and the sun
  bool shaded = false;
  for (const auto& [light, lit] : wall_lit) {
    EXPECT_NEAR(lit, pieces_lit.at(light), kTolerance * kArea) << light;
    shaded = shaded || (lit > 0.0 && lit < kArea);
  }
  EXPECT_TRUE(shaded);
  // The scene itself gives the database's report.
  const Outcome from_scene = run({"report", holes_.string()});
  EXPECT_EQ(from_scene.out, holes);
}

TEST_F(HolesSharingEdgesCli, SunHoursAreThoseOfThePlainPolygons) {
  const auto [holes, plain] = reports({"--format", "sun-hours", "--threshold", "2,6"});
  std::map<std::string, std::vector<std::string>> rows;
  for (const auto& fields : csv_rows(plain)) rows[fields.at(0)] = fields;
  for (const auto& fields : csv_rows(holes)) {
    if (fields.at(0) != "wall") continue;
    // face_id,sun_path,area,mean_sun_hours,min_sun_hours,max_sun_hours,area_at_least_2h,...
    double area = 0.0, weighted = 0.0, least = 1e9, most = 0.0, two = 0.0, six = 0.0;
    for (const std::string& piece : kPieces) {
      const std::vector<std::string>& p = rows.at(piece);
      area += std::stod(p[2]);
      weighted += std::stod(p[2]) * std::stod(p[3]);
      least = std::min(least, std::stod(p[4]));
      most = std::max(most, std::stod(p[5]));
      two += std::stod(p[6]);
      six += std::stod(p[7]);
    }
    EXPECT_EQ(std::stod(fields[2]), area);
    EXPECT_NEAR(std::stod(fields[3]), weighted / area, 1e-9);
    EXPECT_EQ(std::stod(fields[4]), least);
    EXPECT_EQ(std::stod(fields[5]), most);
    EXPECT_NEAR(std::stod(fields[6]), two, kTolerance * kArea);
    EXPECT_NEAR(std::stod(fields[7]), six, kTolerance * kArea);
    EXPECT_LT(least, most);
    return;
  }
  ADD_FAILURE() << "no row for the wall:\n" << holes;
}

TEST_F(HolesSharingEdgesCli, TheShadingScheduleIsThatOfThePlainPolygons) {
  const auto [holes, plain] = reports({"--format", "energyplus", "--lights", "march21"});
  const auto with_holes = csv_rows(holes);
  const auto pieces = csv_rows(plain);
  ASSERT_EQ(with_holes.size(), pieces.size());
  ASSERT_GT(with_holes.size(), 1u);
  EXPECT_EQ(with_holes[0], (std::vector<std::string>{"Surface Name", "WALL", "EAVE", "FIN", ""}));
  EXPECT_EQ(pieces[0],
            (std::vector<std::string>{"Surface Name", "LEFT", "RIGHT", "TOP", "EAVE", "FIN", ""}));
  for (std::size_t r = 1; r < with_holes.size(); ++r) {
    const double lit = 8.0 * std::stod(pieces[r][1]) + 10.0 * std::stod(pieces[r][2]) +
                       5.0 * std::stod(pieces[r][3]);
    EXPECT_NEAR(std::stod(with_holes[r][1]), lit / kArea, 1e-8) << with_holes[r][0];  // 8 decimals
  }
}

TEST_F(HolesSharingEdgesCli, IrradiationIsThatOfThePlainPolygons) {
  const fs::path epw = write("march.epw", joined(epw_lines(3, 21, 1)));
  const auto [holes, plain] = reports({"--format", "irradiation", "--weather", epw.string()});
  std::map<std::string, std::vector<std::string>> rows;
  for (const auto& fields : csv_rows(plain)) rows[fields.at(0)] = fields;
  for (const auto& fields : csv_rows(holes)) {
    if (fields.at(0) != "wall") continue;
    // face_id,sun_path,area,direct_wh,direct_wh_per_area,unshaded_direct_wh_per_area
    double wh = 0.0;
    for (const std::string& piece : kPieces) wh += std::stod(rows.at(piece).at(3));
    EXPECT_EQ(std::stod(fields.at(2)), kArea);
    EXPECT_NEAR(std::stod(fields.at(3)), wh, kTolerance * wh);
    EXPECT_GT(wh, 0.0);
    EXPECT_NEAR(std::stod(fields.at(5)), std::stod(rows.at("top").at(5)), kTolerance * wh);
    return;
  }
  ADD_FAILURE() << "no row for the wall:\n" << holes;
}

// The triangles of the OBJ group `face`, by material, in square units.
std::map<std::string, double> group_areas(const ObjText& obj, const std::string& face) {
  for (const auto& group : obj.groups) {
    if (group.name == face) return material_areas(group);
  }
  ADD_FAILURE() << "no group " << face;
  return {};
}

TEST_F(HolesSharingEdgesCli, TheObjExportIsThatOfThePlainPolygons) {
  for (const bool with_holes : {true, false}) {
    const fs::path obj = dir_ / (with_holes ? "holes.obj" : "plain.obj");
    const Outcome exported =
        run({"export", db(with_holes).string(), "--lights", "sun", "--obj", obj.string()});
    ASSERT_EQ(exported.code, 0) << exported.err;
  }
  const ObjText holes = parse_obj(contents(dir_ / "holes.obj"));
  const ObjText plain = parse_obj(contents(dir_ / "plain.obj"));
  std::map<std::string, double> pieces;
  for (const std::string& piece : kPieces) {
    for (const auto& [material, area] : group_areas(plain, piece)) pieces[material] += area;
  }
  const std::map<std::string, double> wall = group_areas(holes, "wall");
  ASSERT_EQ(wall.size(), pieces.size());
  double total = 0.0;
  for (const auto& [material, area] : wall) {
    EXPECT_NEAR(area, pieces.at(material), kTolerance * kArea) << material;
    total += area;
  }
  EXPECT_NEAR(total, kArea, kTolerance * kArea);
}

// Square pixels of the paths of `face` lit by `light` in an SVG `render` wrote.
double lit_pixels(const std::string& svg, const std::string& face, const std::string& light) {
  const std::regex path(R"re(<path d="([^"]*)"[^>]* data-face="([^"]*)" data-lights="([^"]*)")re");
  double area = 0.0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator();
       ++it) {
    if ((*it)[2] == face && (*it)[3] == light) area += svg_path_area((*it)[1]);
  }
  return area;
}

TEST_F(HolesSharingEdgesCli, TheSvgPictureIsThatOfThePlainPolygons) {
  for (const bool with_holes : {true, false}) {
    const fs::path svg = dir_ / (with_holes ? "holes.svg" : "plain.svg");
    const Outcome rendered =
        run({"render", db(with_holes).string(), "--lights", "sun", "--eye", "5,-20,1.5", "--target",
             "5,0,1.5", "--ortho", "--scale", "20", "--pieces", "--svg", svg.string()});
    ASSERT_EQ(rendered.code, 0) << rendered.err;
  }
  const std::string holes = contents(dir_ / "holes.svg");
  const std::string plain = contents(dir_ / "plain.svg");
  double pieces_lit = 0.0, pieces_shadow = 0.0;
  for (const std::string& piece : kPieces) {
    pieces_lit += lit_pixels(plain, piece, "sun");
    pieces_shadow += lit_pixels(plain, piece, "shadow");
  }
  const double scale = 20.0 * 20.0;  // square pixels per square unit
  EXPECT_GT(pieces_lit, 0.0);
  EXPECT_GT(pieces_shadow, 0.0);
  EXPECT_NEAR(lit_pixels(holes, "wall", "sun"), pieces_lit, kTolerance * kArea * scale);
  EXPECT_NEAR(lit_pixels(holes, "wall", "shadow"), pieces_shadow, kTolerance * kArea * scale);
}

}  // namespace
}  // namespace shadowgen::test
