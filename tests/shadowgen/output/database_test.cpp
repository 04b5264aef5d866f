// The shadowed database (shadowgen/output/database.h, read by shadowgen/scene/
// database_reader.h): lossless round trips, bit for bit, and clear messages for malformed
// files. Scenes are built by hand so that these tests do not depend on shadow generation;
// what a database's geometry must pass is tested in tests/shadowgen/scene/
// database_reader_test.cpp.

#include "shadowgen/output/database.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/scene/database_reader.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

using hsr::Loop3;
using hsr::Polygon3;

Polygon3 square(double x0, double y0, double size, double z) {
  return {{{x0, y0, z}, {x0 + size, y0, z}, {x0 + size, y0 + size, z}, {x0, y0 + size, z}}, {}};
}

// Two faces (one with a hole, one split into two triangles), a directional and a point
// light with a range, a view; lit details for some (face, light) pairs only.
ShadowedScene sample() {
  Scene scene;
  Face ground{"ground", {square(0, 0, 10, 0)}, "scenes/room.json"};
  ground.parts[0].holes.push_back({{2, 2, 0}, {2, 3, 0}, {3, 3, 0}, {3, 2, 0}});
  Face bent{"mesh/7",
            {Polygon3{{{0, 0, 1}, {1, 0, 1}, {0, 1, 1.5}}, {}},
             Polygon3{{{1, 0, 1}, {1, 1, 1}, {0, 1, 1.5}}, {}}},
            "models/bent.obj"};
  bent.origin = {"cityjson", "NL.Pand.1-0", "NL.Pand.1", "RoofSurface"};
  scene.faces = {ground, bent};

  Light sun;
  sun.id = "sun";
  sun.type = LightType::kDirectional;
  sun.direction = {-0.3, 0.2, -1.0};
  Light lamp;
  lamp.id = "lamp";
  lamp.type = LightType::kPoint;
  lamp.position = {4.0, 5.0, 2.5};
  lamp.intensity = {0.5, 0.25, 1.0};
  lamp.range = LightRange{5.0, 20.0, 2.0};
  scene.lights = {sun, lamp};
  scene.views = {ViewSpec{"main", {20, -15, 10}, {5, 5, 0}, {0, 0, 1}, 45.0}};

  Polygon3 lit_ground = square(0, 0, 2, 0);
  lit_ground.holes.push_back({{0.1, 0.2, 0}, {0.1, 0.7, 0}, {0.6, 0.7, 0}});
  ShadowedScene s(
      std::move(scene),
      LitTable({{{LitPolygon{0, lit_ground}, LitPolygon{0, square(5, 5, 1, 0)}}, {}},
                {{}, {LitPolygon{1, Polygon3{{{1, 0, 1}, {1, 1, 1}, {0, 1, 1.5}}, {}}}}}}));
  return s;
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// "p12": built piece by piece, as g++ 12 warns falsely on "p" + std::to_string(12).
std::string numbered(char prefix, std::size_t n) {
  std::string id(1, prefix);
  id += std::to_string(n);
  return id;
}

void expect_same(const glm::dvec3& a, const glm::dvec3& b, const std::string& where) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(bits(a[i]), bits(b[i])) << where << "[" << i << "]: " << a[i] << " vs " << b[i];
  }
}

void expect_same(const Loop3& a, const Loop3& b, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (std::size_t i = 0; i < a.size(); ++i) {
    expect_same(a[i], b[i], where + "[" + std::to_string(i) + "]");
  }
}

void expect_same(const std::vector<Polygon3>& a, const std::vector<Polygon3>& b,
                 const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (std::size_t p = 0; p < a.size(); ++p) {
    const std::string at = where + "[" + std::to_string(p) + "]";
    expect_same(a[p].outer, b[p].outer, at + ".outer");
    ASSERT_EQ(a[p].holes.size(), b[p].holes.size()) << at;
    for (std::size_t h = 0; h < a[p].holes.size(); ++h) {
      expect_same(a[p].holes[h], b[p].holes[h], at + ".holes[" + std::to_string(h) + "]");
    }
  }
}

// Everything the database stores, bit for bit (a light's unused position or direction
// is not stored, so it is not compared).
void expect_same(const std::vector<LitPolygon>& a, const std::vector<LitPolygon>& b,
                 const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].part, b[i].part) << where << "[" << i << "]";
  }
  expect_same(polygons_of(a), polygons_of(b), where);
}

void expect_same(const ShadowedScene& a, const ShadowedScene& b) {
  ASSERT_EQ(a.scene().faces.size(), b.scene().faces.size());
  for (std::size_t f = 0; f < a.scene().faces.size(); ++f) {
    const Face& x = a.scene().faces[f];
    const Face& y = b.scene().faces[f];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.source_file, y.source_file);
    EXPECT_EQ(x.origin, y.origin) << x.id;
    expect_same(x.parts, y.parts, x.id + ".parts");
  }
  ASSERT_EQ(a.scene().lights.size(), b.scene().lights.size());
  for (std::size_t l = 0; l < a.scene().lights.size(); ++l) {
    const Light& x = a.scene().lights[l];
    const Light& y = b.scene().lights[l];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.type, y.type);
    if (x.type == LightType::kDirectional) {
      expect_same(x.direction, y.direction, x.id + ".direction");
    } else {
      expect_same(x.position, y.position, x.id + ".position");
    }
    expect_same(x.intensity, y.intensity, x.id + ".intensity");
    ASSERT_EQ(x.range.has_value(), y.range.has_value()) << x.id;
    if (x.range) {
      EXPECT_EQ(bits(x.range->falloff_start), bits(y.range->falloff_start));
      EXPECT_EQ(bits(x.range->end), bits(y.range->end));
      EXPECT_EQ(bits(x.range->exponent), bits(y.range->exponent));
    }
  }
  ASSERT_EQ(a.scene().views.size(), b.scene().views.size());
  for (std::size_t v = 0; v < a.scene().views.size(); ++v) {
    const ViewSpec& x = a.scene().views[v];
    const ViewSpec& y = b.scene().views[v];
    EXPECT_EQ(x.id, y.id);
    expect_same(x.eye, y.eye, x.id + ".eye");
    expect_same(x.target, y.target, x.id + ".target");
    expect_same(x.up, y.up, x.id + ".up");
    EXPECT_EQ(bits(x.fov_deg), bits(y.fov_deg));
  }
  ASSERT_EQ(a.lit().size(), b.lit().size());
  for (std::size_t f = 0; f < a.lit().size(); ++f) {
    ASSERT_EQ(a.lit()[f].size(), b.lit()[f].size());
    for (std::size_t l = 0; l < a.lit()[f].size(); ++l) {
      expect_same(a.lit()[f][l], b.lit()[f][l],
                  "lit[" + std::to_string(f) + "][" + std::to_string(l) + "]");
    }
  }
}

ShadowedScene round_trip(const ShadowedScene& s) {
  return parse_database(database_json(s), "round-trip.json");
}

class DatabaseFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::path(::testing::TempDir()) /
           (std::string("shadowgen-db-") + info->name() + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }
  static std::string contents(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  std::filesystem::path dir_;
};

std::string error_of(const std::string& json) {
  try {
    parse_database(json, "broken.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Database, RoundTripKeepsEverythingBitForBit) {
  const ShadowedScene s = sample();
  expect_same(s, round_trip(s));
}

TEST(Database, FaceOriginsRoundTripAndAreChecked) {
  const ShadowedScene s = sample();
  const std::string text = database_json(s);
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_FALSE(json["faces"][0].contains("origin"));
  EXPECT_EQ(json["faces"][1]["origin"],
            nlohmann::json::parse(R"({"format": "cityjson", "object": "NL.Pand.1-0",
                                      "group": "NL.Pand.1", "semantic": "RoofSurface"})"));
  std::string empty_format = text;
  const std::string cityjson = R"("cityjson")";
  empty_format.replace(empty_format.find(cityjson), cityjson.size(), R"("")");
  EXPECT_EQ(error_of(empty_format),
            "broken.json: face 'mesh/7': faces[1].origin.format: must name the format the face "
            "comes from, not be empty");
}

TEST(Database, RoundTripIsAFixedPoint) {
  const std::string text = database_json(sample());
  EXPECT_EQ(database_json(parse_database(text, "db.json")), text);
}

// The indexed layout, by hand: the four strips of sun_path_by_hand share their sides, so
// the 16 corners of its regions are 10 vertices, and their 48 coordinates 5 numbers, each
// written once, in the order of first use.
TEST(Database, RegionsShareTheFacesVerticesAndNumbers) {
  const nlohmann::json face =
      nlohmann::json::parse(database_json(test::sun_path_by_hand()))["faces"][0];
  EXPECT_EQ(face["numbers"], nlohmann::json::parse("[0.0, 1.0, 2.0, 3.0, 4.0]"));
  EXPECT_EQ(face["vertices"], nlohmann::json::parse(R"([0,0,0, 1,0,0, 1,1,0, 0,1,0, 2,0,0,
                                                        2,1,0, 3,0,0, 3,1,0, 4,0,0, 4,1,0])"));
  EXPECT_EQ(face["sun_hours"]["p"]["regions"], nlohmann::json::parse(R"([
      {"hours": 0.0, "polygons": [[[0, 1, 2, 3]]]},
      {"hours": 1.5, "polygons": [[[1, 4, 5, 2]], [[4, 6, 7, 5]]]},
      {"hours": 2.0, "polygons": [[[6, 8, 9, 7]]]}])"));
}

// Both layouts hold the same scene: read back, each gives what was written, bit for bit,
// and writing it again gives the same text whichever layout it was read from.
TEST(Database, BothLayoutsReadBackTheSameScene) {
  for (const ShadowedScene& s : {sample(), test::sun_path_by_hand()}) {
    const std::string indexed = database_json(s);
    const std::string inlined = database_json(s, database::Layout::kInline);
    EXPECT_EQ(nlohmann::json::parse(indexed)["format"], "shadowgen-shadowed/2");
    EXPECT_EQ(nlohmann::json::parse(inlined)["format"], "shadowgen-shadowed/1");
    EXPECT_LT(indexed.size(), inlined.size());
    const ShadowedScene from_indexed = parse_database(indexed, "new.json");
    const ShadowedScene from_inline = parse_database(inlined, "old.json");
    expect_same(s, from_indexed);
    expect_same(s, from_inline);
    EXPECT_EQ(database_json(from_inline), indexed);
    EXPECT_EQ(database_json(from_indexed, database::Layout::kInline), inlined);
  }
}

// Numbers are told apart by their bits: 0.0 and -0.0 are two numbers of the table, and a
// vertex keeps its signed zero.
TEST(Database, SignedZerosStayApartInTheSharedNumbers) {
  ShadowedScene s = sample();
  Polygon3 signed_zeros{{{7.0, 0.0, -0.0}, {8.0, -0.0, 0.0}, {8.0, 1.0, -0.0}}, {}};
  s.lit_at(0, 0).push_back({0, signed_zeros});
  const nlohmann::json face = nlohmann::json::parse(database_json(s))["faces"][0];
  std::size_t zeros = 0;
  for (const nlohmann::json& n : face["numbers"]) zeros += n.get<double>() == 0.0 ? 1 : 0;
  EXPECT_EQ(zeros, 2u);
  expect_same(s, round_trip(s));
}

TEST(Database, IndicesOutOfTheirTablesAreErrors) {
  const std::string text = database_json(test::sun_path_by_hand());
  const auto changed = [&](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json db = nlohmann::json::parse(text);
    change(db["faces"][0]);
    return error_of(db.dump());
  };
  EXPECT_EQ(changed([](nlohmann::json& face) {
              face["sun_hours"]["p"]["regions"][2]["polygons"][0][0][1] = 10;
            }),
            "broken.json: face 'g': faces[0].sun_hours.p.regions[2].polygons[0][0][1]: expected "
            "the index of one of the face's 10 vertices");
  EXPECT_EQ(changed([](nlohmann::json& face) { face["vertices"][4] = 5; }),
            "broken.json: face 'g': faces[0].vertices[4]: expected the index of one of the "
            "face's 5 numbers");
  EXPECT_EQ(changed([](nlohmann::json& face) { face["vertices"].erase(29); }),
            "broken.json: face 'g': faces[0].vertices: expected three numbers per vertex, found "
            "29 indices");
  EXPECT_EQ(changed([](nlohmann::json& face) { face.erase("numbers"); }),
            "broken.json: face 'g': faces[0]: \"numbers\" and \"vertices\" come together");
  EXPECT_EQ(changed([](nlohmann::json& face) {
              face["sun_hours"]["p"]["regions"][0]["polygons"][0] = nlohmann::json::array();
            }),
            "broken.json: face 'g': faces[0].sun_hours.p.regions[0].polygons[0]: a polygon needs "
            "its outer loop");
}

// Numbers where the format takes any finite value: light positions and directions. (The
// JSON layer's own round trip, random bit patterns included: tests/shadowgen/json.)
TEST(Database, ExtremeDoublesRoundTrip) {
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kMin = std::numeric_limits<double>::min();
  constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();
  const std::vector<double> values = {-0.0,
                                      0.0,
                                      0.1,
                                      -0.1,
                                      1e-300,
                                      -1e-300,
                                      kDenormMin,
                                      -kDenormMin,
                                      kMin,
                                      kMin / 3.0,
                                      kMax,
                                      -kMax,
                                      1.0 / 3.0,
                                      2.0 / 3.0,
                                      1e21,
                                      1e22,
                                      123456789012345678.0,
                                      9007199254740993.0,
                                      0.30000000000000004,
                                      5e-324 * 12345.0,
                                      1e308,
                                      std::nextafter(1.0, 2.0),
                                      std::nextafter(1.0, 0.0),
                                      1e8 + 0.1};
  Scene scene;
  scene.faces.push_back(Face{"f", {square(0, 0, 1, 0)}, "x.json"});
  for (std::size_t i = 0; i + 2 < values.size(); i += 3) {
    // A direction may have any magnitude (none of these is zero); a position lies within
    // the supported coordinate range (docs/scene-format.md), which is checked on reading.
    const glm::dvec3 v(values[i], values[i + 1], values[i + 2]);
    if (glm::all(glm::lessThanEqual(glm::abs(v), glm::dvec3(1e100)))) {
      Light point;
      point.id = numbered('p', i);
      point.type = LightType::kPoint;
      point.position = v;
      scene.lights.push_back(point);
    }
    Light directional;
    directional.id = numbered('d', i);
    directional.direction = v;
    scene.lights.push_back(directional);
  }
  LitTable lit(1, scene.lights.size());
  ShadowedScene s(std::move(scene), std::move(lit));
  ASSERT_EQ(s.scene().lights.front().id, numbered('p', 0));
  const ShadowedScene back = round_trip(s);
  expect_same(s, back);
  EXPECT_TRUE(std::signbit(back.scene().lights[0].position.x));  // -0.0 kept its sign
}

TEST(Database, RandomBitPatternsRoundTrip) {
  std::mt19937_64 random(20240611);
  Scene scene;
  scene.faces.push_back(Face{"f", {square(0, 0, 1, 0)}, "x.json"});
  for (int l = 0; l < 300; ++l) {
    Light light;  // directional: a direction may have any finite magnitude
    light.id = numbered('l', static_cast<std::size_t>(l));
    for (int i = 0; i < 3; ++i) {
      do {
        light.direction[i] = std::bit_cast<double>(random());
      } while (!std::isfinite(light.direction[i]));
    }
    scene.lights.push_back(light);
  }
  LitTable lit(1, scene.lights.size());
  ShadowedScene s(std::move(scene), std::move(lit));
  expect_same(s, round_trip(s));
}

TEST(Database, NumbersAlwaysReadAsFloatingPoint) {
  Scene scene;
  scene.faces.push_back(Face{"f", {{{{28, -0.0, 1e-300}, {1, 0, 0}, {0, 1, 0}}, {}}}, "x"});
  ShadowedScene s(std::move(scene), LitTable(1, 0));
  const std::string text = database_json(s);
  EXPECT_NE(text.find("[28.0,-0.0,1e-300]"), std::string::npos) << text;
}

TEST(Database, EmptyLitRegionsAreLeftOut) {
  const ShadowedScene s = sample();
  const nlohmann::json json = nlohmann::json::parse(database_json(s));
  EXPECT_EQ(json["format"], "shadowgen-shadowed/2");
  ASSERT_EQ(json["faces"].size(), 2u);
  EXPECT_EQ(json["faces"][0]["id"], "ground");
  EXPECT_TRUE(json["faces"][0]["lit"].contains("sun"));
  EXPECT_FALSE(json["faces"][0]["lit"].contains("lamp"));
  EXPECT_FALSE(json["faces"][1]["lit"].contains("sun"));
  EXPECT_EQ(json["faces"][1]["lit"]["lamp"].size(), 1u);
  EXPECT_FALSE(json["lights"][0].contains("range"));
  EXPECT_EQ(json["lights"][1]["range"]["end"], 20.0);
}

TEST(Database, EmptySceneRoundTrips) {
  const ShadowedScene empty;
  const std::string text = database_json(empty);
  EXPECT_TRUE(nlohmann::json::accept(text)) << text;
  expect_same(empty, round_trip(empty));
}

TEST(Database, IdsWithAnyCharactersRoundTrip) {
  ShadowedScene s = sample();
  s.edit_face(
      0, [&](Face& face) { face.id = "a \"quoted\", back\\slash\nnew line\ttab \u00e9\u6f22"; });
  s.edit_scene([&](Scene& scene) { scene.lights[0].id = "sun/\x01control"; });
  s.edit_face(1, [&](Face& face) { face.source_file = "C:\\models\\bent.obj"; });
  expect_same(s, round_trip(s));
}

// Unknown keys are read past with a warning naming their path (an error when strict).
TEST(Database, ReadsIntegersAndWarnsAboutUnknownKeys) {
  const std::string text = R"({
    "format": "shadowgen-shadowed/1", "generator": "someone else",
    "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1],
                "intensity": [1, 1, 1], "colour": "warm"}],
    "views": [],
    "faces": [{"id": "g", "source_file": "s.json", "note": 1,
               "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}],
               "lit": {"sun": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}]}}]
  })";
  std::vector<std::string> warnings;
  const ShadowedScene s = parse_database(text, "db.json", {}, warnings);
  ASSERT_EQ(s.scene().faces.size(), 1u);
  EXPECT_EQ(s.scene().lights[0].direction, glm::dvec3(0, 0, -1));
  ASSERT_EQ(s.lit()[0][0].size(), 1u);
  EXPECT_EQ(s.lit()[0][0][0].polygon.outer[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(warnings, (std::vector<std::string>{
                          "db.json: light 'sun': lights[0] ('sun'): unknown key 'colour'",
                          "db.json: face 'g': faces[0]: unknown key 'note'",
                          "db.json: unknown key 'generator'"}));

  std::vector<std::string> strict_warnings;
  try {
    (void)parse_database(text, "db.json", {.strict = true}, strict_warnings);
    FAIL() << "no error under strict";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "db.json: light 'sun': lights[0] ('sun'): unknown key 'colour'");
  }
}

// A lit polygon carries the part of its face it lies on: written as "part" on a face of
// several parts, and without the key found as the part whose plane is nearest.
TEST(Database, LitPolygonsKeepTheirPart) {
  const std::string text = database_json(sample());
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_FALSE(json["faces"][0]["lit"]["sun"][0].contains("part"));  // one part: no key
  EXPECT_EQ(json["faces"][1]["lit"]["lamp"][0]["part"], 1);

  const auto read = [](const std::string& lit) {
    return parse_database(R"({"format": "shadowgen-shadowed/1", "lights": [
        {"id": "sun", "type": "directional", "direction": [0, 0, -1], "intensity": [1, 1, 1]}],
      "views": [], "faces": [{"id": "bent", "source_file": "s.json", "parts": [
        {"outer": [[0, 0, 1], [1, 0, 1], [0, 1, 1.5]], "holes": []},
        {"outer": [[1, 0, 1], [1, 1, 1], [0, 1, 1.5]], "holes": []}],
      "lit": {"sun": [)" + lit +
                              "]}}]}",
                          "db.json");
  };
  const std::string second = R"({"outer": [[1, 0, 1], [1, 1, 1], [0, 1, 1.5]], "holes": [])";
  EXPECT_EQ(read(second + "}").lit()[0][0][0].part, 1u);
  EXPECT_EQ(read(second + R"(, "part": 1})").lit()[0][0][0].part, 1u);
  EXPECT_THROW(read(second + R"(, "part": 0})"), InputError);  // not in part 0's plane
  EXPECT_THROW(read(second + R"(, "part": 2})"), InputError);
  EXPECT_THROW(read(second + R"(, "part": -1})"), InputError);
}

TEST(Database, RefusesToWriteWhatCannotBeReadBack) {
  ShadowedScene s = sample();
  s.lit_at(1, 1)[0].polygon.outer[0].y = std::numeric_limits<double>::quiet_NaN();
  try {
    (void)database_json(s);
    FAIL() << "a NaN was written";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("face 'mesh/7'"), std::string::npos) << e.what();
  }

  s = sample();
  s.lit_at(0, 0)[0].polygon.holes[0].pop_back();
  EXPECT_THROW((void)database_json(s), std::invalid_argument);
  s = sample();
  s.edit_scene([&](Scene& scene) { scene.lights[1].id = "sun"; });
  EXPECT_THROW((void)database_json(s), std::invalid_argument);
}

TEST(Database, MalformedFilesNameTheFileTheFaceThePathAndTheProblem) {
  EXPECT_EQ(error_of("{"),
            "broken.json: line 1, column 2: invalid JSON: syntax error while parsing object key - "
            "unexpected end of input; expected string literal");
  EXPECT_EQ(error_of("[]"), "broken.json: a shadowed database is a JSON object; found an array");
  EXPECT_EQ(error_of(R"({"format": "shadowgen-scene/1"})"),
            "broken.json: format: unsupported format 'shadowgen-scene/1'; this reader reads "
            "'shadowgen-shadowed/2' and 'shadowgen-shadowed/1'");
  EXPECT_EQ(error_of(R"({"format": "shadowgen-shadowed/1", "views": [], "faces": []})"),
            "broken.json: missing 'lights'");

  const std::string head =
      R"({"format": "shadowgen-shadowed/1", "views": [],
          "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1],
                      "intensity": [1, 1, 1]}],
          "faces": [)";
  const std::string good_face =
      R"({"id": "good", "source_file": "s.json",
          "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}], "lit": {}})";
  auto faces = [&](const std::string& face) { return head + good_face + "," + face + "]}"; };

  EXPECT_EQ(error_of(faces(R"({"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1]], "holes": []}], "lit": {}})")),
            "broken.json: face 'w': faces[1].parts[0].outer[2]: expected an array of 3 numbers, "
            "found an array of 2");
  EXPECT_EQ(error_of(faces(R"({"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0]], "holes": []}], "lit": {}})")),
            "broken.json: face 'w': faces[1].parts[0]: the outer loop has 2 vertices; at least 3 "
            "are needed");
  EXPECT_EQ(error_of(faces(R"({"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, "z"]], "holes": []}], "lit": {}})")),
            "broken.json: face 'w': faces[1].parts[0].outer[2][2]: expected a number, found a "
            "string");
  EXPECT_NE(error_of(faces(R"({"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 1e400]], "holes": []}], "lit": {}})"))
                .find("invalid JSON: the number 1e400 is out of the range of a double"),
            std::string::npos);
  EXPECT_EQ(error_of(faces(R"({"id": "w", "source_file": "s.json", "parts": [], "lit": {}})")),
            "broken.json: face 'w': faces[1].parts: a face needs at least one polygon");
  EXPECT_EQ(error_of(faces(R"({"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}]})")),
            "broken.json: face 'w': faces[1]: missing 'lit'");
  EXPECT_EQ(error_of(faces(R"({"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}],
      "lit": {"moon": []}})")),
            "broken.json: face 'w': faces[1].lit['moon']: no light has this id");
  EXPECT_EQ(error_of(faces(R"({"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": {}}], "lit": {}})")),
            "broken.json: face 'w': faces[1].parts[0].holes: expected an array, found an object");
  EXPECT_EQ(error_of(faces(R"({"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}],
      "lit": {"sun": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": [[[0, 0, 0]]]}]}})")),
            "broken.json: face 'w': faces[1].lit['sun'][0]: hole 0 has 1 vertices; at least 3 are "
            "needed");
  EXPECT_EQ(error_of(faces(good_face)),
            "broken.json: faces[1].id: duplicate id 'good' (already used by another face)");
  EXPECT_EQ(error_of(faces(R"({"source_file": "s.json"})")), "broken.json: faces[1]: missing 'id'");
  EXPECT_EQ(error_of(R"({"format": "shadowgen-shadowed/1", "views": [], "faces": [],
          "lights": [{"id": "sun", "type": "spot", "direction": [0, 0, -1]}]})"),
            "broken.json: light 'sun': lights[0] ('sun').type: unknown light type 'spot' "
            "(expected 'directional' or 'point')");
  EXPECT_EQ(error_of(R"({"format": "shadowgen-shadowed/1", "views": [], "faces": [],
          "lights": [{"id": "lamp", "type": "point", "position": [0, 0, 1],
                      "intensity": [1, 1, 1], "range": {"falloff_start": 1, "end": 2}}]})"),
            "broken.json: light 'lamp': lights[0] ('lamp').range: missing 'exponent'");
}

TEST_F(DatabaseFile, WriteAndReadAFile) {
  const std::filesystem::path path = dir_ / "db.json";
  const ShadowedScene s = sample();
  write_database(s, path);
  EXPECT_EQ(files(), std::vector<std::string>{"db.json"});
  expect_same(s, read_database(path));
  EXPECT_EQ(contents(path), database_json(s));
}

TEST_F(DatabaseFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const std::filesystem::path path = dir_ / "db.json";
  write_database(sample(), path);
  const std::string before = contents(path);

  ShadowedScene bad = sample();
  bad.edit_face(
      0, [&](Face& face) { face.parts[0].outer[0].x = std::numeric_limits<double>::infinity(); });
  EXPECT_THROW(write_database(bad, path), std::invalid_argument);
  EXPECT_EQ(contents(path), before);
  EXPECT_EQ(files(), std::vector<std::string>{"db.json"});

  EXPECT_THROW(write_database(sample(), dir_ / "missing" / "db.json"), std::runtime_error);
  EXPECT_EQ(files(), std::vector<std::string>{"db.json"});
}

TEST_F(DatabaseFile, ReadingAMissingFileNamesIt) {
  try {
    (void)read_database(dir_ / "nothing.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir_ / "nothing.json").string());
    EXPECT_TRUE(e.face_id().empty());
  }
}

}  // namespace
}  // namespace shadowgen
