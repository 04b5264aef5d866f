// Loading an input file into a shadowed scene (shadowgen/pipeline/load_shadowed.h): a
// scene or a database told apart by "format", what each caller accepts, warnings, the
// hooks around generation, and errors naming the file.

#include "shadowgen/pipeline/load_shadowed.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "clipper/clip.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

namespace fs = std::filesystem;

// A bent quadrilateral (one vertex 1 above the others' plane): read with a warning and
// split into triangles, an error when strict.
constexpr const char* kBentScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "bent", "outer": [[2,2,1],[4,2,1],[4,4,2],[2,4,1]]}
  ],
  "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
})";

// Lights crossing the edge of the ground (an awning over it) for the clip limit.
constexpr const char* kAwning = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "awning", "outer": [[8,3,1],[12,3,1],[12,7,1],[8,7,1]]}
  ],
  "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
})";

class LoadShadowed : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) / ("load-shadowed-" + std::string(test->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }
  // The problem of the InputError that loading `path` with `options` throws.
  static std::string input_problem(const fs::path& path, const LoadOptions& options) {
    try {
      (void)load_shadowed(path, options);
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path.string());
      return e.problem();
    }
    return "(no error)";
  }

  fs::path dir_;
};

LoadOptions accepting(Accept accept) {
  LoadOptions options;
  options.accept = accept;
  options.generate.threads = 1;
  return options;
}

TEST_F(LoadShadowed, AScenesShadowsAreGeneratedADatabaseIsReadAsItIs) {
  const fs::path scene = write("two.json", test::kTwoLights);
  const ShadowedScene from_scene = load_shadowed(scene, accepting(Accept::kSceneOrDatabase));
  EXPECT_EQ(from_scene.scene().faces.size(), 2u);
  EXPECT_DOUBLE_EQ(lit_area(from_scene.lit()[0][0]), 84.0);  // ground less the square below

  const fs::path db = dir_ / "two.shadowed.json";
  write_database(from_scene, db);
  int scenes_generated = 0;
  LoadOptions options = accepting(Accept::kSceneOrDatabase);
  options.on_scene = [&](const Scene&) { ++scenes_generated; };
  const ShadowedScene from_db = load_shadowed(db, options);
  EXPECT_EQ(scenes_generated, 0);
  EXPECT_EQ(database_json(from_db), database_json(from_scene));
  EXPECT_EQ(database_json(load_shadowed(db, accepting(Accept::kDatabase))),
            database_json(from_scene));
}

TEST_F(LoadShadowed, EachCallerGetsOnlyWhatItAccepts) {
  const fs::path scene = write("scene.json", test::kTwoLights);
  const fs::path db = dir_ / "db.json";
  write_database(load_shadowed(scene, accepting(Accept::kScene)), db);
  const fs::path other = write("other.json", R"({"format": "something-else/3"})");

  EXPECT_NE(input_problem(scene, accepting(Accept::kDatabase)).find("is a scene"),
            std::string::npos);
  // A scene only: the scene reader's own message about the format.
  EXPECT_NE(input_problem(db, accepting(Accept::kScene)).find("shadowgen-shadowed/2"),
            std::string::npos);
  const std::string either = input_problem(other, accepting(Accept::kSceneOrDatabase));
  EXPECT_NE(either.find("something-else/3"), std::string::npos) << either;
  EXPECT_NE(either.find("shadowgen-scene/1"), std::string::npos) << either;
  EXPECT_NE(either.find("shadowgen-shadowed/2"), std::string::npos) << either;
  const std::string database_only = input_problem(other, accepting(Accept::kDatabase));
  EXPECT_NE(database_only.find("something-else/3"), std::string::npos) << database_only;
  EXPECT_EQ(database_only.find("shadowgen-scene/1"), std::string::npos) << database_only;
  EXPECT_NE(input_problem(dir_ / "missing.json", accepting(Accept::kSceneOrDatabase)),
            "(no error)");
}

TEST_F(LoadShadowed, WarningsGoToTheCallbackAndStrictMakesThemErrors) {
  const fs::path scene = write("bent.json", kBentScene);
  for (Accept accept : {Accept::kScene, Accept::kSceneOrDatabase}) {
    std::vector<std::string> warnings;
    LoadOptions options = accepting(accept);
    options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
    EXPECT_EQ(load_shadowed(scene, options).scene().faces.size(), 2u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("bent"), std::string::npos) << warnings[0];

    options.strict = true;
    EXPECT_THROW(load_shadowed(scene, options), InputError);
  }
}

TEST_F(LoadShadowed, TheSceneIsAnnouncedBeforeItsLightsAreDone) {
  const fs::path scene = write("two.json", test::kTwoLights);
  std::vector<std::string> events;
  LoadOptions options = accepting(Accept::kScene);
  options.on_scene = [&](const Scene& s) {
    events.push_back("scene with " + std::to_string(s.lights.size()) + " lights");
  };
  options.generate.on_light_done = [&](std::size_t light, const LightStats&) {
    events.push_back("light " + std::to_string(light));
  };
  load_shadowed(scene, options);
  EXPECT_EQ(events, (std::vector<std::string>{"scene with 2 lights", "light 0", "light 1"}));
}

TEST_F(LoadShadowed, ShadowsThatCannotBeComputedNameTheFileTheFaceAndTheLight) {
  const fs::path scene = write("awning.json", kAwning);
  const clipper::SnapRoundLimitForTesting limit(0);
  for (Accept accept : {Accept::kScene, Accept::kSceneOrDatabase}) {
    try {
      load_shadowed(scene, accepting(accept));
      ADD_FAILURE() << "generated shadows with a clip that did not settle";
    } catch (const GenerationError& e) {
      EXPECT_EQ(e.file(), scene.string());
      EXPECT_EQ(e.face_id(), "ground");
      EXPECT_EQ(e.light_id(), "sun");
      EXPECT_EQ(std::string(e.what()).rfind(scene.string() + ": face 'ground', light 'sun': ", 0),
                0u)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace shadowgen
