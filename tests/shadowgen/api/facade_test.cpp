// The public C++ API (shadowgen/shadowgen.h) on scenes made in memory: the numbers it gives
// against hand-computed ones, its outputs against the rooms', and its errors as the public
// types, naming the input at fault.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "shadowgen/shadowgen.h"

namespace shadowgen::api {
namespace {

// A 10 × 10 ground and a 4 × 4 roof 3 above it, under a sun straight overhead: the roof's
// shadow is its own square, so the ground keeps 100 - 16 = 84 lit.
SceneData roof_over_ground() {
  SceneData data;
  data.name = "hand scene";
  data.faces.push_back({"ground", {{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}, {}}});
  data.faces.push_back({"roof", {{{2, 2, 3}, {6, 2, 3}, {6, 6, 3}, {2, 6, 3}}, {}}});
  data.lights.push_back({.id = "noon", .direction = {0, 0, -1}});
  return data;
}

double loop_area(const Loop& loop) {  // in the plane z = constant
  double twice = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Point& a = loop[i];
    const Point& b = loop[(i + 1) % loop.size()];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return std::abs(twice) / 2.0;
}

TEST(Facade, LitAreasOfASceneMadeInMemory) {
  const Shadows shadows = generate(make_scene(roof_over_ground()));
  EXPECT_TRUE(shadows.exact());
  EXPECT_EQ(shadows.method(), "exact");
  const std::vector<LitArea> rows = shadows.lit_areas();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].face_id, "ground");
  EXPECT_EQ(rows[0].light_id, "noon");
  EXPECT_EQ(rows[0].area, 100.0);
  EXPECT_EQ(rows[0].lit_area, 84.0);
  EXPECT_EQ(rows[1].face_id, "roof");
  EXPECT_EQ(rows[1].lit_area, 16.0);
  EXPECT_EQ(rows[1].lit_fraction, 1.0);
}

TEST(Facade, LitPolygonsAreTheGroundLessTheRoofsShadow) {
  const Shadows shadows = generate(make_scene(roof_over_ground()));
  const std::vector<PolygonData> lit = shadows.lit_polygons(0, 0);
  ASSERT_EQ(lit.size(), 1u);
  EXPECT_EQ(loop_area(lit[0].outer), 100.0);
  ASSERT_EQ(lit[0].holes.size(), 1u);
  EXPECT_EQ(loop_area(lit[0].holes[0]), 16.0);
  for (const Point& p : lit[0].holes[0]) {
    EXPECT_TRUE(p[0] == 2.0 || p[0] == 6.0);
    EXPECT_TRUE(p[1] == 2.0 || p[1] == 6.0);
    EXPECT_EQ(p[2], 0.0);
  }
  EXPECT_THROW(shadows.lit_polygons(2, 0), std::out_of_range);
}

TEST(Facade, ReportIsTheCsvOfTheSpec) {
  const Shadows shadows = generate(make_scene(roof_over_ground()));
  EXPECT_EQ(report(shadows),
            "face_id,light_id,area,lit_area,lit_fraction\n"
            "ground,noon,100,84,0.83999999999999997\n"
            "roof,noon,16,16,1\n");
}

TEST(Facade, SampledMethodIsNamedAndHasNoPolygons) {
  GenerateSettings settings;
  settings.method = Method::kRays;
  settings.samples = 16;
  const Shadows shadows = generate(make_scene(roof_over_ground()), settings);
  EXPECT_FALSE(shadows.exact());
  EXPECT_EQ(shadows.method(), "rays 16");
  try {
    shadows.lit_polygons(0, 0);
    FAIL() << "a sampled method's polygons";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "hand scene: light 'noon': no lit polygons kept (a sampled method's estimate, "
                 "or a sun path's instant summed into sun hours)");
  }
  EXPECT_THROW(write_obj(shadows, "unused.obj"), InputError);
}

TEST(Facade, DatabaseWrittenAndLoadedGivesTheSameAreas) {
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / "facade_test.shadowed.json";
  const Shadows shadows = generate(make_scene(roof_over_ground()));
  write_database(shadows, path.string());
  const Shadows loaded = load(path.string());
  EXPECT_EQ(report(loaded), report(shadows));
  EXPECT_EQ(loaded.scene().face_ids(), (std::vector<std::string>{"ground", "roof"}));
  std::filesystem::remove(path);
}

TEST(Facade, SunPathGivesSunHours) {
  SceneData data = roof_over_ground();
  data.lights = {{.id = "day",
                  .kind = LightKind::kSun,
                  .from = "2026-03-21T10:00",
                  .to = "2026-03-21T14:00",
                  .step_min = 60}};
  data.site = SiteData{.latitude_deg = 51.5, .longitude_deg = 0.0};
  const Scene scene = make_scene(data);
  EXPECT_EQ(scene.sun_path_ids(), std::vector<std::string>{"day"});
  EXPECT_EQ(scene.light_ids().size(), 5u);
  const std::vector<SunHours> rows = generate(scene).sun_hours({2.0});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].face_id, "roof");
  EXPECT_EQ(rows[1].path_id, "day");
  EXPECT_EQ(rows[1].mean_hours, 5.0);  // the roof: nothing above it, 5 instants of an hour
  EXPECT_EQ(rows[1].area_at_least, std::vector<double>{16.0});
}

TEST(Facade, GroupsOfTheSceneAndByPattern) {
  SceneData data = roof_over_ground();
  data.groups = {{"everything", {"*"}}};
  const Scene scene = make_scene(data);
  const std::vector<Group> own = groups(scene);
  ASSERT_EQ(own.size(), 1u);
  EXPECT_EQ(own[0].id, "everything");
  EXPECT_EQ(own[0].faces, (std::vector<std::size_t>{0, 1}));
  const std::vector<Group> by = groups(scene, {"r*"});
  ASSERT_EQ(by.size(), 1u);
  EXPECT_EQ(by[0].faces, std::vector<std::size_t>{1});
  try {
    groups(scene, {"nothing*"});
    FAIL() << "a pattern matching no face";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "hand scene");
  }
}

TEST(Facade, BadFaceIsAnInputErrorNamingSceneAndFace) {
  SceneData data = roof_over_ground();
  data.faces[1].polygon.outer[2][0] = std::numeric_limits<double>::quiet_NaN();
  try {
    make_scene(data);
    FAIL() << "a NaN vertex";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "hand scene");
    EXPECT_EQ(e.face_id(), "roof");
    EXPECT_EQ(e.problem(), "a vertex coordinate is not a finite number");
  }
  data = roof_over_ground();
  data.faces[1].id = "ground";
  try {
    make_scene(data);
    FAIL() << "two faces named ground";
  } catch (const InputError& e) {  // as the scene reader says it of a file
    EXPECT_STREQ(e.what(),
                 "hand scene: polygons[1].id: duplicate id 'ground' (already used by polygon "
                 "'ground')");
  }
}

TEST(Facade, MissingFileIsAnInputErrorNamingIt) {
  try {
    load("no/such/scene.json");
    FAIL() << "a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "no/such/scene.json");
    EXPECT_EQ(std::string(e.what()).rfind("no/such/scene.json: ", 0), 0u) << e.what();
  }
}

TEST(Facade, LightsChosenAreTheOnlyOnes) {
  SceneData data = roof_over_ground();
  data.lights.push_back({.id = "lamp", .kind = LightKind::kPoint, .position = {5, 5, 10}});
  ReadSettings read;
  read.lights = {"lamp"};
  EXPECT_EQ(make_scene(data, read).light_ids(), std::vector<std::string>{"lamp"});
  read.lights = {"moon"};
  EXPECT_THROW(make_scene(data, read), InputError);
}

// A scene file of 400 unit squares side by side under a sun straight overhead: enough
// faces for their reading and a report's rows to be spread over threads.
std::filesystem::path tiles_scene() {
  const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / "tiles.json";
  std::ofstream out(path);
  out << R"({"format": "shadowgen-scene/1", "polygons": [)";
  for (int i = 0; i < 400; ++i) {
    const int x = i % 20, y = i / 20;
    out << (i ? "," : "") << R"({"id": "tile)" << i << R"(", "outer": [[)" << x << ',' << y
        << ",0],[" << x + 1 << ',' << y << ",0],[" << x + 1 << ',' << y + 1 << ",0],[" << x << ','
        << y + 1 << ",0]]}";
  }
  out << R"(], "lights": [{"id": "noon", "type": "directional", "direction": [0, 0, -1]}]})";
  return path;
}

std::size_t process_threads() {  // Linux: one entry per thread of this process
  const std::filesystem::directory_iterator tasks("/proc/self/task");
  return static_cast<std::size_t>(std::distance(begin(tasks), end(tasks)));
}

// Loads the tiles on `threads` threads, then reads and writes the results; exits with 0
// when that started no thread, 1 when it did. Run in a fresh process (a death test), which
// holds no worker of an earlier test. On a machine of one hardware thread both runs exit
// with 0: the test is meaningful on two or more.
[[noreturn]] void load_and_write_on(unsigned threads) {
  const std::filesystem::path scene = tiles_scene();
  const std::filesystem::path database = scene.parent_path() / "tiles.shadowed.json";
  const std::size_t before = process_threads();
  const Shadows shadows = load(scene.string(), {.generate = {.threads = threads}});
  std::size_t rows = shadows.lit_areas().size();
  rows += report(shadows).size() + report(shadows, {.format = ReportFormat::kJson}).size();
  write_database(shadows, database.string());
  const bool more = process_threads() != before;
  std::filesystem::remove(scene);
  std::filesystem::remove(database);
  std::exit(rows > 0 && !more ? 0 : 1);
}

TEST(FacadeDeathTest, ResultsRunOnTheThreadsTheShadowsWereMadeWith) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(load_and_write_on(1), ::testing::ExitedWithCode(0), "");
  // The check can fail: on two threads, the work starts a worker.
  EXPECT_EXIT(load_and_write_on(2), ::testing::ExitedWithCode(1), "");
}

TEST(Facade, VersionIsTheHeadersOwn) { EXPECT_STREQ(version(), SHADOWGEN_VERSION); }

}  // namespace
}  // namespace shadowgen::api
