// End-to-end tests of CityJSON files in scenes (docs/cityjson.md): the district example
// runs as examples/cityjson/README.md says, its CityJSONSeq twin gives the same report, its
// files are what their script writes, and a bad file exits 1 naming the file, the city
// object and the problem, writing nothing.

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

const fs::path kDistrict = fs::path(SHADOWGEN_EXAMPLES_DIR) / "cityjson";

std::vector<std::string> sorted_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  std::sort(out.begin(), out.end());
  return out;
}

class CityJsonCli : public CliFolderTest<> {
 protected:
  CityJsonCli() : CliFolderTest("shadowgen-cityjson") {}
};

TEST_F(CityJsonCli, TheDistrictExampleTakesItsSiteFromItsCrsAndReportsSunHours) {
  const std::string scene = (kDistrict / "district.json").string();
  // The scene gives only its time zone: the sun is placed from the file's EPSG:7415.
  const Outcome sun = run({"sun", scene});
  ASSERT_EQ(sun.code, 0) << sun.err;
  EXPECT_EQ(sun.err, "");
  EXPECT_NE(sun.out.find("\nmarch21,march21@2026-03-21T12:30,2026-03-21T12:30,30,"),
            std::string::npos)
      << sun.out;

  const Outcome report = run({"report", scene, "--format", "sun-hours"});
  ASSERT_EQ(report.code, 0) << report.err;
  EXPECT_EQ(report.err, "");
  // The church tower's roof sees the sun all day: 24 half-hour instants, 12 hours.
  EXPECT_NE(report.out.find("\ndistrict/church-tower/1,march21,100,12,12,12,100\n"),
            std::string::npos)
      << report.out;

  // The same district as a CityJSONSeq file gives the same report, row for row.
  const fs::path seq_scene = write("seq.json", R"({"format": "shadowgen-scene/1",
    "meshes": [{"id": "district", "file": ")" + (kDistrict / "district.city.jsonl").string() +
                                                   R"("}],
    "site": {"utc_offset_h": 1},
    "lights": [{"id": "march21", "type": "sun", "from": "2026-03-21T07:00",
                "to": "2026-03-21T18:30", "step_min": 30}]})");
  const Outcome seq_report = run({"report", seq_scene.string(), "--format", "sun-hours"});
  ASSERT_EQ(seq_report.code, 0) << seq_report.err;
  // Rows come in the order of the objects' ids in a CityJSON file, of the features'
  // lines in a CityJSONSeq file.
  EXPECT_EQ(sorted_lines(seq_report.out), sorted_lines(report.out));
}

TEST_F(CityJsonCli, TheDistrictFilesAreWhatTheirScriptWrites) {
  if (shell("command -v python3 >/dev/null 2>&1") != 0) GTEST_SKIP() << "no python3";
  ASSERT_EQ(shell("python3 " + quoted((kDistrict / "make_district.py").string()) + " " +
                  quoted(dir_.string())),
            0);
  for (const char* name : {"district.city.json", "district.city.jsonl"}) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(contents(dir_ / name) == contents(kDistrict / name))
        << "examples/cityjson/" << name
        << " differs from what make_district.py writes: run it and commit the files";
  }
}

TEST_F(CityJsonCli, ABadCityJsonFileExits1NamingItsObjectAndWritesNothing) {
  const fs::path city = write("bad.city.json", R"({"type": "CityJSON", "version": "2.0",
    "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]},
    "CityObjects": {"b": {"type": "Building", "geometry": [
      {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 3]]]}]}},
    "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]})");
  const fs::path scene = write("scene.json", R"({"format": "shadowgen-scene/1",
    "meshes": [{"id": "m", "file": "bad.city.json"}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]})");
  const Outcome outcome = run({"generate", scene.string(), "-o", (dir_ / "out.json").string()});
  EXPECT_EQ(outcome.code, 1);
  EXPECT_EQ(outcome.err, "shadowgen: " + city.string() +
                             ": CityObjects['b'].geometry[0].boundaries[0][0][2]: vertex index 3 "
                             "is out of range: the file has 3 vertices\n");
  EXPECT_EQ(files(), (std::vector<std::string>{"bad.city.json", "scene.json"}));
}

}  // namespace
}  // namespace shadowgen::test
