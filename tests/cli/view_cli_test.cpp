// End-to-end tests of `shadowgen view`: the page's folder and its refusals, and the page
// itself opened from its file:// URL in headless Chromium (Debian's chromium, driven by
// playwright-core through web/test/viewer_check.mjs): no console error, no failed
// request, and, seen from above, the pixels where the database says lit or shadowed
// showing the colours of those light sets. Each example scene's page is opened the same
// way. The browser tests are skipped, saying why, only where node, chromium, the npm
// packages (web/install.sh) or the page's assets (built from web/ with them) are missing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

const fs::path kExamples = fs::path(SHADOWGEN_EXAMPLES_DIR);
const fs::path kWeb = fs::path(SHADOWGEN_WEB_DIR);

// Why the page cannot be opened in a browser here; empty when it can.
std::string browser_missing() {
  const char* set = std::getenv("CHROMIUM");
  const fs::path chromium = set != nullptr && *set != '\0' ? fs::path(set) : "/usr/bin/chromium";
  if (shell("command -v node >/dev/null 2>&1") != 0) return "node is not installed";
  if (!fs::exists(chromium)) return chromium.string() + " is not installed (apt: chromium)";
  if (!fs::exists(kWeb / "node_modules" / "playwright-core")) {
    return "the npm packages are not installed (run web/install.sh)";
  }
  if (!fs::exists(fs::path(SHADOWGEN_EXECUTABLE).parent_path() / "viewer" / "viewer.js")) {
    return "the page's assets were not built (node and web/install.sh before cmake)";
  }
  return "";
}

#define SKIP_WITHOUT_BROWSER()                                                   \
  do {                                                                           \
    const std::string missing = browser_missing();                               \
    if (!missing.empty()) GTEST_SKIP() << "viewer page not opened: " << missing; \
  } while (false)

// What web/test/viewer_check.mjs said of the page in `page` (its JSON), with `extra` for
// its command line; a failed run fails the test and gives null.
nlohmann::json check_page(const fs::path& page, const std::string& extra, const fs::path& scratch) {
  const fs::path out = scratch / "check.json";
  const fs::path err = scratch / "check.err";
  const int code = shell("node " + quoted((kWeb / "test" / "viewer_check.mjs").string()) + " " +
                         quoted(page.string()) + " " + extra + " >" + quoted(out.string()) + " 2>" +
                         quoted(err.string()));
  EXPECT_EQ(code, 0) << contents(err);
  if (code != 0) return nullptr;
  return nlohmann::json::parse(contents(out));
}

// A page that loaded cleanly: drawn, nothing logged as an error, nothing failed to load,
// nothing asked of the network.
void ExpectCleanPage(const nlohmann::json& result) {
  ASSERT_FALSE(result.is_null());
  EXPECT_EQ(result["ready"], true) << result.dump();
  EXPECT_EQ(result["console_errors"], nlohmann::json::array()) << result.dump();
  EXPECT_EQ(result["page_errors"], nlohmann::json::array()) << result.dump();
  EXPECT_EQ(result["failed_requests"], nlohmann::json::array()) << result.dump();
  EXPECT_EQ(result["network_requests"], nlohmann::json::array()) << result.dump();
}

// A ground 20 × 20 centred on the origin and a closed box 4 × 4 × 4 on [-2,2]², under two
// equal suns: "east" travelling +x as it falls 1 (its shadow on the ground beyond the
// box: [2,6] × [-2,2]) and "diag" travelling +x and +y (the box's footprint swept by
// (4,4): the hexagon (-2,-2) (2,-2) (6,2) (6,6) (2,6) (-2,2), area 48). Seen from above:
//   (3.5, 1) in both shadows (the triangle (2,-2) (6,2) (2,2)): light set "shadow";
//   (5, -1) in east's shadow alone: lit by "diag";
//   (4, 4) in diag's shadow alone: lit by "east";
//   (-6, 6) on the ground and (0, 0, 4) on the box's top: lit by both.
// The ground's lit areas: east 400 − 16 − 16 = 368, diag 400 − 48 = 352.
constexpr const char* kBoxScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[-10,-10,0],[10,-10,0],[10,10,0],[-10,10,0]]},
    {"id": "top", "outer": [[-2,-2,4],[2,-2,4],[2,2,4],[-2,2,4]]},
    {"id": "south", "outer": [[-2,-2,0],[2,-2,0],[2,-2,4],[-2,-2,4]]},
    {"id": "east", "outer": [[2,-2,0],[2,2,0],[2,2,4],[2,-2,4]]},
    {"id": "north", "outer": [[2,2,0],[-2,2,0],[-2,2,4],[2,2,4]]},
    {"id": "west", "outer": [[-2,2,0],[-2,-2,0],[-2,-2,4],[-2,2,4]]}
  ],
  "lights": [
    {"id": "east", "type": "directional", "direction": [1,0,-1]},
    {"id": "diag", "type": "directional", "direction": [1,1,-1]}
  ]
})";

class ViewCli : public CliFolderTest<> {
 protected:
  ViewCli() : CliFolderTest("view-cli") {}
  // The path of `name` in the test's folder.
  std::string at(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(ViewCli, WritesThePageItsScriptAndItsModelIntoTheFolder) {
  write("scene.json", kBoxScene);
  ASSERT_EQ(run({"generate", at("scene.json"), "-o", at("db.json"), "--quiet"}).code, 0);
  if (!fs::exists(fs::path(SHADOWGEN_EXECUTABLE).parent_path() / "viewer" / "index.html")) {
    GTEST_SKIP() << "the page's assets were not built (node and web/install.sh before cmake)";
  }
  const Outcome outcome = run({"view", at("db.json"), "-o", at("page")});
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  EXPECT_EQ(files(dir_ / "page"),
            (std::vector<std::string>{"index.html", "model.js", "viewer.js"}));
  const std::string model = contents(dir_ / "page" / "model.js");
  EXPECT_EQ(model.rfind("window.shadowgenModel = {\"meta\": ", 0), 0u);
  EXPECT_NE(model.find("\"name\":\"east+diag\""), std::string::npos);
  // A scene is generated first, as by export.
  ASSERT_EQ(run({"view", at("scene.json"), "-o", at("page2")}).code, 0);
  // The same model but for the title, the input's file name.
  const std::string model2 = contents(dir_ / "page2" / "model.js");
  EXPECT_NE(model.find("\"title\":\"db.json\""), std::string::npos);
  EXPECT_EQ(model2.substr(model2.find("\"total_intensity\"")),
            model.substr(model.find("\"total_intensity\"")));
}

TEST_F(ViewCli, BadRequestsAreRefusedWithAMessage) {
  write("scene.json", kBoxScene);
  ASSERT_EQ(run({"generate", at("scene.json"), "-o", at("db.json"), "--quiet"}).code, 0);
  Outcome outcome = run({"view", at("db.json"), "-o", "-"});
  EXPECT_EQ(outcome.code, 2);
  EXPECT_NE(outcome.err.find("shadowgen: -o -: a page is a folder of files, not one stream"),
            std::string::npos)
      << outcome.err;
  outcome = run({"view", at("db.json")});
  EXPECT_EQ(outcome.code, 2);
  EXPECT_NE(outcome.err.find("--output is required"), std::string::npos) << outcome.err;
  if (!browser_missing().empty() &&
      !fs::exists(fs::path(SHADOWGEN_EXECUTABLE).parent_path() / "viewer" / "index.html")) {
    GTEST_SKIP() << "the page's assets were not built: the rest needs them";
  }
  outcome = run({"view", at("db.json"), "-o", at("page"), "--sun-hours", "march21"});
  EXPECT_EQ(outcome.code, 1);
  EXPECT_EQ(outcome.err, "shadowgen: " + at("db.json") +
                             ": has no sun path (a `sun` light with from, to and step_min), so no "
                             "sun hours of 'march21'\n");
  write("taken", "a file");
  outcome = run({"view", at("db.json"), "-o", at("taken")});
  EXPECT_EQ(outcome.code, 1);
  EXPECT_EQ(outcome.err,
            "shadowgen: cannot write the viewer page into '" + at("taken") + "': not a folder\n");
  EXPECT_EQ(contents(dir_ / "taken"), "a file");
}

TEST_F(ViewCli, PixelsWhereTheDatabaseSaysLitOrShadowedShowThoseLightSetsColours) {
  SKIP_WITHOUT_BROWSER();
  write("scene.json", kBoxScene);
  ASSERT_EQ(run({"generate", at("scene.json"), "-o", at("db.json"), "--quiet"}).code, 0);
  // The database's lit areas are the hand-computed ones, so its regions are those above.
  const Outcome report = run({"report", at("db.json")});
  ASSERT_EQ(report.code, 0) << report.err;
  const std::vector<ReportRow> rows = parse_report(report.out);
  ASSERT_GE(rows.size(), 2u);
  EXPECT_EQ(rows[0].face, "ground");
  EXPECT_EQ(rows[0].light, "east");
  EXPECT_LT(relative_error(rows[0].lit_area, 368.0), 1e-12);
  EXPECT_EQ(rows[1].light, "diag");
  EXPECT_LT(relative_error(rows[1].lit_area, 352.0), 1e-12);

  const Outcome outcome = run({"view", at("db.json"), "-o", at("page")});
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  write("points.json", R"([
    {"name": "shadow", "at": [3.5, 1, 0]},
    {"name": "diag", "at": [5, -1, 0]},
    {"name": "east", "at": [4, 4, 0]},
    {"name": "east+diag", "at": [-6, 6, 0]},
    {"name": "east+diag", "at": [0, 0, 4]}
  ])");
  const nlohmann::json result =
      check_page(dir_ / "page",
                 "--hash " + quoted("camera=top&panels=off") + " --points " +
                     quoted((dir_ / "points.json").string()),
                 dir_);
  ExpectCleanPage(result);
  if (result.is_null() || result["ready"] != true) return;
  // The colours of obj_export.h's rule in sRGB bytes: shadow 0.2, one of two equal lights
  // 0.6, both 1.
  const std::map<std::string, int> expected = {
      {"shadow", 51}, {"diag", 153}, {"east", 153}, {"east+diag", 255}};
  ASSERT_EQ(result["points"].size(), 5u);
  for (const nlohmann::json& point : result["points"]) {
    SCOPED_TRACE(point.dump());
    ASSERT_TRUE(point["rgb"].is_array());
    for (int c = 0; c < 3; ++c) {
      // Within one step of the byte: the sRGB colour through three.js's linear working space.
      EXPECT_NEAR(point["rgb"][c].get<int>(), expected.at(point["name"]), 1);
    }
  }
  // The points' pixels differ from the background (#f4f4f2): the scene fills the view.
  EXPECT_NE(result["points"][3]["rgb"], nlohmann::json({244, 244, 242}));
}

TEST_F(ViewCli, ALightSwitchedOffAndTheFaceUnderThePointerShowWhatTheDatabaseSays) {
  SKIP_WITHOUT_BROWSER();
  write("scene.json", kBoxScene);
  ASSERT_EQ(run({"generate", at("scene.json"), "-o", at("db.json"), "--quiet"}).code, 0);
  ASSERT_EQ(run({"view", at("db.json"), "-o", at("page")}).code, 0);
  write("points.json", R"([
    {"name": "shadow", "at": [3.5, 1, 0]},
    {"name": "diag", "at": [5, -1, 0]},
    {"name": "east", "at": [4, 4, 0]},
    {"name": "east+diag", "at": [-6, 6, 0]}
  ])");
  const nlohmann::json result =
      check_page(dir_ / "page",
                 "--hash " + quoted("camera=top&panels=off") + " --switch-off light:diag" +
                     " --hover 3.5,1,0 --points " + quoted((dir_ / "points.json").string()),
                 dir_);
  ExpectCleanPage(result);
  if (result.is_null() || result["ready"] != true) return;
  // With diag off, what it alone lit is in shadow (0.2), and what both lit is east's (0.6).
  const std::map<std::string, int> expected = {
      {"shadow", 51}, {"diag", 51}, {"east", 153}, {"east+diag", 153}};
  ASSERT_EQ(result["points"].size(), 4u);
  for (const nlohmann::json& point : result["points"]) {
    SCOPED_TRACE(point.dump());
    ASSERT_TRUE(point["rgb"].is_array());
    EXPECT_NEAR(point["rgb"][0].get<int>(), expected.at(point["name"]), 1);
  }
  // The ground's id, area and lit areas (368 and 352 of 400), and the light set there.
  EXPECT_EQ(result["hover"],
            nlohmann::json({"face ground", "area 400 m²", "lit by east: 368 m² (92.0 %)",
                            "lit by diag: 352 m² (88.0 %)", "here: shadow (no light)"}));
}

TEST_F(ViewCli, TheNorthArrowPointsToTrueNorthFromTheSitesNorthAxis) {
  SKIP_WITHOUT_BROWSER();
  // The scene's +y is 30° clockwise from true north, so seen from above with +y up the
  // screen, north is 30° counter-clockwise from up: -30°. Without a site, +y: 0°.
  std::string scene = kBoxScene;
  scene.insert(
      scene.find("\"lights\""),
      R"("site": {"latitude_deg": 51.5, "longitude_deg": 0, "utc_offset_h": 0, "north_axis_deg": 30}, )");
  write("scene.json", scene);
  ASSERT_EQ(run({"view", at("scene.json"), "-o", at("page")}).code, 0);
  nlohmann::json result = check_page(dir_ / "page", "--hash camera=top", dir_);
  ExpectCleanPage(result);
  if (result.is_null() || result["ready"] != true) return;
  EXPECT_NEAR(result["north"].get<double>(), -30.0, 1e-6);
  write("scene.json", kBoxScene);
  ASSERT_EQ(run({"view", at("scene.json"), "-o", at("page")}).code, 0);
  result = check_page(dir_ / "page", "--hash camera=top", dir_);
  ASSERT_FALSE(result.is_null());
  EXPECT_NEAR(result["north"].get<double>(), 0.0, 1e-6);
}

// Every example scene's pages, as the build target example_viewer_pages makes them
// (examples/view_examples.sh, here into the test's folder): the scene's page and, for a
// scene with a sun path, its sun-hours page; each loads cleanly and draws.
class ExampleViewerPage : public CliFolderTest<::testing::TestWithParam<std::string>> {
 protected:
  ExampleViewerPage() : CliFolderTest("view-example") {}
};

TEST_P(ExampleViewerPage, LoadsWithoutAnErrorAndDraws) {
  SKIP_WITHOUT_BROWSER();
  const std::string name = GetParam();
  const fs::path pages = dir_ / "pages";
  ASSERT_EQ(shell("bash " + quoted((kExamples / "view_examples.sh").string()) + " " +
                  quoted(SHADOWGEN_EXECUTABLE) + " --out " + quoted(pages.string()) + " " +
                  quoted(name) + " >" + quoted((dir_ / "script.out").string()) + " 2>&1"),
            0)
      << contents(dir_ / "script.out");
  const std::vector<std::string> made = sorted_names(pages, dir_ / "run");
  const std::set<std::string> with_path = {"garden", "roof"};
  std::vector<std::string> expected = {name};
  if (with_path.count(name) != 0) expected.push_back(name + "-sun-hours");
  EXPECT_EQ(made, expected);
  for (const std::string& page : made) {
    SCOPED_TRACE(page);
    const nlohmann::json result = check_page(pages / page, "", dir_);
    ExpectCleanPage(result);
    if (result.is_null() || result["ready"] != true) continue;
    // A band no region falls in is listed but has nothing to draw.
    const auto drawn =
        std::count_if(result["groups"].begin(), result["groups"].end(),
                      [](const nlohmann::json& g) { return !g["colour"].is_null(); });
    EXPECT_GE(drawn, 1) << result.dump();
  }
}

std::vector<std::string> example_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kExamples / "scenes")) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleViewerPage, ::testing::ValuesIn(example_names()),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
}  // namespace shadowgen::test
