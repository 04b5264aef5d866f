// Malformed scenes through `shadowgen generate`, one table row each: every one must exit 1
// with one line on stderr that names the file to blame, the problem (a distinctive piece of
// its text) and the face where one is to blame, print nothing on stdout, and leave no
// output (nor a temporary file) behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

struct Malformed {
  const char* name;
  std::string scene;                      // written to <name>.json
  std::vector<std::string> problem;       // pieces the message must hold
  std::string face = {};                  // the face id it must name ('id'), if any
  std::vector<std::string> options = {};  // more arguments to `generate`
  std::vector<std::pair<std::string, std::string>> files = {};  // more input files (path, text)
  std::string blamed = {};  // the file it must name; the scene file when empty
};

// gtest names a failing case by this.
void PrintTo(const Malformed& c, std::ostream* os) { *os << c.name; }

// A valid scene around `polygons` (a JSON array's inside) and `lights`.
std::string scene_with(const std::string& polygons,
                       const std::string& lights =
                           R"({"id": "sun", "type": "directional", "direction": [0, 0, -1]})") {
  return R"({"format": "shadowgen-scene/1",
  "polygons": [)" +
         polygons + R"(],
  "lights": [)" +
         lights + "]}\n";
}

const char* const kSquare = R"({"id": "tile", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]})";

// Three vertices and a face that uses a fourth that is not there (line 5).
const char* const kStatueObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 1 2 7\n";

std::vector<Malformed> cases() {
  return {
      {"broken_json",
       "{\"format\": \"shadowgen-scene/1\",\n  \"polygons\": [\n    " + std::string(kSquare) +
           "\n  ]\n  \"lights\": []\n}\n",
       {"invalid JSON", "line 5"}},
      {"empty_file", "", {"invalid JSON", "line 1, column 1"}},
      {"top_level_array", "[1, 2, 3]\n", {"a scene is a JSON object"}},
      {"wrong_format_version",
       R"({"format": "shadowgen-scene/2", "polygons": [], "lights": []})",
       {"unsupported format 'shadowgen-scene/2'"}},
      {"string_coordinate",
       scene_with(R"({"id": "tile", "outer": [[0,0,0],[1,"0",0],[1,1,0]]})"),
       {"outer[1][1]", "expected a number, found a string"},
       "tile"},
      {"number_id",
       scene_with(R"({"id": 7, "outer": [[0,0,0],[1,0,0],[1,1,0]]})"),
       {"polygons[0].id", "expected a string, found a number"}},
      {"outer_not_an_array",
       scene_with(R"({"id": "tile", "outer": "square"})"),
       {"outer: expected an array, found a string"},
       "tile"},
      // "polygon" for "polygons": the scene's polygons are missing.
      {"missing_polygons",
       R"({"format": "shadowgen-scene/1",
  "polygon": [{"id": "tile", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
  "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]})",
       {"polygons"}},
      {"missing_outer", scene_with(R"({"id": "lid", "holes": []})"), {"missing 'outer'"}, "lid"},
      {"missing_id",
       scene_with(R"({"outer": [[0,0,0],[1,0,0],[1,1,0]]})"),
       {"polygons[0]", "missing 'id'"}},
      {"empty_id",
       scene_with(R"({"id": "", "outer": [[0,0,0],[1,0,0],[1,1,0]]})"),
       {"must not be empty"}},
      {"nan_token",
       scene_with(R"({"id": "tile", "outer": [[0,0,0],[1,NaN,0],[1,1,0]]})"),
       {"invalid JSON", "line 2"}},
      {"infinity_token",
       scene_with(R"({"id": "tile", "outer": [[0,0,0],[1,0,0],[1,1,-Infinity]]})"),
       {"invalid JSON", "line 2"}},
      {"infinite_number",
       scene_with(R"({"id": "tile", "outer": [[0,0,0],[1e999,0,0],[1,1,0]]})"),
       {"1e999", "out of the range of a double", "line 2"}},
      {"unknown_light_type",
       scene_with(kSquare, R"({"id": "torch", "type": "spot", "position": [0, 0, 1]})"),
       {"light 'torch'", "unknown light type 'spot'"}},
      {"point_light_without_position",
       scene_with(kSquare, R"({"id": "bulb", "type": "point"})"),
       {"light 'bulb'", "missing 'position'"}},
      {"zero_light_direction",
       scene_with(kSquare, R"({"id": "sun", "type": "directional", "direction": [0, 0, 0]})"),
       {"light 'sun'", "direction: must not be zero"}},
      {"light_direction_of_two_numbers",
       scene_with(kSquare, R"({"id": "sun", "type": "directional", "direction": [0, -1]})"),
       {"light 'sun'", "expected an array of 3 numbers, found an array of 2"}},
      {"range_starting_beyond_its_end",
       scene_with(kSquare, R"({"id": "bulb", "type": "point", "position": [0, 0, 2],
                               "range": {"falloff_start": 9, "end": 3}})"),
       {"light 'bulb'", "must not exceed 'end'"}},
      {"negative_intensity",
       scene_with(
           kSquare,
           R"({"id": "bulb", "type": "point", "position": [0, 0, 2], "intensity": [1, -1, 1]})"),
       {"light 'bulb'", "intensity: must not be negative"}},
      {"duplicate_light_id",
       scene_with(kSquare, R"({"id": "sun", "type": "directional", "direction": [0, 0, -1]},
                              {"id": "sun", "type": "directional", "direction": [0, 1, -1]})"),
       {"duplicate id 'sun'"}},
      {"missing_mesh_file",
       R"({"format": "shadowgen-scene/1",
  "meshes": [{"id": "statue", "file": "models/statue.obj"}],
  "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]})",
       {"mesh 'statue'", "statue.obj", "not found"}},
      {"mesh_vertex_index_out_of_range",
       R"({"format": "shadowgen-scene/1",
  "meshes": [{"id": "statue", "file": "models/statue.obj"}],
  "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]})",
       {"out of range", "line 5"},
       "statue/1",
       {},
       {{"models/statue.obj", kStatueObj}},
       "statue.obj"},
      {"mesh_transform_of_three_rows",
       R"({"format": "shadowgen-scene/1",
  "meshes": [{"id": "statue", "file": "models/statue.obj",
              "transform": [[1,0,0,0],[0,1,0,0],[0,0,1,0]]}],
  "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]})",
       {"mesh 'statue'", "transform", "4 rows of 4 numbers"},
       "",
       {},
       {{"models/statue.obj", kStatueObj}}},
      {"self_intersecting_polygon",
       scene_with(R"({"id": "bowtie", "outer": [[0,0,0],[1,1,0],[1,0,0],[0,1,0]]})"),
       {"intersects itself"},
       "bowtie"},
      {"non_planar_polygon_under_strict",
       scene_with(R"({"id": "bent", "outer": [[0,0,0],[1,0,0],[1,1,0.5],[0,1,0]]})"),
       {"not planar"},
       "bent",
       {"--strict"}},
      {"duplicate_face_id",
       scene_with(std::string(kSquare) + R"(, {"id": "tile", "outer": [[0,0,1],[1,0,1],[1,1,1]]})"),
       {"polygons[1].id", "duplicate id 'tile'"}},
      {"polygon_and_mesh_sharing_an_id",
       R"({"format": "shadowgen-scene/1",
  "polygons": [{"id": "statue", "outer": [[0,0,0],[1,0,0],[1,1,0]]}],
  "meshes": [{"id": "statue", "file": "models/statue.obj"}],
  "lights": []})",
       {"duplicate id 'statue'"},
       "",
       {},
       {{"models/statue.obj", kStatueObj}}},
      {"polygon_id_with_slash",
       scene_with(R"({"id": "roof/left", "outer": [[0,0,0],[1,0,0],[1,1,0]]})"),
       {"must not contain '/'"},
       "roof/left"},
      {"hole_outside_its_outer_loop",
       scene_with(R"({"id": "frame", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]],
                      "holes": [[[2,2,0],[3,2,0],[3,3,0],[2,3,0]]]})"),
       {"hole 0 is not inside the outer loop"},
       "frame"},
      {"holes_crossing",
       scene_with(R"({"id": "frame", "outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]],
                      "holes": [[[1,1,0],[2,1,0],[2,2,0],[1,2,0]],
                                [[1.5,1.5,0],[3,1.5,0],[3,3,0],[1.5,3,0]]]})"),
       {"hole 1 crosses hole 0"},
       "frame"},
      {"hole_along_the_outer_loop_outside_it",
       scene_with(R"({"id": "frame", "outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]],
                      "holes": [[[0,-1,0],[2,-1,0],[2,0,0],[0,0,0]]]})"),
       {"hole 0 is not inside the outer loop"},
       "frame"},
      {"loop_of_two_vertices",
       scene_with(R"({"id": "stub", "outer": [[0,0,0],[1,0,0]]})"),
       {"the outer loop has 2 vertices"},
       "stub"},
      {"hole_of_two_vertices",
       scene_with(R"({"id": "frame", "outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]],
                      "holes": [[[1,1,0],[2,2,0]]]})"),
       {"hole 0 has 2 vertices"},
       "frame"},
      {"loop_of_repeated_vertices",
       scene_with(R"({"id": "tile", "outer": [[0,0,0],[1,0,0],[1,0,0]]})"),
       {"fewer than 3 distinct vertices"},
       "tile"},
  };
}

class MalformedCli : public CliFolderTest<::testing::TestWithParam<Malformed>> {
 protected:
  MalformedCli() : CliFolderTest("shadowgen-malformed") {}

  // Every file under dir_ but run/, as paths relative to dir_, sorted (the harness's
  // files() lists one folder only).
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
      const fs::path relative = entry.path().lexically_relative(dir_);
      if (*relative.begin() == "run" || entry.is_directory()) continue;
      names.push_back(relative.generic_string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }
};

TEST_P(MalformedCli, ExitsOneNamingTheProblemAndLeavesNoOutput) {
  const Malformed& c = GetParam();
  const fs::path scene = write(std::string(c.name) + ".json", c.scene);
  std::vector<std::string> inputs{scene.filename().string()};
  for (const auto& [path, text] : c.files) {
    fs::create_directories((dir_ / path).parent_path());
    write(path, text);
    inputs.push_back(path);
  }
  std::sort(inputs.begin(), inputs.end());

  std::vector<std::string> args{"generate", scene.string(), "-o", (dir_ / "out.json").string()};
  args.insert(args.end(), c.options.begin(), c.options.end());
  const Outcome outcome = run(args);
  const int code = outcome.code;
  const std::string& out = outcome.out;
  const std::string& err = outcome.err;

  EXPECT_EQ(code, 1) << err;
  EXPECT_EQ(out, "");
  EXPECT_EQ(err.rfind("shadowgen: ", 0), 0u) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  const std::string blamed = c.blamed.empty() ? scene.filename().string() : c.blamed;
  EXPECT_NE(err.find(blamed), std::string::npos) << "names no " << blamed << ": " << err;
  for (const std::string& piece : c.problem) {
    EXPECT_NE(err.find(piece), std::string::npos) << "says no \"" << piece << "\": " << err;
  }
  if (!c.face.empty()) {
    EXPECT_NE(err.find("'" + c.face + "'"), std::string::npos) << "names no face: " << err;
  }
  EXPECT_EQ(files(), inputs);  // no out.json, no temporary file
}

INSTANTIATE_TEST_SUITE_P(Scenes, MalformedCli, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Malformed>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace shadowgen::test
