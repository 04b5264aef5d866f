// OBJ + MTL export (shadowgen/obj_export.h), read back with an independent plain reader
// (tests/support/obj_text.h): per face group, each material's triangles add up to its
// light-set region, lit and shadowed parts add up to the face, names and colours are as
// documented, vertices read back bit for bit, and the output is deterministic.

#include "shadowgen/output/obj_export.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "clipper/predicates.h"
#include "hsr/area.h"
#include "hsr/plane_chart.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/shadows/light_regions.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/support/obj_text.h"
#include "tests/support/relative_error.h"

namespace shadowgen {
namespace {

using test::generated;
using test::kDartUnderRoof;
using test::kTwoLights;
using test::relative_error;

struct Worst {
  double region = 0.0;  // a material's triangles against its region, relative
  double face = 0.0;    // all of a group's triangles against the face's area, relative
  double lit = 0.0;     // materials holding a light against its lit area, relative to face
};

// Everything the OBJ must say about a shadowed scene, read back from the text.
Worst ExpectObjMatches(const ShadowedScene& s, const ObjFiles& files, double tolerance) {
  Worst worst;
  const test::ObjText obj = test::parse_obj(files.obj);
  const test::MtlText mtl = test::parse_mtl(files.mtl);
  EXPECT_TRUE(obj.errors.empty()) << obj.errors.front();
  EXPECT_TRUE(mtl.errors.empty()) << mtl.errors.front();
  const Scene& scene = s.scene();
  EXPECT_EQ(obj.groups.size(), scene.faces.size());
  if (obj.groups.size() != scene.faces.size()) return worst;

  // The documented naming: sets in light_regions' order over the whole scene, each named
  // obj_name(light_set_name(...)), a name already taken getting ~2, ~3, ...
  std::vector<std::vector<std::size_t>> sets;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (const LightRegion& r : light_regions(s, f)) sets.push_back(r.lights);
  }
  std::sort(sets.begin(), sets.end(), [](const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
  std::map<std::vector<std::size_t>, std::string> name_of;
  std::map<std::string, std::vector<std::size_t>> set_of_material;
  std::vector<std::string> names;
  for (const auto& set : sets) {
    const std::string base = obj_name(light_set_name(scene, set));
    std::string name = base;
    for (int k = 2; set_of_material.count(name) != 0; ++k) name = base + "~" + std::to_string(k);
    name_of[set] = name;
    set_of_material[name] = set;
    names.push_back(name);
  }
  EXPECT_EQ(mtl.order, names);

  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const Face& face = scene.faces[f];
    const test::ObjGroup& group = obj.groups[f];
    EXPECT_EQ(group.name, obj_name(face.id));
    const std::vector<LightRegion> regions = light_regions(s, f);
    const std::map<std::string, double> areas = test::material_areas(group);
    EXPECT_EQ(areas.size(), regions.size()) << face.id;

    double total = 0.0;
    for (const auto& [material, a] : areas) total += a;
    const double face_area = area(face.parts);
    const double face_error = relative_error(total, face_area);
    EXPECT_LE(face_error, tolerance) << face.id << ": triangles " << total;
    worst.face = std::max(worst.face, face_error);

    for (const LightRegion& r : regions) {
      const std::string& material = name_of.at(r.lights);
      if (areas.count(material) == 0) {
        ADD_FAILURE() << face.id << ": no triangles of " << material;
        continue;
      }
      const double region_error = relative_error(areas.at(material), lit_area(r.polygons));
      EXPECT_LE(region_error, tolerance) << face.id << ", " << material;
      worst.region = std::max(worst.region, region_error);

      EXPECT_EQ(mtl.kd.count(material), 1u) << material;
      if (mtl.kd.count(material) == 0) continue;
      const glm::dvec3 kd = light_set_colour(scene, r.lights);
      EXPECT_EQ(mtl.kd.at(material), (test::Vec3{kd.x, kd.y, kd.z})) << material;
    }

    if (face_area == 0.0) continue;
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      double with_light = 0.0;
      for (const auto& [material, a] : areas) {
        const auto& set = set_of_material[material];
        if (std::find(set.begin(), set.end(), l) != set.end()) with_light += a;
      }
      const double error = std::abs(with_light - lit_area(s.lit()[f][l])) / face_area;
      EXPECT_LE(error, tolerance) << face.id << ", light " << scene.lights[l].id;
      worst.lit = std::max(worst.lit, error);
    }

    // Counter-clockwise seen from the front: each triangle turns, exactly, the way its
    // normal points (orient2d in the chart that drops the normal's largest component), and
    // the normal is a unit vector.
    for (const test::ObjTriangle& t : group.triangles) {
      const test::Vec3 n = t.normals[0];
      EXPECT_NEAR(test::dot(n, n), 1.0, 1e-12);
      const hsr::PlaneChart chart = hsr::chart_facing({n[0], n[1], n[2]});
      auto at = [&chart, &t](int k) {
        const test::Vec3& v = t.corners[static_cast<std::size_t>(k)];
        return chart(glm::dvec3(v[0], v[1], v[2]));
      };
      const clipper::Orientation turn = clipper::orient2d(at(0), at(1), at(2));
      const clipper::Orientation front = n[static_cast<std::size_t>(chart.dropped_axis)] > 0
                                             ? clipper::Orientation::kCounterClockwise
                                             : clipper::Orientation::kClockwise;
      EXPECT_EQ(turn, front) << face.id << ": a triangle turns the wrong way or has no area";
    }
  }
  return worst;
}

TEST(ObjExport, TwoLightsHandScene) {
  const ShadowedScene s = generated(kTwoLights);
  const ObjFiles files = obj_export(s, "two.mtl");
  ExpectObjMatches(s, files, 1e-12);

  const test::ObjText obj = test::parse_obj(files.obj);
  EXPECT_EQ(obj.mtllib, "two.mtl");
  ASSERT_EQ(obj.groups.size(), 2u);
  const std::map<std::string, double> ground = test::material_areas(obj.groups[0]);
  ASSERT_EQ(ground.size(), 4u);
  EXPECT_NEAR(ground.at("shadow"), 12.0, 1e-12);
  EXPECT_NEAR(ground.at("down"), 4.0, 1e-12);
  EXPECT_NEAR(ground.at("slant"), 4.0, 1e-12);
  EXPECT_NEAR(ground.at("down+slant"), 80.0, 1e-12);
  const std::map<std::string, double> square = test::material_areas(obj.groups[1]);
  ASSERT_EQ(square.size(), 1u);
  EXPECT_NEAR(square.at("down+slant"), 16.0, 1e-12);

  // The colour rule with two lights of intensity 1: 0.2, 0.2 + 0.8 / 2, 1.
  const test::MtlText mtl = test::parse_mtl(files.mtl);
  EXPECT_EQ(mtl.order, (std::vector<std::string>{"shadow", "down", "slant", "down+slant"}));
  EXPECT_EQ(mtl.kd.at("shadow"), (test::Vec3{0.2, 0.2, 0.2}));
  EXPECT_EQ(mtl.kd.at("down"), (test::Vec3{0.2 + 0.8 * 0.5, 0.2 + 0.8 * 0.5, 0.2 + 0.8 * 0.5}));
  EXPECT_EQ(mtl.kd.at("slant"), mtl.kd.at("down"));
  EXPECT_EQ(mtl.kd.at("down+slant"), (test::Vec3{1.0, 1.0, 1.0}));

  // Both faces face +z: one normal each, (0, 0, 1).
  EXPECT_EQ(obj.normals, (std::vector<test::Vec3>{{0, 0, 1}, {0, 0, 1}}));
}

TEST(ObjExport, ColourRuleWeighsEachChannelByIntensity) {
  Scene scene;
  Light red, blue, dim;
  red.id = "red";
  red.intensity = {1, 0, 0};
  blue.id = "blue";
  blue.intensity = {0, 0, 3};
  dim.id = "dim";
  dim.intensity = {1, 0, 1};
  scene.lights = {red, blue, dim};
  const std::vector<std::size_t> none, r{0}, b{1}, rd{0, 2}, all{0, 1, 2};
  EXPECT_EQ(light_set_colour(scene, none), glm::dvec3(0.2));
  EXPECT_EQ(light_set_colour(scene, r), glm::dvec3(0.2 + 0.8 * 0.5, 0.2, 0.2));
  EXPECT_EQ(light_set_colour(scene, b), glm::dvec3(0.2, 0.2, 0.2 + 0.8 * 0.75));
  EXPECT_EQ(light_set_colour(scene, rd), glm::dvec3(1.0, 0.2, 0.2 + 0.8 * 0.25));
  EXPECT_EQ(light_set_colour(scene, all), glm::dvec3(1.0, 0.2, 1.0));
  // Negative intensities count as 0: the colour stays within [0.2, 1].
  scene.lights[1].intensity = {-5, 0, 3};
  EXPECT_EQ(light_set_colour(scene, b), glm::dvec3(0.2, 0.2, 0.2 + 0.8 * 0.75));
}

TEST(ObjExport, ShadowIsDarkerThanLitInEveryChannel) {
  const ShadowedScene s = generated(kTwoLights);
  const glm::dvec3 shadow = light_set_colour(s.scene(), std::vector<std::size_t>{});
  for (const std::vector<std::size_t>& set :
       {std::vector<std::size_t>{0}, std::vector<std::size_t>{1}, std::vector<std::size_t>{0, 1}}) {
    const glm::dvec3 lit = light_set_colour(s.scene(), set);
    for (int c = 0; c < 3; ++c) EXPECT_LT(shadow[c], lit[c]);
  }
}

// Names are escaped reversibly: distinct ids stay distinct ("a b" and "a_b" once both
// became "a_b", which merged their groups and materials in viewers).
TEST(ObjExport, NamesAreEscapedAndMaterialsStayDistinct) {
  EXPECT_EQ(obj_name("sun"), "sun");
  EXPECT_EQ(obj_name("mesh/12"), "mesh/12");
  EXPECT_EQ(obj_name("a b\tc#d"), "a%20b%09c%23d");
  EXPECT_EQ(obj_name("caf\xc3\xa9"), "caf%C3%A9");
  EXPECT_EQ(obj_name("50%"), "50%25");
  EXPECT_EQ(obj_name(std::string("nul\0", 4)), "nul%00");
  EXPECT_EQ(obj_name(""), "%");
  EXPECT_NE(obj_name("a b"), obj_name("a_b"));
  EXPECT_NE(obj_name("a%20b"), obj_name("a b"));

  std::string two = kTwoLights;
  two.replace(two.find("\"down\""), 6, "\"a b\"");
  two.replace(two.find("\"slant\""), 7, "\"a_b\"");
  const ShadowedScene s = generated(two);
  const ObjFiles files = obj_export(s, "names.mtl");
  ExpectObjMatches(s, files, 1e-12);
  EXPECT_EQ(test::parse_mtl(files.mtl).order,
            (std::vector<std::string>{"shadow", "a%20b", "a_b", "a%20b+a_b"}));
  EXPECT_NE(files.mtl.find("# lights: a_b\nnewmtl a_b\n"), std::string::npos) << files.mtl;
  const std::map<std::string, double> ground =
      test::material_areas(test::parse_obj(files.obj).groups[0]);
  EXPECT_NEAR(ground.at("a%20b+a_b"), 80.0, 1e-12);

  // A light called "shadow" meets the empty set's name; a face id with a space.
  const ShadowedScene lone = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "the ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
      {"id": "square", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]]}
    ],
    "lights": [{"id": "shadow", "type": "directional", "direction": [0,0,-1]}]
  })");
  const ObjFiles lone_files = obj_export(lone, "lone.mtl");
  ExpectObjMatches(lone, lone_files, 1e-12);
  EXPECT_EQ(test::parse_mtl(lone_files.mtl).order,
            (std::vector<std::string>{"shadow", "shadow~2"}));
  const test::ObjText obj = test::parse_obj(lone_files.obj);
  ASSERT_EQ(obj.groups.size(), 2u);
  EXPECT_EQ(obj.groups[0].name, "the%20ground");
  EXPECT_EQ(test::material_areas(obj.groups[0]).at("shadow~2"), 84.0);
  EXPECT_EQ(test::material_areas(obj.groups[0]).at("shadow"), 16.0);
}

TEST(ObjExport, VerticesReadBackBitForBit) {
  // Coordinates with no short decimal form.
  const double third = 1.0 / 3.0, tenth = 0.1;
  char json[1024];
  std::snprintf(json, sizeof json, R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "ground", "outer": [[%.17g,%.17g,%.17g],[10.7,0,%.17g],[10.7,9.3,%.17g],[0,9.3,%.17g]]},
      {"id": "square", "outer": [[2.1,3.3,1.7],[6.9,3.3,1.7],[6.9,7.1,1.7],[2.1,7.1,1.7]]}
    ],
    "lights": [{"id": "sun", "type": "directional", "direction": [0.3,0.1,-1]}]
  })",
                tenth, third, tenth, tenth, tenth, tenth);
  const ShadowedScene s = generated(json);
  const ObjFiles files = obj_export(s, "x.mtl");
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_TRUE(obj.errors.empty()) << obj.errors.front();
  std::set<test::Vec3> expected, read(obj.vertices.begin(), obj.vertices.end());
  for (std::size_t f = 0; f < s.scene().faces.size(); ++f) {
    for (const LightRegion& r : light_regions(s, f)) {
      for (const LitPolygon& lit : r.polygons) {
        for (const glm::dvec3& v : lit.polygon.outer) expected.insert({v.x, v.y, v.z});
        for (const hsr::Loop3& h : lit.polygon.holes) {
          for (const glm::dvec3& v : h) expected.insert({v.x, v.y, v.z});
        }
      }
    }
  }
  EXPECT_EQ(read, expected);
  EXPECT_TRUE(read.count({tenth, third, tenth}) == 1);
  ExpectObjMatches(s, files, 1e-12);
}

TEST(ObjExport, NonPlanarFaceHasANormalPerTriangle) {
  const ShadowedScene s = generated(kDartUnderRoof);
  const ObjFiles files = obj_export(s, "dart.mtl");
  ExpectObjMatches(s, files, 1e-12);
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_EQ(obj.groups.size(), 2u);
  std::set<test::Vec3> dart_normals;
  for (const test::ObjTriangle& t : obj.groups[0].triangles) dart_normals.insert(t.normals[0]);
  EXPECT_EQ(dart_normals.size(), 2u);
  const std::map<std::string, double> dart = test::material_areas(obj.groups[0]);
  EXPECT_NEAR(dart.at("shadow"), std::sqrt(14.0) / 4, 1e-12);
  EXPECT_NEAR(dart.at("sun"), std::sqrt(14.0) * 7 / 4, 1e-12);
}

TEST(ObjExport, FaceWithHoleAndFaceWithoutArea) {
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]],
       "holes": [[[4,4,0],[6,4,0],[6,6,0],[4,6,0]]]},
      {"id": "square", "outer": [[3,3,1],[5,3,1],[5,5,1],[3,5,1]]},
      {"id": "line", "outer": [[0,0,2],[1,1,2],[2,2,2]]}
    ],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })");
  const ObjFiles files = obj_export(s, "hole.mtl");
  ExpectObjMatches(s, files, 1e-12);
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_EQ(obj.groups.size(), 3u);
  const std::map<std::string, double> ground = test::material_areas(obj.groups[0]);
  EXPECT_NEAR(ground.at("shadow"), 3.0, 1e-12);
  EXPECT_NEAR(ground.at("sun"), 93.0, 1e-12);
  EXPECT_EQ(obj.groups[2].name, "line");
  EXPECT_TRUE(obj.groups[2].triangles.empty());
}

TEST(ObjExport, ZeroLightsGiveOneShadowMaterial) {
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [{"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]}],
    "lights": []
  })");
  const ObjFiles files = obj_export(s, "dark.mtl");
  ExpectObjMatches(s, files, 1e-12);
  const test::MtlText mtl = test::parse_mtl(files.mtl);
  EXPECT_EQ(mtl.order, std::vector<std::string>{"shadow"});
  EXPECT_EQ(test::material_areas(test::parse_obj(files.obj).groups[0]).at("shadow"), 100.0);
}

constexpr const char* kRoom = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "floor", "outer": [[0,0,0],[8,0,0],[8,6,0],[0,6,0]]},
    {"id": "wall", "outer": [[0,6,0],[8,6,0],[8,6,4],[0,6,4]],
     "holes": [[[2,6,1],[3,6,1],[3,6,2],[2,6,2]]]},
    {"id": "table", "outer": [[2,2,1],[5,2,1],[5,4,1.2],[2,4,1]]},
    {"id": "shelf", "outer": [[1,5,2],[6,5,2],[6,6,2],[1,6,2]]},
    {"id": "post", "outer": [[6,1,0],[6.5,1,0],[6.5,1,3],[6,1,3]]},
    {"id": "ceiling", "outer": [[0,0,4],[0,6,4],[8,6,4],[8,0,4]]}
  ],
  "lights": [
    {"id": "sun", "type": "directional", "direction": [0.4, 0.5, -1], "intensity": [1, 0.9, 0.8]},
    {"id": "bulb", "type": "point", "position": [4, 3, 3]},
    {"id": "low", "type": "point", "position": [7, 0.5, 0.5], "intensity": [0.2, 0.2, 0.6]}
  ]
})";

TEST(ObjExport, AreasOnAGeneratedRoomWithThreeLights) {
  const ShadowedScene s = generated(kRoom);
  const ObjFiles files = obj_export(s, "room.mtl");
  const Worst w = ExpectObjMatches(s, files, 1e-9);
  std::printf("worst relative errors: region %.3g, face %.3g, lit %.3g\n", w.region, w.face, w.lit);
}

// A ground whose lit region has a hole per occluder (over 256 vertices) is triangulated in
// tiles: its triangles still add up to each region and to the lit area, and their
// corners are the regions' own and the crossings of the tiles' cut lines.
TEST(ObjExport, AGroundWithAHolePerOccluderIsTriangulatedInTiles) {
  const ShadowedScene s = generated(test::ground_under_slabs());
  const ObjFiles files = obj_export(s, "slabs.mtl");
  ExpectObjMatches(s, files, 1e-9);
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_EQ(obj.groups.front().name, "ground");
  std::set<test::Vec3> corners;
  for (const test::ObjTriangle& t : obj.groups.front().triangles) {
    corners.insert(t.corners.begin(), t.corners.end());
  }
  // The regions' own corners: the lit region's, whose holes are the shadows.
  const std::vector<LitPolygon>& lit = s.lit().at(0, 0);
  ASSERT_EQ(lit.size(), 1u);
  std::size_t own = lit[0].polygon.outer.size();
  for (const hsr::Loop3& hole : lit[0].polygon.holes) own += hole.size();
  ASSERT_GT(own, 256u);
  EXPECT_GT(corners.size(), own);
}

TEST(ObjExport, OutputIsDeterministic) {
  const ShadowedScene one = generated(kRoom, 1);
  const ShadowedScene three = generated(kRoom, 3);
  const ObjFiles a = obj_export(one, "room.mtl");
  const ObjFiles b = obj_export(one, "room.mtl");
  const ObjFiles c = obj_export(three, "room.mtl");
  EXPECT_EQ(a.obj, b.obj);
  EXPECT_EQ(a.mtl, b.mtl);
  EXPECT_EQ(a.obj, c.obj);
  EXPECT_EQ(a.mtl, c.mtl);
}

// Layers by light: per face a group of the whole face in shadow, then one group per light
// reaching it whose triangles add up to that light's lit area; "shadow" and one material
// per light reaching some face, coloured by the rule for that light alone.
void ExpectLayersMatch(const ShadowedScene& s, const ObjFiles& files, double tolerance) {
  const test::ObjText obj = test::parse_obj(files.obj);
  const test::MtlText mtl = test::parse_mtl(files.mtl);
  ASSERT_TRUE(obj.errors.empty()) << obj.errors.front();
  ASSERT_TRUE(mtl.errors.empty()) << mtl.errors.front();
  const Scene& scene = s.scene();
  auto group_name = [](const std::string& id) {
    std::string out;
    for (const char c : obj_name(id)) out += c == '@' ? std::string("%40") : std::string(1, c);
    return out;
  };
  std::vector<bool> reaches(scene.lights.size(), false);
  std::size_t g = 0;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const Face& face = scene.faces[f];
    ASSERT_LT(g, obj.groups.size());
    const test::ObjGroup& base = obj.groups[g++];
    EXPECT_EQ(base.name, group_name(face.id));
    const double face_area = area(face.parts);
    const std::map<std::string, double> shadow = test::material_areas(base);
    if (face_area > 0.0) {
      ASSERT_EQ(shadow.size(), 1u) << face.id;
      EXPECT_EQ(shadow.begin()->first, "shadow");
      EXPECT_LE(relative_error(shadow.begin()->second, face_area), tolerance) << face.id;
    }
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      if (s.lit()[f][l].empty()) continue;
      reaches[l] = true;
      ASSERT_LT(g, obj.groups.size());
      const test::ObjGroup& layer = obj.groups[g++];
      EXPECT_EQ(layer.name, group_name(face.id) + "@" + obj_name(scene.lights[l].id));
      const std::map<std::string, double> lit = test::material_areas(layer);
      ASSERT_EQ(lit.size(), 1u) << layer.name;
      EXPECT_LE(std::abs(lit.begin()->second - lit_area(s.lit()[f][l])), tolerance * face_area)
          << layer.name;
      const std::string& material = lit.begin()->first;
      ASSERT_EQ(mtl.kd.count(material), 1u) << material;
      const glm::dvec3 kd = light_set_colour(scene, std::vector<std::size_t>{l});
      EXPECT_EQ(mtl.kd.at(material), (test::Vec3{kd.x, kd.y, kd.z})) << material;
    }
  }
  EXPECT_EQ(g, obj.groups.size());
  std::vector<std::string> materials = {"shadow"};
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    if (reaches[l]) materials.push_back(obj_name(scene.lights[l].id));
  }
  EXPECT_EQ(mtl.order, materials);
}

TEST(ObjExport, LayersByLightAddUpToEachLightsLitArea) {
  const ShadowedScene room = generated(kRoom);
  ExpectLayersMatch(room, obj_export_by_light(room, "room.mtl"), 1e-9);
  const ShadowedScene two = generated(kTwoLights);
  const ObjFiles files = obj_export_by_light(two, "two.mtl");
  ExpectLayersMatch(two, files, 1e-12);
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_EQ(obj.groups.size(), 6u);
  EXPECT_EQ(obj.groups[1].name, "ground@down");
  EXPECT_NEAR(test::material_areas(obj.groups[1]).at("down"), 84.0, 1e-12);
  EXPECT_NEAR(test::material_areas(obj.groups[2]).at("slant"), 84.0, 1e-12);
}

// A face id and a light id holding '@' (as a sun path's instants do): the face's '@' is
// escaped, so the first '@' of a group name separates the two.
TEST(ObjExport, LayersByLightKeepFaceAndLightApart) {
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "roof@north", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
      {"id": "square", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]]}
    ],
    "lights": [{"id": "sun@noon", "type": "directional", "direction": [0,0,-1]},
               {"id": "shadow", "type": "directional", "direction": [0,0,1]}]
  })");
  const ObjFiles files = obj_export_by_light(s, "at.mtl");
  ExpectLayersMatch(s, files, 1e-12);
  const test::ObjText obj = test::parse_obj(files.obj);
  ASSERT_EQ(obj.groups.size(), 4u);
  EXPECT_EQ(obj.groups[0].name, "roof%40north");
  EXPECT_EQ(obj.groups[1].name, "roof%40north@sun@noon");
  EXPECT_EQ(test::material_areas(obj.groups[1]).at("sun@noon"), 84.0);
  // The light facing away from every face reaches none and gets no material.
  EXPECT_EQ(test::parse_mtl(files.mtl).order, (std::vector<std::string>{"shadow", "sun@noon"}));
  EXPECT_EQ(files.obj, obj_export_by_light(s, "at.mtl").obj);
}

}  // namespace
}  // namespace shadowgen
