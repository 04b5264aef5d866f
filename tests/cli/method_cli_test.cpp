// End-to-end tests of the sampled methods (docs/scene-format.md, "Methods"): `generate` and
// `report` take --method, the database and the JSON report name it, a sampled database
// reads back and is refused by what draws lit polygons; `compare` measures every method
// against the exact one on the scene, its exact row without error, and with --view the view
// methods against exact's picture.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

// A 10 × 10 ground under a 4 × 4 roof at z = 1, the sun straight down: the ground's lit
// fraction is 84/100, the roof's 1.
const std::string kRoof = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "roof", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]]}
  ],
  "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
})";

// A 2 × 2 × 2 box on a 20 × 20 ground under a sun, with a view.
const std::string kBox = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[-10,-10,0],[10,-10,0],[10,10,0],[-10,10,0]]},
    {"id": "top", "outer": [[-1,-1,2],[1,-1,2],[1,1,2],[-1,1,2]]},
    {"id": "south", "outer": [[-1,-1,0],[1,-1,0],[1,-1,2],[-1,-1,2]]},
    {"id": "north", "outer": [[1,1,0],[-1,1,0],[-1,1,2],[1,1,2]]},
    {"id": "west", "outer": [[-1,1,0],[-1,-1,0],[-1,-1,2],[-1,1,2]]},
    {"id": "east", "outer": [[1,-1,0],[1,1,0],[1,1,2],[1,-1,2]]}
  ],
  "lights": [{"id": "sun", "type": "directional", "direction": [1, 0.6, -1.5]}],
  "views": [
    {"id": "main", "eye": [9, -11, 8], "target": [0, 0, 0.5], "fov_deg": 50},
    {"id": "top", "eye": [0, 0, 30], "target": [0, 0, 0], "up": [0, 1, 0]}
  ]
})";

class MethodCli : public CliFolderTest<> {
 protected:
  MethodCli() : CliFolderTest("shadowgen-method") {}
};

TEST_F(MethodCli, ReportEstimatesWithEachMethodAndNamesIt) {
  const fs::path scene = write("roof.json", kRoof);
  for (const std::vector<std::string>& method :
       {std::vector<std::string>{"--method", "rays", "--samples", "4096"},
        std::vector<std::string>{"--method", "shadow-map", "--samples", "4096", "--resolution",
                                 "1024"}}) {
    std::vector<std::string> args{"report", scene.string()};
    args.insert(args.end(), method.begin(), method.end());
    const Outcome csv = run(args);
    ASSERT_EQ(csv.code, 0) << csv.err;
    const std::vector<ReportRow> rows = parse_report(csv.out);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_NEAR(rows[0].lit_fraction, 0.84, 0.01) << method[1];
    EXPECT_EQ(rows[1].lit_fraction, 1.0) << method[1];  // nothing over the roof: every point lit

    args.insert(args.end(), {"--format", "json"});
    const Outcome json = run(args);
    ASSERT_EQ(json.code, 0) << json.err;
    const nlohmann::json report = nlohmann::json::parse(json.out);
    EXPECT_EQ(report["method"]["name"], method[1]);
    EXPECT_EQ(report["method"]["samples"], 4096);
    EXPECT_EQ(report["method"].contains("resolution"), method[1] == "shadow-map");
  }
}

TEST_F(MethodCli, SampledDatabaseReadsBackAndCannotBeDrawn) {
  const fs::path scene = write("roof.json", kRoof);
  const fs::path db = dir_ / "roof.db.json";
  const Outcome generated =
      run({"generate", scene.string(), "-o", db.string(), "--method", "rays", "--samples", "64"});
  ASSERT_EQ(generated.code, 0) << generated.err;
  const nlohmann::json database = nlohmann::json::parse(contents(db));
  EXPECT_EQ(database["method"], (nlohmann::json{{"name", "rays"}, {"samples", 64}}));
  EXPECT_FALSE(database["faces"][0].contains("lit"));
  EXPECT_EQ(database["faces"][1]["lit_area"]["sun"], 16.0);

  const Outcome direct = run({"report", scene.string(), "--method", "rays", "--samples", "64"});
  const Outcome from_db = run({"report", db.string()});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.out, direct.out);  // the same points, the same estimate

  const Outcome exported = run({"export", db.string(), "--obj", (dir_ / "roof.obj").string()});
  EXPECT_EQ(exported.code, 1);
  EXPECT_NE(exported.err.find("no lit polygons to draw: generate it with --method exact"),
            std::string::npos)
      << exported.err;
  EXPECT_FALSE(fs::exists(dir_ / "roof.obj"));
  const Outcome rendered = run({"render", db.string(), "--svg", (dir_ / "roof.svg").string(),
                                "--eye", "5,-20,20", "--target", "5,5,0"});
  EXPECT_EQ(rendered.code, 1) << rendered.err;
  EXPECT_NE(rendered.err.find("no lit polygons to draw"), std::string::npos) << rendered.err;

  const Outcome again = run({"report", db.string(), "--method", "rays"});
  EXPECT_EQ(again.code, 1);
  EXPECT_NE(again.err.find("a method applies to a scene only"), std::string::npos) << again.err;
}

TEST_F(MethodCli, OptionsThatDoNotFitAreUsageErrors) {
  const fs::path scene = write("roof.json", kRoof);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"report", scene.string(), "--samples", "4"}, "--samples applies only to a sampled method"},
      {{"report", scene.string(), "--method", "rays", "--resolution", "64"},
       "--resolution applies only to --method shadow-map"},
      {{"report", scene.string(), "--method", "rays", "--samples", "0"}, "--samples"},
      {{"report", scene.string(), "--method", "stencil"}, "--method"},
      {{"report", scene.string(), "--method", "rays", "--format", "sun-hours"},
       "sun-hours regions, which a sampled method does not make"},
      {{"generate", scene.string(), "-o", "x.json", "--method", "rays", "--keep-instants"},
       "--keep-instants keeps lit polygons"},
      {{"compare", scene.string(), "--methods", "rays:0"}, "expected exact, rays[:SAMPLES]"},
      {{"compare", scene.string(), "--methods", "exact:4"}, "expected exact, rays[:SAMPLES]"},
      {{"compare", scene.string(), "--methods", "shadow-map:4:4:4"}, "expected exact"},
  };
  for (const auto& [args, message] : cases) {
    const Outcome outcome = run(args);
    EXPECT_EQ(outcome.code, 2) << args.back() << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(message), std::string::npos) << outcome.err;
    EXPECT_EQ(files(), std::vector<std::string>{"roof.json"});
  }
}

// shadow-map:N means texels, in --methods as in --view-methods and --resolution; points per
// face are samples=N. --methods shadow-map:2048 once meant 2048 samples: the spelling of
// two numbers is refused saying the new one, and a number alone, which means texels now,
// says so on stderr (but under --quiet).
TEST_F(MethodCli, ShadowMapNMeansTexelsInEveryMethodList) {
  const fs::path scene = write("roof.json", kRoof);
  auto rows_of = [](const std::string& csv) {
    std::istringstream in(csv);
    std::string line;
    std::vector<std::vector<std::string>> rows;
    std::getline(in, line);  // the header
    while (std::getline(in, line)) rows.push_back(csv_fields(line));
    return rows;
  };
  const Outcome texels = run({"compare", scene.string(), "--methods",
                              "shadow-map:128,shadow-map:64:samples=8,rays:samples=8", "--format",
                              "csv", "--threads", "1"});
  ASSERT_EQ(texels.code, 0) << texels.err;
  EXPECT_EQ(texels.err,
            "shadowgen: warning: --methods shadow-map:128: 128 is the depth maps' resolution in "
            "texels, as in --view-methods (it was once the points per face, now written "
            "shadow-map:RESOLUTION:samples=N)\n");
  const std::vector<std::vector<std::string>> rows = rows_of(texels.out);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[1][0] + ":" + rows[1][1] + ":" + rows[1][2], "shadow-map:256:128");
  EXPECT_EQ(rows[2][0] + ":" + rows[2][1] + ":" + rows[2][2], "shadow-map:8:64");
  EXPECT_EQ(rows[3][0] + ":" + rows[3][1], "rays:8");
  const Outcome quiet = run({"compare", scene.string(), "--methods", "shadow-map:128", "--format",
                             "csv", "--threads", "1", "--quiet"});
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");

  const Outcome old = run({"compare", scene.string(), "--methods", "rays:16,shadow-map:64:1024"});
  EXPECT_EQ(old.code, 2);
  EXPECT_EQ(old.err,
            "shadowgen: --methods shadow-map:64:1024: shadow-map:SAMPLES:RESOLUTION is written "
            "shadow-map:1024:samples=64 (the number after shadow-map is the depth maps' "
            "resolution in texels, as in --view-methods)\nRun with --help for more "
            "information.\n");
  for (const char* bad : {"shadow-map:samples=4:samples=4", "rays:4:samples=4",
                          "shadow-map:64:samples=0", "shadow-map:samples=x", "exact:samples=4"}) {
    const Outcome refused = run({"compare", scene.string(), "--methods", bad});
    EXPECT_EQ(refused.code, 2) << bad;
    EXPECT_EQ(refused.err.rfind(std::string("shadowgen: --methods ") + bad +
                                    ": expected exact, rays[:SAMPLES] or "
                                    "shadow-map[:RESOLUTION][:samples=N], ",
                                0),
              0u)
        << refused.err;
  }
  EXPECT_EQ(files(), std::vector<std::string>{"roof.json"});
}

TEST_F(MethodCli, CompareMeasuresEveryMethodAgainstExact) {
  const fs::path scene = write("roof.json", kRoof);
  const fs::path plot = dir_ / "plot.svg";
  const Outcome outcome =
      run({"compare", scene.string(), "--methods", "rays:16,rays:1024,shadow-map:256:samples=64",
           "--format", "csv", "--plot", plot.string(), "--threads", "1"});
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  std::istringstream in(outcome.out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "method,samples,resolution,seconds,mean_error,max_error,worst_face,worst_light,pareto");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) rows.push_back(csv_fields(line));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0][0], "exact");
  EXPECT_EQ(rows[0][4], "0");  // the exact row has no error
  EXPECT_EQ(rows[0][5], "0");
  EXPECT_EQ(rows[1][0] + ":" + rows[1][1], "rays:16");
  EXPECT_EQ(rows[2][0] + ":" + rows[2][1], "rays:1024");
  EXPECT_EQ(rows[3][0] + ":" + rows[3][1] + ":" + rows[3][2], "shadow-map:64:256");
  // Only the ground is partly shadowed: the roof is lit whole by every method.
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r][6], "ground") << rows[r][0];
    EXPECT_LT(std::stod(rows[r][5]), 0.1) << rows[r][0];
    EXPECT_NEAR(std::stod(rows[r][4]), std::stod(rows[r][5]) / 2, 1e-12);  // two pairs
  }
  EXPECT_LT(std::stod(rows[2][5]), std::stod(rows[1][5]));  // more samples, less error
  ExpectWellFormedXml(plot, dir_ / "xmllint.txt");
  const std::string svg = contents(plot);
  EXPECT_NE(svg.find(R"(data-method="exact")"), std::string::npos);
  EXPECT_NE(svg.find(R"(data-method="rays 1024")"), std::string::npos);
  EXPECT_NE(svg.find(R"(data-method="shadow-map 64 @ 256")"), std::string::npos);

  const fs::path db = dir_ / "roof.db.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome table = run({"compare", db.string(), "--methods", "rays:16"});  // its scene
  ASSERT_EQ(table.code, 0) << table.err;
  EXPECT_NE(table.out.find("over 2 (face, light) pairs"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("\nexact "), std::string::npos) << table.out;
}

TEST_F(MethodCli, CompareViewMeasuresTheViewMethodsAgainstExact) {
  const fs::path scene = write("box.json", kBox);
  const Outcome outcome = run({"compare", scene.string(), "--methods", "rays:16", "--view", "main",
                               "--width", "96", "--height", "72", "--view-methods",
                               "exact,shadow-map:256,volumes,stencil,stencil-silhouettes",
                               "--format", "csv", "--threads", "1"});
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  std::istringstream in(outcome.out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "method,samples,resolution,seconds,mean_error,max_error,worst_face,worst_light,pareto");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line) && !line.empty()) rows.push_back(csv_fields(line));
  ASSERT_EQ(rows.size(), 2u);  // the per-face block as without --view
  EXPECT_EQ(rows[0][0], "exact");
  std::getline(in, line);
  EXPECT_EQ(line, "view_method,resolution,seconds,differing_share,pairs,pareto");
  std::vector<std::vector<std::string>> views;
  while (std::getline(in, line)) views.push_back(csv_fields(line));
  ASSERT_EQ(views.size(), 5u) << outcome.out;
  EXPECT_EQ(views[0][0] + ":" + views[0][1], "exact:");
  EXPECT_EQ(views[1][0] + ":" + views[1][1], "shadow-map:256");
  EXPECT_EQ(views[2][0] + ":" + views[2][1], "volumes:");
  EXPECT_EQ(views[3][0] + ":" + views[3][1], "stencil:");
  EXPECT_EQ(views[4][0] + ":" + views[4][1], "stencil-silhouettes:");
  EXPECT_EQ(views[0][3], "0");
  // Marked Pareto-optimal exactly where no other row is as fast and as close to exact and
  // better in one (times vary from run to run: a method as accurate as exact may be faster).
  for (const std::vector<std::string>& row : views) {
    bool beaten = false;
    for (const std::vector<std::string>& other : views) {
      const double t = std::stod(row[2]), e = std::stod(row[3]);
      const double ot = std::stod(other[2]), oe = std::stod(other[3]);
      beaten = beaten || (&other != &row && ot <= t && oe <= e && (ot < t || oe < e));
    }
    EXPECT_EQ(row[5], beaten ? "0" : "1") << row[0];
  }
  EXPECT_LE(std::stod(views[1][3]), 0.02);  // a coarse shadow map, nearly
  EXPECT_EQ(views[2][3], "0");              // shadow volumes: exactly, off boundaries
  EXPECT_EQ(views[3][3], "0");
  // The box has no bottom, so its silhouette is open at the ground; the sides it lacks lie
  // below the ground, where z-pass (the eye is in no shadow) counts nothing.
  EXPECT_EQ(views[4][3], "0");
  for (const std::vector<std::string>& row : views) {
    ASSERT_EQ(row.size(), 6u);
    EXPECT_GT(std::stoul(row[4]), 3000u) << row[0];  // most of the 96 × 72 pixels see something
    EXPECT_EQ(row[4], views[0][4]);                  // the same pairs for every method
  }

  const fs::path plot = dir_ / "view_plot.svg";
  const Outcome table = run({"compare", scene.string(), "--methods", "rays:16", "--view", "top",
                             "--width", "40", "--height", "30", "--view-methods",
                             "exact,volumes,shadow-map:16", "--plot", plot.string()});
  ASSERT_EQ(table.code, 0) << table.err;
  EXPECT_NE(table.out.find("\nview top, 40×30: share of (pixel, light) pairs off boundaries "
                           "whose lit state differs from exact"),
            std::string::npos)
      << table.out;
  // The plot gains a panel of the view methods: share against time, each one labelled.
  ExpectWellFormedXml(plot, dir_ / "view_plot_xmllint.txt");
  const std::string svg = contents(plot);
  EXPECT_NE(svg.find(R"(data-method="rays 16")"), std::string::npos);
  EXPECT_NE(svg.find(R"(data-view-method="exact")"), std::string::npos) << svg;
  EXPECT_NE(svg.find(R"(data-view-method="volumes" data-seconds=)"), std::string::npos);
  EXPECT_NE(svg.find(R"(data-view-method="shadow-map @ 16")"), std::string::npos);
  EXPECT_NE(svg.find(">View top, 40×30: pairs differing from exact against time</text>"),
            std::string::npos);
  EXPECT_NE(svg.find(R"(height="960.0")"), std::string::npos);
  EXPECT_NE(table.out.find("\nvolumes "), std::string::npos) << table.out;

  const Outcome missing = run({"compare", scene.string(), "--view", "side"});
  EXPECT_EQ(missing.code, 1) << missing.err;
  EXPECT_NE(missing.err.find("has no view 'side' (its views: 'main', 'top')"), std::string::npos)
      << missing.err;
  EXPECT_TRUE(missing.out.empty());

  for (const std::string bad : {"shadows", "volumes:64", "shadow-map:0", "shadow-map:x"}) {
    const Outcome refused =
        run({"compare", scene.string(), "--view", "main", "--view-methods", bad});
    EXPECT_EQ(refused.code, 2) << bad << "\n" << refused.err;
    EXPECT_NE(refused.err.find("--view-methods " + bad +
                               ": expected exact, volumes, stencil, stencil-silhouettes, "
                               "shadow-map[:RESOLUTION] or angular[:ROWS]"),
              std::string::npos)
        << refused.err;
  }
  const Outcome without_view = run({"compare", scene.string(), "--width", "64"});
  EXPECT_EQ(without_view.code, 2) << without_view.err;
  // The refused runs wrote nothing.
  EXPECT_EQ(files(),
            (std::vector<std::string>{"box.json", "view_plot.svg", "view_plot_xmllint.txt"}));
}

// A sun path's instants keep only lit areas in the comparison's exact run; --view draws
// --view-instants of them, spread over the path, generated again with their lit polygons,
// and names them. The box under a morning's sun, every 30 minutes from 09:00 to 12:00.
TEST_F(MethodCli, CompareViewDrawsInstantsSpreadOverEachSunPath) {
  std::string box = kBox;
  const std::string sun =
      R"("lights": [{"id": "sun", "type": "directional", "direction": [1, 0.6, -1.5]}],)";
  box.replace(box.find(sun), sun.size(),
              R"("site": {"latitude_deg": 48.85, "longitude_deg": 2.35, "utc_offset_h": 1},
  "lights": [{"id": "day", "type": "sun", "from": "2026-03-21T09:00", "to": "2026-03-21T12:00",
              "step_min": 30}],)");
  const fs::path scene = write("box_day.json", box);
  const Outcome table = run({"compare", scene.string(), "--methods", "rays:16", "--view", "main",
                             "--width", "96", "--height", "72", "--view-methods", "exact,volumes",
                             "--view-instants", "2", "--threads", "1"});
  ASSERT_EQ(table.code, 0) << table.err;
  // 7 instants; of 2 spread evenly, ranks ⌊7/4⌋ = 1 and ⌊21/4⌋ = 5.
  EXPECT_NE(table.out.find("instants of sun paths drawn: 2 of 7 (day@2026-03-21T09:30, "
                           "day@2026-03-21T11:30)\n"),
            std::string::npos)
      << table.out;
  const Outcome csv = run({"compare", scene.string(), "--methods", "rays:16", "--view", "main",
                           "--width", "96", "--height", "72", "--view-methods", "exact,volumes",
                           "--view-instants", "2", "--threads", "1", "--format", "csv"});
  ASSERT_EQ(csv.code, 0) << csv.err;
  const std::string tail = csv.out.substr(csv.out.find("\nview_method,"));
  std::istringstream in(tail);
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  std::vector<std::vector<std::string>> views;
  while (std::getline(in, line)) views.push_back(csv_fields(line));
  ASSERT_EQ(views.size(), 2u) << csv.out;
  // Two instants' pairs are compared (no longer none), and Bergeron's volumes agree on all.
  EXPECT_GT(std::stoi(views[0][4]), 2000) << csv.out;
  EXPECT_EQ(views[1][4], views[0][4]);
  EXPECT_EQ(views[1][3], "0");
  // With none drawn, no pair is compared.
  const Outcome none =
      run({"compare", scene.string(), "--methods", "rays:16", "--view", "main", "--width", "96",
           "--height", "72", "--view-methods", "volumes", "--view-instants", "0"});
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_NE(none.out.find("instants of sun paths drawn: 0 of 7\n"), std::string::npos) << none.out;
}

}  // namespace
}  // namespace shadowgen::test
