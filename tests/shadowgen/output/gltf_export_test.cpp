// glTF export (shadowgen/output/gltf_export.h), read back from its bytes with an
// independent plain reader (tests/support/gltf_file.h): per material, the triangles' area
// is the database's area of its light set or band; the axes, the origin, names, colours and
// extras are as documented; a district at projected coordinates keeps its areas. Every
// file is also kept for the Khronos validator (CTest's gltf.validator).

#include "shadowgen/output/gltf_export.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bench/scenes/city.h"
#include "hsr/area.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/obj_export.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/shadows/light_regions.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/support/gltf_file.h"
#include "tests/support/relative_error.h"

namespace shadowgen {
namespace {

using test::generated;
using test::GltfFile;
using test::kTwoLights;
using test::relative_error;

constexpr GltfForm kForms[] = {GltfForm::kBinary, GltfForm::kText};

// An sRGB channel as glTF's linear colour factor (the sRGB transfer function).
double linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The file read back, kept for the validator, with no reading error.
GltfFile read_back(const std::string& bytes, GltfForm form) {
  test::keep_for_validator(bytes, form == GltfForm::kBinary ? ".glb" : ".gltf");
  GltfFile file = test::parse_gltf(bytes);
  EXPECT_TRUE(file.errors.empty()) << file.errors.front();
  return file;
}

// The database's area per light set, named as light_set_name() names it: the regions of
// every face (the OBJ export's and the glTF export's pieces).
std::map<std::string, double> light_set_areas(const ShadowedScene& shadowed) {
  std::map<std::string, double> areas;
  for (std::size_t f = 0; f < shadowed.scene().faces.size(); ++f) {
    for (const LightRegion& r : light_regions(shadowed, f)) {
      areas[light_set_name(shadowed.scene(), r.lights)] += lit_area(r.polygons);
    }
  }
  return areas;
}

// How far float32 positions may move a material's area, from the file's own triangles:
// each coordinate relative to the node is rounded to nearest, off by at most 2^-24 of its
// magnitude, so each vertex by at most δ = √3 · 2^-24 · (largest |coordinate|); a
// triangle's area then moves by at most δ times half its perimeter, plus 3δ².
std::map<std::string, double> float_rounding_bounds(GltfFile& file) {
  std::map<std::string, double> bounds;
  for (std::size_t m = 0; m < file.json["meshes"].size(); ++m) {
    const std::vector<test::GltfTriangle> triangles = test::mesh_triangles(file, m);
    double largest = 0.0;
    for (const test::GltfTriangle& t : triangles) {
      for (const glm::dvec3& p : t) {
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
      }
    }
    const double delta = std::sqrt(3.0) * std::ldexp(largest, -24);
    double bound = 0.0;
    for (const test::GltfTriangle& t : triangles) {
      const double perimeter =
          glm::length(t[1] - t[0]) + glm::length(t[2] - t[1]) + glm::length(t[0] - t[2]);
      bound += delta * perimeter / 2 + 3 * delta * delta;
    }
    const int material = file.json["meshes"][m]["primitives"][0]["material"];
    bounds[file.json["materials"][material]["name"]] += bound;
  }
  return bounds;
}

// Per material, the triangles' area against `expected`'s, every material written and every
// set with area drawn: within `tolerance` relative, or, where `tolerance` is negative,
// within the float rounding bound. Returns the worst relative error.
double ExpectMaterialAreas(GltfFile& file, const std::map<std::string, double>& expected,
                           double tolerance) {
  const std::map<std::string, double> areas = test::material_areas(file);
  const std::map<std::string, double> bounds = float_rounding_bounds(file);
  double worst = 0.0;
  for (const auto& [name, area] : expected) {
    if (area == 0.0) continue;
    const auto it = areas.find(name);
    if (it == areas.end()) {
      ADD_FAILURE() << "no mesh of material " << name;
      continue;
    }
    const double error = relative_error(it->second, area);
    worst = std::max(worst, error);
    if (tolerance >= 0.0) {
      EXPECT_LE(error, tolerance) << name << ": " << it->second << " vs " << area;
    } else {
      EXPECT_LE(std::abs(it->second - area), bounds.at(name))
          << name << ": " << it->second << " vs " << area;
    }
  }
  for (const auto& [name, area] : areas) {
    EXPECT_TRUE(expected.count(name) != 0) << "a mesh of material " << name << " not expected";
  }
  return worst;
}

std::vector<std::string> names_of(const nlohmann::json& array) {
  std::vector<std::string> names;
  for (const auto& item : array) names.push_back(item["name"]);
  return names;
}

// Ground 10 × 10 under a 4 × 4 square and two lights (hand_scenes.h): every vertex,
// shadow corners included, lies on whole numbers around the centre (5, 5, 0.5), which
// float32 holds exactly, so the triangles add up to the database's areas to the last bit.
TEST(GltfExport, MaterialAreasAreTheDatabasesPerLightSet) {
  const ShadowedScene s = generated(kTwoLights);
  const std::map<std::string, double> expected = light_set_areas(s);
  // "down" shades [2,6] × [3,7] on the ground, "slant" [3,7] × [3,7]: in shadow of both
  // [3,6] × [3,7], lit by "slant" alone [2,3] × [3,7], by "down" alone [6,7] × [3,7].
  EXPECT_NEAR(expected.at("shadow"), 12.0, 1e-12);
  EXPECT_NEAR(expected.at("slant"), 4.0, 1e-12);
  EXPECT_NEAR(expected.at("down"), 4.0, 1e-12);
  EXPECT_NEAR(expected.at("down+slant"), 100.0 - 20.0 + 16.0, 1e-12);
  for (const GltfForm form : kForms) {
    GltfFile file = read_back(gltf_export(s, form), form);
    EXPECT_LE(ExpectMaterialAreas(file, expected, 1e-9), 1e-9);
    EXPECT_EQ(names_of(file.json["materials"]),
              (std::vector<std::string>{"shadow", "down", "slant", "down+slant"}));
    EXPECT_EQ(names_of(file.json["nodes"]),
              (std::vector<std::string>{"shadowgen", "shadow", "down", "slant", "down+slant"}));
    EXPECT_EQ(file.json["nodes"][0]["children"], nlohmann::json({1, 2, 3, 4}));
    EXPECT_EQ(file.json["scenes"][0]["nodes"], nlohmann::json({0}));
    EXPECT_EQ(file.json["extensionsUsed"], nlohmann::json({"KHR_materials_unlit"}));
    EXPECT_FALSE(file.json.contains("extensionsRequired"));
  }
}

// Component c of a material's baseColorFactor, 1 where it is left out (glTF's default).
double base_colour(const nlohmann::json& material, int c) {
  const nlohmann::json& pbr = material["pbrMetallicRoughness"];
  return pbr.contains("baseColorFactor") ? pbr["baseColorFactor"][c].get<double>() : 1.0;
}

// Colours: the MTL's (light_set_colour), sRGB, as glTF's linear factors; two-sided, unlit.
TEST(GltfExport, MaterialsAreTheMtlColoursTwoSidedAndUnlit) {
  const ShadowedScene s = generated(kTwoLights);
  GltfFile file = read_back(gltf_export(s, GltfForm::kBinary), GltfForm::kBinary);
  const std::vector<std::vector<std::size_t>> sets = {{}, {0}, {1}, {0, 1}};
  ASSERT_EQ(file.json["materials"].size(), sets.size());
  for (std::size_t m = 0; m < sets.size(); ++m) {
    const nlohmann::json& material = file.json["materials"][m];
    const glm::dvec3 srgb = light_set_colour(s.scene(), sets[m]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(base_colour(material, c), linear(srgb[c]));
    EXPECT_EQ(base_colour(material, 3), 1.0);
    EXPECT_EQ(material["pbrMetallicRoughness"]["metallicFactor"], 0.0);
    EXPECT_EQ(material["doubleSided"], true);
    EXPECT_TRUE(material["extensions"].contains("KHR_materials_unlit"));
  }
  // The shadow is grey 0.2 (sRGB); the region both lights reach white.
  EXPECT_EQ(base_colour(file.json["materials"][0], 0), linear(0.2));
  EXPECT_EQ(base_colour(file.json["materials"][3], 0), 1.0);
  EXPECT_EQ(file.json["materials"][0]["extras"]["lights"], nlohmann::json::array());
  EXPECT_EQ(file.json["materials"][1]["extras"]["lights"], nlohmann::json({"down"}));
  EXPECT_EQ(file.json["materials"][3]["extras"]["lights"], nlohmann::json({"down", "slant"}));
}

// Faces and pieces in the extras: every face with its area and lit area; each mesh's
// pieces name their face, their first triangle and their area.
TEST(GltfExport, ExtrasListFacesAndEachMeshsPieces) {
  const ShadowedScene s = generated(kTwoLights);
  GltfFile file = read_back(gltf_export(s, GltfForm::kText), GltfForm::kText);
  const nlohmann::json& extras = file.json["scenes"][0]["extras"];
  EXPECT_EQ(extras["shadowgen"], "light sets");
  EXPECT_EQ(extras["origin"], nlohmann::json({5.0, 5.0, 0.5}));
  EXPECT_FALSE(extras.contains("site"));
  EXPECT_EQ(extras["lights"], nlohmann::json({"down", "slant"}));
  EXPECT_EQ(extras["faces"]["id"], nlohmann::json({"ground", "square"}));
  EXPECT_EQ(extras["faces"]["area"], nlohmann::json({100.0, 16.0}));
  EXPECT_NEAR(extras["faces"]["lit_area"][0].get<double>(), 88.0, 1e-12);
  EXPECT_EQ(extras["faces"]["lit_area"][1], 16.0);
  // Mesh "shadow" holds the ground's region alone; "down+slant" the ground's, then the
  // square's.
  const nlohmann::json& shadow = file.json["meshes"][0];
  EXPECT_EQ(file.json["nodes"][1]["name"], "shadow");
  EXPECT_EQ(file.json["nodes"][1]["mesh"], 0);
  EXPECT_EQ(shadow["extras"]["pieces"]["face"], nlohmann::json({0}));
  EXPECT_EQ(shadow["extras"]["pieces"]["first_triangle"], nlohmann::json({0}));
  EXPECT_NEAR(shadow["extras"]["pieces"]["area"][0].get<double>(), 12.0, 1e-12);
  EXPECT_FALSE(shadow["extras"]["pieces"].contains("hours"));
  const nlohmann::json& both = file.json["meshes"][3]["extras"]["pieces"];
  EXPECT_EQ(both["face"], nlohmann::json({0, 1}));
  EXPECT_NEAR(both["area"][0].get<double>(), 80.0, 1e-12);
  EXPECT_EQ(both["area"][1], 16.0);
  // The square's triangles are those from its first on: area 16.
  const std::vector<test::GltfTriangle> triangles = test::mesh_triangles(file, 3);
  double square = 0.0;
  for (std::size_t t = both["first_triangle"][1]; t < triangles.size(); ++t) {
    square += test::triangle_area(triangles[t]);
  }
  EXPECT_EQ(square, 16.0);
}

// What a page asks for beyond the export (GltfOptions): each vertex's face as _FACE, and the
// faces' outlines as a mesh of lines after the materials'; neither unless asked.
TEST(GltfExport, TheFaceAttributeAndTheOutlinesAreWrittenWhenAsked) {
  const ShadowedScene s = generated(kTwoLights);
  GltfFile plain = read_back(gltf_export(s, GltfForm::kBinary), GltfForm::kBinary);
  ASSERT_EQ(plain.json["meshes"].size(), 4u);
  for (const nlohmann::json& mesh : plain.json["meshes"]) {
    EXPECT_FALSE(mesh["primitives"][0]["attributes"].contains("_FACE"));
  }
  for (const GltfForm form : kForms) {
    const LightSetGltf made = light_set_gltf(s, form, {.face_attribute = true, .outlines = true});
    GltfFile file = read_back(made.bytes, form);
    // The materials, listed with their light sets: shadow, down, slant, down+slant.
    ASSERT_EQ(made.materials.size(), 4u);
    EXPECT_EQ(made.materials[3].lights, (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(made.materials[3].name, "down+slant");
    ASSERT_EQ(file.json["meshes"].size(), 5u);
    // Mesh "down+slant" holds the ground's region, then the square's: each vertex names
    // its face, those of the square's triangles face 1.
    const std::vector<double> faces = test::mesh_scalars(file, 3, "_FACE");
    const std::vector<test::GltfTriangle> triangles = test::mesh_triangles(file, 3);
    EXPECT_EQ(std::set<double>(faces.begin(), faces.end()), (std::set<double>{0.0, 1.0}));
    EXPECT_EQ(
        faces.size(),
        file.json["accessors"][file.json["meshes"][3]["primitives"][0]["attributes"]["POSITION"]
                                   .get<int>()]["count"]
            .get<std::size_t>());
    // The outlines: the ground's and the square's four edges each, in glTF's axes around
    // the root at the centre (5, 5, 0.5): the ground's corner (0, 0, 0) is (−5, −0.5, 5).
    EXPECT_EQ(file.json["nodes"].back()["name"], "outlines");
    EXPECT_FALSE(file.json["meshes"][4]["primitives"][0].contains("material"));
    const std::vector<std::array<glm::dvec3, 2>> lines = test::mesh_lines(file, 4);
    ASSERT_EQ(lines.size(), 8u);
    EXPECT_EQ(lines[0][0], glm::dvec3(-5.0, -0.5, 5.0));
    EXPECT_EQ(test::mesh_translation(file, 4), glm::dvec3(5.0, 0.5, -5.0));
    // The materials' areas are those of the plain file.
    EXPECT_EQ(test::material_areas(file), test::material_areas(plain));
    EXPECT_TRUE(file.errors.empty()) << file.errors.front();
  }
}

// The scene's (x, y, z) is glTF's (x, z, −y): a wall in the plane y = 0 facing −y, from
// (0, 0, 0) to (4, 0, 2), stands in glTF in the plane z = 0 facing +z, from (0, 0, 0) to
// (4, 2, 0); the root node stands at the centre (2, 0, 1), in glTF (2, 1, 0).
TEST(GltfExport, SceneZUpIsGltfYUp) {
  const ShadowedScene s = generated(R"({
    "format": "shadowgen-scene/1",
    "polygons": [{"id": "wall", "outer": [[0,0,0],[4,0,0],[4,0,2],[0,0,2]]}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,1,0]}]
  })");
  for (const GltfForm form : kForms) {
    GltfFile file = read_back(gltf_export(s, form), form);
    ASSERT_EQ(file.json["meshes"].size(), 1u);
    EXPECT_EQ(file.json["materials"][0]["name"], "sun");
    EXPECT_EQ(file.json["nodes"][0]["translation"], nlohmann::json({2.0, 1.0, -0.0}));
    EXPECT_EQ(test::mesh_translation(file, 0), glm::dvec3(2, 1, 0));
    std::set<std::tuple<double, double, double>> corners;
    for (const test::GltfTriangle& t : test::mesh_triangles(file, 0)) {
      for (const glm::dvec3& p : t) {
        const glm::dvec3 q = p + test::mesh_translation(file, 0);
        corners.insert({q.x, q.y, q.z});
      }
      // Counter-clockwise seen from +z, the front.
      EXPECT_GT(glm::cross(t[1] - t[0], t[2] - t[0]).z, 0.0);
    }
    EXPECT_EQ(corners, (std::set<std::tuple<double, double, double>>{
                           {0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {0, 2, 0}}));
    // No NORMAL: a viewer takes the flat normal of each triangle's winding, here +z.
    EXPECT_EQ(file.json["meshes"][0]["primitives"][0]["attributes"],
              nlohmann::json({{"POSITION", 0}}));
    const auto& accessor = file.json["accessors"][0];
    EXPECT_EQ(accessor["min"], nlohmann::json({-2.0, -1.0, 0.0}));
    EXPECT_EQ(accessor["max"], nlohmann::json({2.0, 1.0, 0.0}));
  }
}

// A district of 96 faces at Dutch national grid coordinates (85000, 447000): float32
// spaces numbers 0.03 apart there, but positions are relative to the root node, so every
// light set keeps its area within the float rounding bound and 1e-6 relative.
TEST(GltfExport, DistrictAtProjectedCoordinatesKeepsItsAreas) {
  Scene city = bench::city_scene({4, 20.0, 1});
  const glm::dvec3 offset(85000.0, 447000.0, 0.0);
  for (Face& face : city.faces) {
    for (hsr::Polygon3& part : face.parts) {
      for (glm::dvec3& p : part.outer) p += offset;
      for (hsr::Loop3& hole : part.holes) {
        for (glm::dvec3& p : hole) p += offset;
      }
    }
  }
  for (Light& light : city.lights) light.position += offset;
  const ShadowedScene s = generate_shadows(city, {}).shadowed;
  const std::map<std::string, double> expected = light_set_areas(s);
  ASSERT_GE(expected.size(), 2u);
  GltfFile file = read_back(gltf_export(s, GltfForm::kBinary), GltfForm::kBinary);
  const double worst = ExpectMaterialAreas(file, expected, -1.0);
  EXPECT_LE(worst, 1e-6);
  const nlohmann::json& origin = file.json["scenes"][0]["extras"]["origin"];
  EXPECT_NEAR(origin[0].get<double>(), 85040.0, 40.0);
  EXPECT_NEAR(origin[1].get<double>(), 447040.0, 40.0);
  EXPECT_EQ(file.json["nodes"][0]["translation"][2], -origin[1].get<double>());
}

// The sun-hours regions by hand (hand_scenes.h): face "g" has 0 h on [0,1], 1.5 h on
// [1,3] in two pieces, 2 h on [3,4]; the default bands of four 30-minute instants are
// 0–0.5, ..., ≥ 2 h.
TEST(GltfExport, SunHoursBandsAreMaterialsWithThePiecesHours) {
  const ShadowedScene s = test::sun_path_by_hand();
  const SunPathHours& path = s.sun_paths.front();
  const HourBands bands = hour_bands(path);
  for (const GltfForm form : kForms) {
    GltfFile file = read_back(sun_hours_gltf_export(s, path, bands, form), form);
    std::vector<std::string> band_names;
    for (const HourBand& band : bands.bands) band_names.push_back(band.name);
    EXPECT_EQ(names_of(file.json["materials"]), band_names);
    const std::string zero = bands.bands[bands.band_of(0.0)].name;
    const std::string middle = bands.bands[bands.band_of(1.5)].name;
    const std::string most = bands.bands[bands.band_of(2.0)].name;
    ExpectMaterialAreas(file, {{zero, 1.0}, {middle, 2.0}, {most, 1.0}}, 1e-9);
    EXPECT_EQ(names_of(file.json["nodes"]),
              (std::vector<std::string>{"shadowgen", zero, middle, most}));
    // The 1.5 h region is one piece of two polygons.
    const nlohmann::json& pieces = file.json["meshes"][1]["extras"]["pieces"];
    EXPECT_EQ(pieces["face"], nlohmann::json({0}));
    EXPECT_EQ(pieces["first_triangle"], nlohmann::json({0}));
    EXPECT_EQ(pieces["area"], nlohmann::json({2.0}));
    EXPECT_EQ(pieces["hours"], nlohmann::json({1.5}));
    const HourBand& band = bands.bands[bands.band_of(1.5)];
    const nlohmann::json& material = file.json["materials"][bands.band_of(1.5)];
    EXPECT_EQ(material["extras"]["label"], band.label);
    EXPECT_EQ(material["extras"]["from"], band.from);
    const nlohmann::json& extras = file.json["scenes"][0]["extras"];
    EXPECT_EQ(extras["shadowgen"], "sun hours");
    EXPECT_EQ(extras["sun_path"]["id"], "p");
    EXPECT_EQ(extras["sun_path"]["instants"], 4);
    EXPECT_EQ(extras["sun_path"]["most_hours"], 2.0);
    EXPECT_EQ(extras["faces"]["id"], nlohmann::json({"g"}));
    EXPECT_FALSE(extras["faces"].contains("lit_area"));
    // The colour is the band's, the SVG legend's and the MTL's.
    EXPECT_EQ(base_colour(material, 1), linear(band.colour.g));
  }
}

// A courtyard at London over 21 March: the site in the extras, and each band's triangles
// within float32's rounding of the database's sun-hours regions.
TEST(GltfExport, CourtyardSunHoursKeepTheSiteAndTheBandsAreas) {
  const ShadowedScene s = generated(test::site_scene(test::kCourtyard, test::kMarch21));
  const SunPathHours& path = s.sun_paths.front();
  const HourBands bands = hour_bands(path);
  std::map<std::string, double> expected;
  for (const auto& regions : path.regions) {
    for (const SunHoursRegion& r : regions) {
      expected[bands.bands[bands.band_of(r.hours)].name] += lit_area(r.polygons);
    }
  }
  for (const GltfForm form : kForms) {
    GltfFile file = read_back(sun_hours_gltf_export(s, path, bands, form), form);
    EXPECT_LE(ExpectMaterialAreas(file, expected, -1.0), 1e-6);
    const nlohmann::json& site = file.json["scenes"][0]["extras"]["site"];
    EXPECT_EQ(site["latitude_deg"], 51.5);
    EXPECT_EQ(site["longitude_deg"], -0.1);
    EXPECT_EQ(site["north_axis_deg"], 0.0);
  }
}

// A face id that is not UTF-8 (a mesh file's group name may hold any byte) is written
// with U+FFFD in place of the bad byte: glTF's JSON is UTF-8, and the export goes on.
TEST(GltfExport, AFaceIdThatIsNotUtf8IsWrittenWithReplacementCharacters) {
  ShadowedScene s = generated(kTwoLights);
  s.edit_face(0, [&](Face& face) { face.id = "ground\xff"; });
  for (const GltfForm form : kForms) {
    GltfFile file = read_back(gltf_export(s, form), form);
    EXPECT_EQ(file.json["scenes"][0]["extras"]["faces"]["id"][0], "ground\xef\xbf\xbd");
  }
}

TEST(GltfExport, ASceneWithoutFacesIsStillAFile) {
  Scene empty;
  empty.file = "empty.json";
  const ShadowedScene s(empty, LitTable());
  GltfFile file = read_back(gltf_export(s, GltfForm::kBinary), GltfForm::kBinary);
  EXPECT_FALSE(file.json.contains("meshes"));
  EXPECT_FALSE(file.json.contains("buffers"));
  EXPECT_EQ(file.json["scenes"][0]["extras"]["faces"]["id"], nlohmann::json::array());
}

TEST(GltfExport, AnAreasOnlyPathIsRefusedNamingTheFile) {
  ShadowedScene s = test::sun_path_by_hand();
  s.sun_paths.front().regions_kept = false;
  const HourBands bands = hour_bands(s.sun_paths.front());
  try {
    sun_hours_gltf_export(s, s.sun_paths.front(), bands, GltfForm::kBinary);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test.json"), std::string::npos) << e.what();
  }
}

TEST(GltfExport, FormOfAFileName) {
  EXPECT_EQ(gltf_form_of("a/b.glb"), GltfForm::kBinary);
  EXPECT_EQ(gltf_form_of("B.GLB"), GltfForm::kBinary);
  EXPECT_EQ(gltf_form_of("model.gltf"), GltfForm::kText);
  EXPECT_EQ(gltf_form_of("model.glTF"), GltfForm::kText);
  EXPECT_EQ(gltf_form_of("model.obj"), std::nullopt);
  EXPECT_EQ(gltf_form_of("glb"), std::nullopt);
  EXPECT_EQ(gltf_form_of(""), std::nullopt);
}

}  // namespace
}  // namespace shadowgen
