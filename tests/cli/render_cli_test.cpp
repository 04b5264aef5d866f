// End-to-end tests of `shadowgen render`: the courtyard example's database drawn from two
// viewpoints after its scene file is gone (so no shadow pass can run), checked by
// xmllint (well-formed XML), rsvg-convert (a PNG comes out) and by measuring the SVG's
// own paths against the report's lit areas; usage and input errors.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

struct SvgAreas {
  double pixels_per_unit = 0.0;
  std::size_t paths = 0;
  // By (face id, light id or "shadow"), in square pixels.
  std::map<std::pair<std::string, std::string>, double> by_face_and_light;
  std::map<std::string, double> by_face;
};

SvgAreas measure(const std::string& svg) {
  SvgAreas result;
  const std::regex scale(R"re(data-pixels-per-unit="([^"]+)")re");
  std::smatch m;
  if (std::regex_search(svg, m, scale)) result.pixels_per_unit = std::stod(m[1]);
  const std::regex path(
      R"re(<path d="([^"]*)" fill="#[0-9a-f]{6}" fill-rule="evenodd" data-face="([^"]*)" data-lights="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator();
       ++it) {
    ++result.paths;
    const double area = svg_path_area((*it)[1]);
    const std::string face = (*it)[2], lights = (*it)[3];
    result.by_face[face] += area;
    std::size_t start = 0;
    while (true) {
      const std::size_t plus = lights.find('+', start);
      result.by_face_and_light[{face, lights.substr(start, plus - start)}] += area;
      if (plus == std::string::npos) break;
      start = plus + 1;
    }
  }
  return result;
}

class RenderCli : public CliFolderTest<> {
 protected:
  RenderCli() : CliFolderTest("shadowgen-render") {}

  void SetUp() override {
    CliFolderTest::SetUp();
    // The courtyard's database, made from a copy of the example that is then deleted.
    const fs::path scene = dir_ / "courtyard.json";
    fs::copy_file(fs::path(SHADOWGEN_EXAMPLES_DIR) / "scenes" / "courtyard.json", scene);
    db_ = dir_ / "courtyard.shadowed.json";
    const Outcome generated = run({"generate", scene.string(), "-o", db_.string()});
    ASSERT_EQ(generated.code, 0) << generated.err;
    const Outcome report = run({"report", db_.string()});
    ASSERT_EQ(report.code, 0) << report.err;
    for (const ReportRow& row : parse_report(report.out)) {
      areas_[row.face] = row.area;
      lit_[{row.face, row.light}] = row.lit_area;
    }
    fs::remove(scene);
  }

  // xmllint finds the file well-formed and rsvg-convert draws it into a non-empty PNG.
  void ExpectValidSvg(const fs::path& svg) const {
    ExpectWellFormedXml(svg, dir_ / "run" / "xmllint");
    const fs::path png = fs::path(svg).replace_extension(".png");
    EXPECT_EQ(shell("rsvg-convert " + quoted(svg.string()) + " -o " + quoted(png.string())), 0);
    ASSERT_TRUE(fs::exists(png));
    const std::string bytes = contents(png);
    EXPECT_GT(bytes.size(), 100u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  }

  fs::path db_;
  std::map<std::string, double> areas_;
  std::map<std::pair<std::string, std::string>, double> lit_;
};

TEST_F(RenderCli, TwoViewpointsFromTheDatabaseAlone) {
  ASSERT_FALSE(fs::exists(dir_ / "courtyard.json"));

  // The database's own view, in perspective.
  const fs::path main_svg = dir_ / "main.svg";
  const Outcome main_view = run({"render", "--pieces", db_.string(), "--view", "main", "--svg",
                                 main_svg.string(), "--width", "640", "--height", "480"});
  ASSERT_EQ(main_view.code, 0) << main_view.err;
  EXPECT_EQ(main_view.out, "");
  EXPECT_EQ(main_view.err, "");
  ExpectValidSvg(main_svg);
  const SvgAreas main_areas = measure(contents(main_svg));
  EXPECT_GT(main_areas.paths, 10u);
  for (const char* face : {"ground", "wall-south", "canopy"}) {
    EXPECT_GT(main_areas.by_face.count(face), 0u) << face;
  }
  // The 640-pixel picture and the light sets' legend, 220 pixels wide, beside it.
  EXPECT_NE(contents(main_svg).find("viewBox=\"0 0 860 480\""), std::string::npos);

  // Straight down from between the canopy (z = 2.5) and the ground: the orthographic
  // camera's near plane through its eye cuts the canopy away, the wall is edge-on, so the
  // whole ground is seen and its lit pieces must add up to the report's lit areas.
  const fs::path top_svg = dir_ / "top.svg";
  const Outcome top = run({"render", "--pieces", db_.string(), "--eye", "10,10,2", "--target",
                           "10,10,0", "--up", "0,1,0", "--ortho", "--scale", "20", "--width", "440",
                           "--height", "440", "--svg", top_svg.string()});
  ASSERT_EQ(top.code, 0) << top.err;
  ExpectValidSvg(top_svg);
  const SvgAreas top_areas = measure(contents(top_svg));
  ASSERT_EQ(top_areas.pixels_per_unit, 20.0);
  const double s2 = 400.0;
  EXPECT_EQ(top_areas.by_face.size(), 1u);  // only the ground
  EXPECT_LE(relative_error(top_areas.by_face.at("ground") / s2, areas_.at("ground")), 1e-9);
  for (const char* light : {"sun", "lamp"}) {
    const double expected = lit_.at({"ground", light});
    ASSERT_GT(expected, 0.0);
    const double measured = top_areas.by_face_and_light.at({"ground", light}) / s2;
    // Holds to 1e-15 here; the contract is 1e-6.
    EXPECT_LE(relative_error(measured, expected), 1e-9)
        << light << ": " << measured << " vs " << expected;
  }
  EXPECT_EQ(files(), (std::vector<std::string>{"courtyard.shadowed.json", "main.png", "main.svg",
                                               "top.png", "top.svg"}));
}

// --lights lamp draws the database as if it held the lamp alone: the same picture as the
// database of the scene without the sun, and the ground's lamp-lit pieces the report's.
TEST_F(RenderCli, LightsDrawsOnlyThoseLights) {
  nlohmann::json scene = nlohmann::json::parse(
      contents(fs::path(SHADOWGEN_EXAMPLES_DIR) / "scenes" / "courtyard.json"));
  scene["lights"].erase(0);
  ASSERT_EQ(scene["lights"][0]["id"], "lamp");
  const fs::path lamp_scene = write("lamp.json", scene.dump(2));
  const fs::path lamp_db = dir_ / "lamp.shadowed.json";
  ASSERT_EQ(run({"generate", lamp_scene.string(), "-o", lamp_db.string()}).code, 0);
  const Outcome alone = run({"render", "--pieces", lamp_db.string(), "--view", "main", "--svg",
                             (dir_ / "alone.svg").string()});
  ASSERT_EQ(alone.code, 0) << alone.err;
  const Outcome picked = run({"render", "--pieces", db_.string(), "--view", "main", "--lights",
                              "lamp", "--svg", (dir_ / "picked.svg").string()});
  ASSERT_EQ(picked.code, 0) << picked.err;
  EXPECT_EQ(contents(dir_ / "picked.svg"), contents(dir_ / "alone.svg"));
  const SvgAreas areas = measure(contents(dir_ / "picked.svg"));
  for (const auto& [face_and_light, area] : areas.by_face_and_light) {
    EXPECT_TRUE(face_and_light.second == "lamp" || face_and_light.second == "shadow")
        << face_and_light.first << ": " << face_and_light.second;
  }
  EXPECT_GT(areas.by_face_and_light.count({"ground", "lamp"}), 0u);

  const Outcome unknown = run({"render", db_.string(), "--view", "main", "--lights", "sunn",
                               "--svg", (dir_ / "no.svg").string()});
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.err.find("--lights names 'sunn', which is not a light of it"),
            std::string::npos)
      << unknown.err;
  EXPECT_FALSE(fs::exists(dir_ / "no.svg"));
}

// --by-light: the base covers what the light-set picture covers, face by face, and each
// light's layer what that picture's pieces lit by the light cover; a valid SVG.
TEST_F(RenderCli, ByLightLayersCoverWhatTheLightSetsCover) {
  const fs::path sets = dir_ / "sets.svg", layers = dir_ / "layers.svg";
  ASSERT_EQ(
      run({"render", "--pieces", db_.string(), "--view", "main", "--svg", sets.string()}).code, 0);
  const Outcome r = run({"render", "--pieces", db_.string(), "--view", "main", "--svg",
                         layers.string(), "--by-light"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  ExpectValidSvg(layers);
  const SvgAreas s = measure(contents(sets)), l = measure(contents(layers));
  ASSERT_FALSE(s.by_face.empty());
  for (const auto& [face, area] : s.by_face) {
    EXPECT_NEAR(l.by_face_and_light.at({face, "shadow"}), area, 1e-6) << face;
    for (const char* light : {"sun", "lamp"}) {
      const auto lit = s.by_face_and_light.find({face, light});
      const auto layer = l.by_face_and_light.find({face, light});
      EXPECT_NEAR(layer == l.by_face_and_light.end() ? 0.0 : layer->second,
                  lit == s.by_face_and_light.end() ? 0.0 : lit->second, 1e-6)
          << face << ", " << light;
    }
  }
  const std::string text = contents(layers);
  EXPECT_NE(text.find("<g style=\"mix-blend-mode:plus-lighter\" data-light=\"sun\">"),
            std::string::npos);
  // Layers are an SVG's; a sun-hours map is not split by lights at all.
  EXPECT_EQ(run({"render", db_.string(), "--view", "main", "--png", (dir_ / "x.png").string(),
                 "--by-light"})
                .code,
            2);
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(RenderCli, PerspectiveFromEyeAndFittedOrthographic) {
  const fs::path inside = dir_ / "inside.svg";
  // From inside the courtyard, under the canopy, looking at the wall's windows.
  const Outcome perspective =
      run({"render", "--pieces", db_.string(), "--eye", "10,9,1.5", "--target", "10,4,1.5", "--fov",
           "100", "--svg", inside.string()});
  ASSERT_EQ(perspective.code, 0) << perspective.err;
  ExpectValidSvg(inside);
  const SvgAreas areas = measure(contents(inside));
  EXPECT_GT(areas.by_face.count("wall-south"), 0u);
  EXPECT_GT(areas.by_face.count("canopy"), 0u);  // overhead, seen from below: its back

  const fs::path fitted = dir_ / "fitted.svg";
  const Outcome ortho = run({"render", "--pieces", db_.string(), "--view", "main", "--ortho",
                             "--svg", fitted.string(), "--width", "300", "--height", "300"});
  ASSERT_EQ(ortho.code, 0) << ortho.err;
  ExpectValidSvg(fitted);
  EXPECT_GT(measure(contents(fitted)).pixels_per_unit, 0.0);
}

TEST_F(RenderCli, UsageErrorsExitTwoAndLeaveNoSvg) {
  const std::string db = db_.string(), svg = (dir_ / "out.svg").string();
  EXPECT_EQ(run({"render", db, "--svg", svg}).code, 2);  // no camera
  EXPECT_EQ(
      run({"render", db, "--view", "main", "--eye", "1,2,3", "--target", "0,0,0", "--svg", svg})
          .code,
      2);                                                                     // both
  EXPECT_EQ(run({"render", db, "--eye", "1,2,3", "--svg", svg}).code, 2);     // no target
  EXPECT_EQ(run({"render", db, "--target", "1,2,3", "--svg", svg}).code, 2);  // no eye
  EXPECT_EQ(run({"render", db, "--eye", "1,2", "--target", "0,0,0", "--svg", svg}).code, 2);
  EXPECT_EQ(run({"render", db, "--eye", "1,2,x", "--target", "0,0,0", "--svg", svg}).code, 2);
  // Beyond the supported coordinate range (it was once "view direction must be finite").
  const Outcome far = run({"render", db, "--eye", "1e300,0,10", "--target", "0,0,0", "--svg", svg});
  EXPECT_EQ(far.code, 2);
  EXPECT_NE(far.err.find("--eye: 1e300,0,10 is outside the supported range"), std::string::npos)
      << far.err;
  EXPECT_EQ(run({"render", db, "--eye", "0,0,1", "--target", "0,-2e100,0", "--svg", svg}).code, 2);
  EXPECT_EQ(run({"render", db, "--view", "main"}).code, 2);  // no --svg
  EXPECT_EQ(run({"render", db, "--view", "main", "--scale", "3", "--svg", svg}).code, 2);
  EXPECT_EQ(run({"render", db, "--view", "main", "--width", "0", "--svg", svg}).code, 2);
  EXPECT_EQ(run({"render", "--view", "main", "--svg", svg}).code, 2);  // no database
  const Outcome usage = run({"render", db, "--svg", svg});
  EXPECT_NE(usage.err.find("--view"), std::string::npos) << usage.err;
  EXPECT_EQ(files(), std::vector<std::string>{"courtyard.shadowed.json"});

  const Outcome help = run({"render", "--help"});
  EXPECT_EQ(help.code, 0);
  for (const char* option : {"--view", "--eye", "--target", "--up", "--fov", "--ortho", "--scale",
                             "--svg", "--width", "--height"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option << "\n" << help.out;
  }
}

// A camera whose picture can show nothing is a usage error naming the option, before any
// work (each once drew an empty picture with exit 0): a field of view whose pixels are
// below the rounding of the eye-target distance, a scale beyond the coordinate range's
// (shadowgen/model/view_limits.h).
TEST_F(RenderCli, ACameraThatCanShowNothingIsAUsageErrorNamingTheOption) {
  const std::string db = db_.string(), svg = (dir_ / "out.svg").string();
  const std::vector<std::string> look = {"render",   db,      "--eye", "30,-40,25",
                                         "--target", "5,5,0", "--svg", svg};
  auto with = [&look](std::vector<std::string> more) {
    more.insert(more.begin(), look.begin(), look.end());
    return more;
  };
  const Outcome narrow = run(with({"--fov", "1e-200"}));
  EXPECT_EQ(narrow.code, 2);
  EXPECT_EQ(narrow.err.rfind(
                "shadowgen: --fov: 1e-200 must be at least 1e-06 and below 180 degrees\n", 0),
            0u)
      << narrow.err;
  // No field of view at all is the same usage error, naming --fov (not the camera).
  const Outcome none = run(with({"--fov", "0"}));
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.err.rfind("shadowgen: --fov: 0 must be at least 1e-06 and below 180 degrees\n", 0),
            0u)
      << none.err;
  const Outcome fine = run(with({"--ortho", "--scale", "1e200"}));
  EXPECT_EQ(fine.code, 2);
  EXPECT_EQ(
      fine.err.rfind(
          "shadowgen: --scale: 1e200 must lie between 1e-100 and 1e+100 pixels per unit\n", 0),
      0u)
      << fine.err;
  const Outcome coarse = run(with({"--ortho", "--scale", "1e-200"}));
  EXPECT_EQ(coarse.code, 2);
  EXPECT_EQ(files(), std::vector<std::string>{"courtyard.shadowed.json"});
  // The ends of the ranges draw.
  EXPECT_EQ(run(with({"--fov", "1e-6"})).code, 0);
  EXPECT_EQ(run(with({"--ortho", "--scale", "1e100"})).code, 0);
}

// An --up that fixes no roll is refused as a view's 'up' is (the same check): zero, or
// along the line of sight (it once drew with an arbitrary roll).
TEST_F(RenderCli, AnUpThatFixesNoRollIsAUsageErrorNamingIt) {
  const std::string db = db_.string(), svg = (dir_ / "out.svg").string();
  const Outcome zero =
      run({"render", db, "--eye", "30,-40,25", "--target", "5,5,0", "--up", "0,0,0", "--svg", svg});
  EXPECT_EQ(zero.code, 2);
  EXPECT_EQ(zero.err,
            "shadowgen: --up 0,0,0: must not be zero\nRun with --help for more information.\n");
  const Outcome along = run(
      {"render", db, "--eye", "5,5,30", "--target", "5,5,0", "--up", "0,1e-9,-2", "--svg", svg});
  EXPECT_EQ(along.code, 2);
  EXPECT_EQ(along.err,
            "shadowgen: --up 0,1e-9,-2: must not be parallel to the direction from --eye to "
            "--target\nRun with --help for more information.\n");
  EXPECT_EQ(files(), std::vector<std::string>{"courtyard.shadowed.json"});
  // Straight down without --up: the default up gives way to +y, north up on a map.
  EXPECT_EQ(run({"render", db, "--eye", "5,5,30", "--target", "5,5,0", "--svg", svg}).code, 0);
}

TEST_F(RenderCli, BadInputExitsOneAndLeavesNoSvg) {
  const std::string svg = (dir_ / "out.svg").string();
  const Outcome unknown = run({"render", db_.string(), "--view", "balcony", "--svg", svg});
  EXPECT_EQ(unknown.code, 1);
  EXPECT_EQ(unknown.err.rfind("shadowgen: ", 0), 0u) << unknown.err;
  EXPECT_NE(unknown.err.find("balcony"), std::string::npos) << unknown.err;
  EXPECT_EQ(std::count(unknown.err.begin(), unknown.err.end(), '\n'), 1) << unknown.err;

  const Outcome same =
      run({"render", db_.string(), "--eye", "1,2,3", "--target", "1,2,3", "--svg", svg});
  EXPECT_EQ(same.code, 1);

  // A scene is not a database: render never runs a shadow pass.
  write("scene.json", R"({"format": "shadowgen-scene/1", "polygons": [], "lights": []})");
  const Outcome scene =
      run({"render", (dir_ / "scene.json").string(), "--view", "main", "--svg", svg});
  EXPECT_EQ(scene.code, 1);
  EXPECT_NE(scene.err.find("scene.json"), std::string::npos) << scene.err;
  fs::remove(dir_ / "scene.json");

  const Outcome missing =
      run({"render", (dir_ / "none.json").string(), "--view", "main", "--svg", svg});
  EXPECT_EQ(missing.code, 1);
  const Outcome unwritable =
      run({"render", db_.string(), "--view", "main", "--svg", (dir_ / "no" / "out.svg").string()});
  EXPECT_EQ(unwritable.code, 1);
  EXPECT_NE(unwritable.err.find("out.svg"), std::string::npos) << unwritable.err;
  EXPECT_EQ(files(), std::vector<std::string>{"courtyard.shadowed.json"});

  // A failed run leaves an existing picture alone.
  write("out.svg", "old picture");
  EXPECT_EQ(run({"render", db_.string(), "--view", "balcony", "--svg", svg}).code, 1);
  EXPECT_EQ(contents(svg), "old picture");
}

}  // namespace
}  // namespace shadowgen::test
