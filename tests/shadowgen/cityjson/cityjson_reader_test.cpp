// Tests of shadowgen/cityjson/cityjson_reader.h on files written here from the CityJSON
// 2.0 specification (https://www.cityjson.org/specs/2.0.1/) and its 1.0 version: placement
// by the transform, the level of detail chosen, children, solids with interior shells,
// multi-solids, geometry templates, holes, semantic types, ids, a 1.0 file, a CityJSONSeq
// file against its CityJSON twin, the site from the CRS, and the messages bad input gets.

#include "shadowgen/cityjson/cityjson_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/scene/scene_reader.h"
#include "tests/support/temp_folder.h"

namespace shadowgen::cityjson {
namespace {

const test::TempFolder& folder() {
  static const test::TempFolder f("shadowgen-cityjson");
  return f;
}

// The path of `name` in the test folder, written with `text`.
std::string write(const std::string& name, const std::string& text) {
  return folder().write(name, text).string();
}

SourceModel read(const std::string& name, const std::string& text, SourceOptions options = {}) {
  return read_cityjson(write(name, text), options);
}

// What read_cityjson throws, as the command line prints it.
std::string error_of(const std::string& name, const std::string& text, SourceOptions options = {}) {
  try {
    read(name, text, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A CityJSON 2.0 file: `objects` is the CityObjects member's content, `vertices` the
// vertices' (integers), `more` further top-level members (each followed by a comma).
std::string city_json(const std::string& objects, const std::string& vertices,
                      const std::string& more = "") {
  return R"({"type": "CityJSON", "version": "2.0",
  "transform": {"scale": [0.5, 0.5, 0.25], "translate": [155000, 463000, 10]},)" +
         more + R"(
  "CityObjects": {)" +
         objects + R"(},
  "vertices": [)" +
         vertices + "]}";
}

// A cube 2 × 2 × 4 (integer steps of the transform above: 0.5, 0.5, 0.25 apart) whose
// corners are vertices `first` to `first + 7`: 0..3 the bottom counter-clockwise seen from
// above, 4..7 the top.
std::string cube_vertices(int x, int y, int z) {
  std::string out;
  const int corners[8][3] = {{0, 0, 0},  {4, 0, 0},  {4, 4, 0},  {0, 4, 0},
                             {0, 0, 16}, {4, 0, 16}, {4, 4, 16}, {0, 4, 16}};
  for (const auto& c : corners) {
    out += out.empty() ? "[" : ", [";
    out += std::to_string(x + c[0]);
    out += ", ";
    out += std::to_string(y + c[1]);
    out += ", ";
    out += std::to_string(z + c[2]);
    out += ']';
  }
  return out;
}

// The six surfaces of the cube on vertices first..first+7, each counter-clockwise seen
// from outside: bottom, top, front (y low), right (x high), back, left.
std::string cube_shell(int first, bool inward = false) {
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::string out = "[";
  for (int f = 0; f < 6; ++f) {
    out += f ? ", [[" : "[[";
    for (int v = 0; v < 4; ++v) {
      const int i = inward ? faces[f][3 - v] : faces[f][v];
      out += (v ? ", " : "") + std::to_string(first + i);
    }
    out += "]]";
  }
  return out + "]";
}

const SourceFace& face(const SourceModel& model, const std::string& id) {
  for (const SourceFace& f : model.faces) {
    if (f.id == id) return f;
  }
  throw std::runtime_error("no face " + id);
}

std::vector<std::string> ids(const SourceModel& model) {
  std::vector<std::string> out;
  for (const SourceFace& f : model.faces) out.push_back(f.id);
  return out;
}

glm::dvec3 newell(const hsr::Loop3& loop) {
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < loop.size(); ++i)
    n += glm::cross(loop[i], loop[(i + 1) % loop.size()]);
  return n;
}

glm::dvec3 centroid(const hsr::Loop3& loop) {
  glm::dvec3 c(0.0);
  for (const glm::dvec3& p : loop) c += p;
  return c / static_cast<double>(loop.size());
}

// ---- Placement, ids, orientation -------------------------------------------------------

TEST(CityJsonReader, ATransformPlacesEachVertexAtScaleTimesItPlusTranslate) {
  const SourceModel model =
      read("transform.city.json", city_json(R"("b1": {"type": "Building", "geometry": [
                {"type": "Solid", "lod": "1", "boundaries": [)" +
                                                cube_shell(0) + "]}]}",
                                            cube_vertices(2, 4, 8)));
  ASSERT_EQ(model.faces.size(), 6u);
  EXPECT_EQ(ids(model), (std::vector<std::string>{"b1/0", "b1/1", "b1/2", "b1/3", "b1/4", "b1/5"}));
  // The top, vertices 4, 5, 6, 7: integers (2, 4, 24), (6, 4, 24), (6, 8, 24), (2, 8, 24)
  // scaled by (0.5, 0.5, 0.25) and moved by (155000, 463000, 10): real projected
  // coordinates, not re-centred.
  const SourceFace& top = face(model, "b1/1");
  EXPECT_EQ(
      top.polygon.outer,
      (hsr::Loop3{
          {155001, 463002, 16}, {155003, 463002, 16}, {155003, 463004, 16}, {155001, 463004, 16}}));
  EXPECT_TRUE(top.polygon.holes.empty());
  // Half a step per axis: |(0.5, 0.5, 0.25)| / 2.
  EXPECT_EQ(top.vertex_rounding, 0.375);
  EXPECT_EQ(top.origin, (FaceOrigin{"cityjson", "b1", "b1", ""}));
  EXPECT_EQ(top.described, "object 'b1' surface 1");
  EXPECT_EQ(top.line, 0u);
  // Every outer loop runs counter-clockwise seen from outside: the front side is out.
  const glm::dvec3 middle(155002, 463003, 14);
  for (const SourceFace& f : model.faces) {
    SCOPED_TRACE(f.id);
    EXPECT_GT(glm::dot(newell(f.polygon.outer), centroid(f.polygon.outer) - middle), 0.0);
  }
  EXPECT_TRUE(model.site.empty());
  EXPECT_TRUE(model.warnings.empty());
}

TEST(CityJsonReader, AMillimetreScaleGivesAVertexRoundingOfHalfItsDiagonal) {
  const SourceModel model = read("mm.city.json", R"({"type": "CityJSON", "version": "2.0",
    "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0, 0, 0]},
    "CityObjects": {"w": {"type": "GenericCityObject", "geometry": [
      {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}]}},
    "vertices": [[0, 0, 0], [1000, 0, 0], [0, 1000, 0]]})");
  ASSERT_EQ(model.faces.size(), 1u);
  EXPECT_DOUBLE_EQ(model.faces[0].vertex_rounding, 0.5 * std::sqrt(3.0) * 0.001);
}

TEST(CityJsonReader, TheHighestLevelOfDetailIsTakenUnlessOneIsAsked) {
  // Three geometries of "b": an LoD1 Solid (6 surfaces), two LoD2.2 MultiSurfaces (1 and 2
  // surfaces) and an LoD2 MultiSurface (1). The highest, 2.2, gives both its geometries'
  // surfaces, numbered on across them in file order.
  const std::string text = city_json(R"("b": {"type": "Building", "geometry": [
      {"type": "Solid", "lod": "1", "boundaries": [)" +
                                         cube_shell(0) + R"(]},
      {"type": "MultiSurface", "lod": "2.2", "boundaries": [[[4, 5, 6, 7]]]},
      {"type": "MultiSurface", "lod": "2", "boundaries": [[[0, 1, 5, 4]]]},
      {"type": "MultiSurface", "lod": "2.2", "boundaries": [[[0, 1, 5, 4]], [[1, 2, 6, 5]]]}
    ]})",
                                     cube_vertices(0, 0, 0));
  const SourceModel highest = read("lods.city.json", text);
  EXPECT_EQ(ids(highest), (std::vector<std::string>{"b/0", "b/1", "b/2"}));
  EXPECT_EQ(face(highest, "b/0").polygon.outer[0], glm::dvec3(155000, 463000, 14));  // vertex 4
  EXPECT_EQ(face(highest, "b/2").polygon.outer[0], glm::dvec3(155002, 463000, 10));  // vertex 1

  const SourceModel lod1 = read("lods.city.json", text, {.lod = "1"});
  EXPECT_EQ(lod1.faces.size(), 6u);
  const SourceModel lod2 = read("lods.city.json", text, {.lod = "2"});
  EXPECT_EQ(ids(lod2), (std::vector<std::string>{"b/0"}));
  EXPECT_EQ(
      error_of("lods.city.json", text, {.lod = "3"}),
      write("lods.city.json", text) + ": no geometry has lod '3' (the file's levels: 1, 2, 2.2)");
}

TEST(CityJsonReader, AnObjectWithoutTheLevelAskedGivesNoFacesAndAWarning) {
  const std::string text = city_json(R"(
      "a": {"type": "Building", "geometry": [
        {"type": "MultiSurface", "lod": "2.2", "boundaries": [[[0, 1, 2]]]}]},
      "t": {"type": "SolitaryVegetationObject", "geometry": [
        {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}]})",
                                     "[0, 0, 0], [2, 0, 0], [0, 2, 0]");
  const SourceModel model = read("missing-lod.city.json", text, {.lod = "2.2"});
  EXPECT_EQ(ids(model), (std::vector<std::string>{"a/0"}));
  EXPECT_EQ(model.warnings,
            (std::vector<std::string>{
                write("missing-lod.city.json", text) +
                ": 1 city object has no geometry of lod '2.2' and gives no faces: t"}));
}

TEST(CityJsonReader, ABuildingPartGivesItsOwnFacesGroupedUnderItsBuilding) {
  // "b" has no geometry of its own; its part "b-p" and the part's installation "b-p-i"
  // (a child of a child) hold it. Each face names the object that holds it, and the top
  // of its parents as its group.
  const SourceModel model = read("parts.city.json", city_json(R"(
      "b": {"type": "Building", "children": ["b-p"], "attributes": {"roofType": "gabled"}},
      "b-p": {"type": "BuildingPart", "parents": ["b"], "children": ["b-p-i"], "geometry": [
        {"type": "MultiSurface", "lod": "2", "boundaries": [[[0, 1, 2]], [[0, 2, 3]]]}]},
      "b-p-i": {"type": "BuildingInstallation", "parents": ["b-p"], "geometry": [
        {"type": "MultiSurface", "lod": "2", "boundaries": [[[0, 1, 3]]]}]})",
                                                              cube_vertices(0, 0, 0)));
  EXPECT_EQ(ids(model), (std::vector<std::string>{"b-p/0", "b-p/1", "b-p-i/0"}));
  EXPECT_EQ(face(model, "b-p/1").origin, (FaceOrigin{"cityjson", "b-p", "b", ""}));
  EXPECT_EQ(face(model, "b-p-i/0").origin, (FaceOrigin{"cityjson", "b-p-i", "b", ""}));
  EXPECT_TRUE(model.warnings.empty());
}

TEST(CityJsonReader, ASolidsInteriorShellKeepsItsSurfacesAsWritten) {
  // A cube with a cubic cavity: the interior shell's surfaces face into the cavity
  // (CityJSON orients a shell's surfaces away from the solid's material), and so do the
  // faces: numbered on after the exterior shell's.
  const SourceModel model =
      read("cavity.city.json", city_json(R"("c": {"type": "Building", "geometry": [
        {"type": "Solid", "lod": "1", "boundaries": [)" +
                                             cube_shell(0) + ", " + cube_shell(8, true) + "]}]}",
                                         cube_vertices(0, 0, 0) + ", " +
                                             "[1, 1, 4], [3, 1, 4], [3, 3, 4], [1, 3, 4], " +
                                             "[1, 1, 12], [3, 1, 12], [3, 3, 12], [1, 3, 12]"));
  ASSERT_EQ(model.faces.size(), 12u);
  EXPECT_EQ(model.faces[11].id, "c/11");
  // Inner top (face 7, vertices 15, 14, 13, 12): at z 10 + 12 × 0.25 = 13, facing down.
  const SourceFace& inner_top = face(model, "c/7");
  EXPECT_EQ(inner_top.polygon.outer, (hsr::Loop3{{155000.5, 463001.5, 13},
                                                 {155001.5, 463001.5, 13},
                                                 {155001.5, 463000.5, 13},
                                                 {155000.5, 463000.5, 13}}));
  EXPECT_LT(newell(inner_top.polygon.outer).z, 0.0);
}

TEST(CityJsonReader, AMultiSolidsSurfacesAreNumberedOnAcrossItsSolids) {
  const SourceModel model = read(
      "multisolid.city.json", city_json(R"("m": {"type": "Building", "geometry": [
        {"type": "MultiSolid", "lod": "1", "boundaries": [[)" +
                                            cube_shell(0) + "], [" + cube_shell(8) + "]]}]}",
                                        cube_vertices(0, 0, 0) + ", " + cube_vertices(10, 0, 0)));
  ASSERT_EQ(model.faces.size(), 12u);
  // Surface 1 of the second solid (its top) is face 7; its first corner is vertex 12,
  // integer (10, 0, 16).
  EXPECT_EQ(face(model, "m/7").polygon.outer[0], glm::dvec3(155005, 463000, 14));
}

TEST(CityJsonReader, HolesAreTheRingsAfterTheFirst) {
  // A wall 4 × 4 with a window 2 × 2 (CityJSON 2.0, "Geometry Objects": a surface is its
  // exterior ring, then its interior rings).
  const SourceModel model = read("hole.city.json", city_json(R"("w": {"type": "Building",
      "geometry": [{"type": "MultiSurface", "lod": "2",
        "boundaries": [[[0, 1, 2, 3], [4, 7, 6, 5]]]}]})",
                                                             "[0, 0, 0], [8, 0, 0], [8, 0, 16], "
                                                             "[0, 0, 16], [2, 0, 4], [6, 0, 4], "
                                                             "[6, 0, 12], [2, 0, 12]"));
  ASSERT_EQ(model.faces.size(), 1u);
  const hsr::Polygon3& p = model.faces[0].polygon;
  EXPECT_EQ(p.outer.size(), 4u);
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_EQ(
      p.holes[0],
      (hsr::Loop3{
          {155001, 463000, 11}, {155001, 463000, 13}, {155003, 463000, 13}, {155003, 463000, 11}}));
}

TEST(CityJsonReader, SemanticSurfaceTypesGoWithTheirFaces) {
  // CityJSON 2.0, "Semantics of geometric primitives": "values" nests as the boundaries,
  // one index (or null) per surface; null in place of a shell's array stands for none in
  // that shell.
  const SourceModel model = read("semantics.city.json", city_json(R"("s": {"type": "Building",
      "geometry": [{"type": "Solid", "lod": "2", "boundaries": [)" + cube_shell(0) +
                                                                      R"(],
        "semantics": {
          "surfaces": [{"type": "GroundSurface"}, {"type": "RoofSurface", "slope": 0},
                       {"type": "WallSurface", "parent": 1, "+colour": "red"}],
          "values": [[0, 1, 2, 2, null, 2]]}}]})",
                                                                  cube_vertices(0, 0, 0)));
  ASSERT_EQ(model.faces.size(), 6u);
  const std::vector<std::string> expected = {
      "GroundSurface", "RoofSurface", "WallSurface", "WallSurface", "", "WallSurface"};
  for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(model.faces[k].origin.semantic, expected[k]);
  EXPECT_TRUE(model.warnings.empty());
}

TEST(CityJsonReader, AGeometryInstancePlacesItsTemplateByItsMatrixAtItsReferencePoint) {
  // A tree template (CityJSON 2.0, "Geometry templates"): two crossed triangles in
  // vertices-templates, real coordinates the transform does not touch. The instance's
  // matrix (row-major) doubles x and y, keeps z, and moves by (1, 0, 0); its reference
  // point is vertex 1 of the file, integer (4, 2, 0), real (155002, 463001, 10).
  const SourceModel model = read("tree.city.json", city_json(R"(
      "t": {"type": "SolitaryVegetationObject", "geometry": [
        {"type": "GeometryInstance", "template": 1, "boundaries": [1],
         "transformationMatrix": [2, 0, 0, 1,  0, 2, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1]}]})",
                                                             "[0, 0, 0], [4, 2, 0]",
                                                             R"(
  "geometry-templates": {
    "templates": [
      {"type": "MultiPoint", "lod": "0", "boundaries": [0]},
      {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]], [[3, 4, 2]]],
       "semantics": {"surfaces": [{"type": "+Crown"}], "values": [0, null]}}],
    "vertices-templates": [[-1.5, 0, 0], [1.5, 0, 0], [0, 0, 8.25], [0, -1.5, 0], [0, 1.5, 0]]},)"));
  ASSERT_EQ(model.faces.size(), 2u);
  EXPECT_EQ(model.faces[0].id, "t/0");
  // (-1.5, 0, 0) → (2 × -1.5 + 1, 0, 0) + (155002, 463001, 10) = (155000, 463001, 10).
  EXPECT_EQ(model.faces[0].polygon.outer,
            (hsr::Loop3{{155000, 463001, 10}, {155006, 463001, 10}, {155003, 463001, 18.25}}));
  EXPECT_EQ(model.faces[1].polygon.outer[0], glm::dvec3(155003, 462998, 10));
  EXPECT_EQ(model.faces[0].origin, (FaceOrigin{"cityjson", "t", "t", "+Crown"}));
  EXPECT_EQ(model.faces[1].origin.semantic, "");
  // The reference point's rounding (0.375) plus the template's (2 decimals written: half
  // of 0.01 on each axis) as the matrix moves it: 0.01 on x and y, 0.005 on z.
  EXPECT_DOUBLE_EQ(model.faces[0].vertex_rounding,
                   0.375 + std::sqrt(2 * 0.01 * 0.01 + 0.005 * 0.005));
}

// ---- CityJSON 1.0 and CityJSONSeq ------------------------------------------------------

TEST(CityJsonReader, AVersion1FileWithNumberLodsAndNoTransform) {
  // CityJSON 1.0: "lod" is a number, the transform optional (vertices then real numbers
  // as written, here to 3 decimals: a rounding of √3 × 0.0005), the CRS an OGC URN.
  const std::string text = R"({"type": "CityJSON", "version": "1.0",
    "metadata": {"referenceSystem": "urn:ogc:def:crs:EPSG::7415", "datasetTitle": "test"},
    "CityObjects": {"b": {"type": "Building", "geometry": [
      {"type": "MultiSurface", "lod": 2, "boundaries": [[[0, 1, 2]]]},
      {"type": "MultiSurface", "lod": 2.2, "boundaries": [[[0, 1, 2]], [[0, 2, 3]]]}]}},
    "vertices": [[154999.5, 462999.5, 0.125], [155000.5, 462999.5, 0], [155000.5, 463000.5, 0],
                 [154999.5, 463000.5, 0]]})";
  const SourceModel model = read("v1.city.json", text);
  EXPECT_EQ(ids(model), (std::vector<std::string>{"b/0", "b/1"}));
  EXPECT_EQ(model.faces[0].polygon.outer[0], glm::dvec3(154999.5, 462999.5, 0.125));
  EXPECT_DOUBLE_EQ(model.faces[0].vertex_rounding, std::sqrt(3.0) * 0.0005);
  EXPECT_EQ(read("v1.city.json", text, {.lod = "2"}).faces.size(), 1u);
  EXPECT_EQ(read("v1.city.json", text, {.lod = "2.2"}).faces.size(), 2u);
  // The middle of the vertices' box is the RD origin.
  EXPECT_EQ(model.site.from, "EPSG:7415 through PROJ at (155000, 463000)");
  EXPECT_NEAR(*model.site.latitude_deg, 52.156160556, 1e-8);
  EXPECT_NEAR(*model.site.longitude_deg, 5.387638889, 1e-8);
  EXPECT_NEAR(*model.site.north_axis_deg, 0.0, 1e-8);
}

TEST(CityJsonReader, ACityJsonSeqFileGivesTheFacesOfItsCityJsonTwin) {
  // The same two buildings (one with a part) and a tree, as one CityJSON file and as a
  // CityJSONSeq file: a header line with the transform, metadata and templates, then one
  // feature a line with its own vertices.
  const std::string templates = R"("geometry-templates": {"templates": [
      {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}],
      "vertices-templates": [[-1, 0, 0], [1, 0, 0], [0, 0, 6]]})";
  const std::string header =
      R"({"type": "CityJSON", "version": "2.0", "transform": {"scale": [0.5, 0.5, 0.25],
      "translate": [155000, 463000, 10]},
      "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"}, )" +
      templates + R"(, "CityObjects": {}, "vertices": []})";
  std::string seq;
  for (char c : header) seq += c == '\n' ? ' ' : c;
  seq += "\n";
  seq +=
      R"({"type": "CityJSONFeature", "id": "a", "CityObjects": {"a": {"type": "Building", "geometry": [{"type": "Solid", "lod": "1", "boundaries": [)" +
      cube_shell(0) + R"(]}]}}, "vertices": [)" + cube_vertices(0, 0, 0) + "]}\n";
  seq +=
      R"({"type": "CityJSONFeature", "id": "b", "CityObjects": {"b": {"type": "Building", "children": ["b1"]}, "b1": {"type": "BuildingPart", "parents": ["b"], "geometry": [{"type": "MultiSurface", "lod": "2", "boundaries": [[[1, 0, 2]]], "semantics": {"surfaces": [{"type": "RoofSurface"}], "values": [0]}}]}}, "vertices": [[0, 10, 0], [2, 12, 4], [0, 12, 4]]})"
      "\n\n";
  seq +=
      R"({"type": "CityJSONFeature", "id": "t", "CityObjects": {"t": {"type": "SolitaryVegetationObject", "geometry": [{"type": "GeometryInstance", "template": 0, "boundaries": [0], "transformationMatrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]}}, "vertices": [[20, 20, 0]]})"
      "\n";
  const std::string whole = R"({"type": "CityJSON", "version": "2.0",
    "transform": {"scale": [0.5, 0.5, 0.25], "translate": [155000, 463000, 10]},
    "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"}, )" +
                            templates + R"(,
    "CityObjects": {
      "a": {"type": "Building", "geometry": [{"type": "Solid", "lod": "1", "boundaries": [)" +
                            cube_shell(0) + R"(]}]},
      "b": {"type": "Building", "children": ["b1"]},
      "b1": {"type": "BuildingPart", "parents": ["b"], "geometry": [{"type": "MultiSurface",
        "lod": "2", "boundaries": [[[9, 8, 10]]],
        "semantics": {"surfaces": [{"type": "RoofSurface"}], "values": [0]}}]},
      "t": {"type": "SolitaryVegetationObject", "geometry": [{"type": "GeometryInstance",
        "template": 0, "boundaries": [11],
        "transformationMatrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]}},
    "vertices": [)" + cube_vertices(0, 0, 0) +
                            R"(, [0, 10, 0], [2, 12, 4], [0, 12, 4], [20, 20, 0]]})";

  const SourceModel from_seq = read("district.city.jsonl", seq);
  const SourceModel from_whole = read("district.city.json", whole);
  ASSERT_EQ(from_seq.faces.size(), 8u);
  ASSERT_EQ(from_whole.faces.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    SCOPED_TRACE(from_whole.faces[i].id);
    EXPECT_EQ(from_seq.faces[i].id, from_whole.faces[i].id);
    EXPECT_EQ(from_seq.faces[i].polygon.outer, from_whole.faces[i].polygon.outer);
    EXPECT_EQ(from_seq.faces[i].origin, from_whole.faces[i].origin);
    EXPECT_EQ(from_seq.faces[i].vertex_rounding, from_whole.faces[i].vertex_rounding);
  }
  // Each face of the sequence knows its line; the empty line 4 is passed over.
  EXPECT_EQ(face(from_seq, "a/0").line, 2u);
  EXPECT_EQ(face(from_seq, "b1/0").line, 3u);
  EXPECT_EQ(face(from_seq, "t/0").line, 5u);
  EXPECT_EQ(face(from_seq, "b1/0").origin, (FaceOrigin{"cityjson", "b1", "b", "RoofSurface"}));
  EXPECT_EQ(face(from_seq, "t/0").polygon.outer[0], glm::dvec3(155009, 463010, 10));
  EXPECT_EQ(from_seq.site.from, from_whole.site.from);
  EXPECT_EQ(from_seq.site.latitude_deg, from_whole.site.latitude_deg);
  EXPECT_TRUE(from_seq.warnings.empty());
  // Without the .jsonl name, the lines after a first line that is a JSON object of its
  // own tell a sequence.
  EXPECT_EQ(read("district-seq.json", seq).faces.size(), 8u);
}

// ---- The site from the CRS -------------------------------------------------------------

TEST(CityJsonReader, TheSiteIsTakenAtTheMiddleOfTheFacesBox) {
  // Faces from (154998, 462998) to (155002, 463002) in RD New: the middle is the origin.
  const SourceModel model = read("site.city.json", R"({"type": "CityJSON", "version": "2.0",
    "transform": {"scale": [1, 1, 1], "translate": [154998, 462998, 0]},
    "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/28992"},
    "CityObjects": {"g": {"type": "TINRelief", "geometry": [
      {"type": "CompositeSurface", "lod": "1", "boundaries": [[[0, 1, 2]], [[0, 2, 3]]]}]}},
    "vertices": [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0], [100, 100, 0]]})");
  EXPECT_EQ(model.site.from, "EPSG:28992 through PROJ at (155000, 463000)");
  EXPECT_NEAR(*model.site.latitude_deg, 52.156160556, 1e-8);
}

TEST(CityJsonReader, AGeographicCrsGivesNoSiteAndAWarning) {
  const std::string text = R"({"type": "CityJSON", "version": "2.0",
    "transform": {"scale": [1e-7, 1e-7, 0.001], "translate": [5, 52, 0]},
    "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/4979"},
    "CityObjects": {"g": {"type": "TINRelief", "geometry": [
      {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}]}},
    "vertices": [[0, 0, 0], [10, 0, 0], [0, 10, 0]]})";
  const SourceModel model = read("geographic.city.json", text);
  EXPECT_TRUE(model.site.empty());
  EXPECT_EQ(model.warnings,
            (std::vector<std::string>{write("geographic.city.json", text) +
                                      ": metadata.referenceSystem: no site from it: EPSG:4979 is a "
                                      "geographic CRS, not a projected one"}));
}

// ---- Precision, through a scene -------------------------------------------------------

TEST(CityJsonReader, ARoofOffItsPlaneByItsQuantizationIsPlanarInAScene) {
  // A roof 10 m square at real RD coordinates, stored to the millimetre: one corner 1 mm
  // (one step) above the plane of the other three lies 0.25 mm from their best-fit plane,
  // 2.5e-5 of the roof's size, far beyond the relative tolerance 1e-9, but within twice
  // the vertex rounding, 2 × 0.866 mm: planar, not split. Eight millimetres (2 mm from the
  // plane) are not.
  auto roof = [](int lift_mm) {
    return R"({"type": "CityJSON", "version": "2.0",
      "transform": {"scale": [0.001, 0.001, 0.001], "translate": [84500, 447200, 0]},
      "CityObjects": {"r": {"type": "Building", "geometry": [
        {"type": "MultiSurface", "lod": "2", "boundaries": [[[0, 1, 2, 3]]]}]}},
      "vertices": [[0, 0, 9000], [10000, 0, 9000], [10000, 10000, )" +
           std::to_string(9000 + lift_mm) + R"(], [0, 10000, 9000]]})";
  };
  const std::string scene = R"({"format": "shadowgen-scene/1",
    "meshes": [{"id": "m", "file": "roof.city.json"}], "lights": []})";
  write("roof.city.json", roof(1));
  const ReadResult planar = read_scene(write("roof-scene.json", scene));
  ASSERT_EQ(planar.scene.faces.size(), 1u);
  EXPECT_EQ(planar.scene.faces[0].parts.size(), 1u);
  EXPECT_TRUE(planar.warnings.empty());

  write("roof.city.json", roof(8));
  const ReadResult bent = read_scene(write("roof-scene.json", scene));
  ASSERT_EQ(bent.scene.faces.size(), 1u);
  EXPECT_EQ(bent.scene.faces[0].parts.size(), 2u);  // split into triangles
  ASSERT_EQ(bent.warnings.size(), 1u);
  EXPECT_NE(bent.warnings[0].find("face 'm/r/0': not planar"), std::string::npos)
      << bent.warnings[0];
}

// ---- Reading rules ---------------------------------------------------------------------

TEST(CityJsonReader, UnknownKeysAreWarnedExceptExtensionsAndAttributes) {
  const std::string text = R"({"type": "CityJSON", "version": "2.0", "+census": {"a": 1},
    "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]},
    "metadata": {"title": "anything", "pointOfContact": {}},
    "CityObjects": {
      "b": {"type": "Building", "atributes": {}, "+colour": "red",
            "attributes": {"any": {"thing": 1}}, "geometry": [
        {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]], "lood": "2"}]},
      "x": {"type": "+NoiseBarrier", "height": 3}},
    "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]})";
  const SourceModel model = read("keys.city.json", text);
  const std::string file = write("keys.city.json", text);
  EXPECT_EQ(
      model.warnings,
      (std::vector<std::string>{
          file + ": CityObjects['b'].geometry[0]: unknown key 'lood' (did you mean 'lod'?)",
          file + ": CityObjects['b']: unknown key 'atributes' (did you mean 'attributes'?)"}));
  EXPECT_EQ(error_of("keys.city.json", text, {.strict = true, .lod = std::nullopt}),
            file + ": CityObjects['b'].geometry[0]: unknown key 'lood' (did you mean 'lod'?)");
}

TEST(CityJsonReader, BadInputIsOneLineNamingTheFileTheObjectAndTheProblem) {
  struct Case {
    const char* name;
    std::string text;
    std::string message;  // after "<file>: "
  };
  const std::string vertices = "[0, 0, 0], [1, 0, 0], [0, 1, 0]";
  auto one = [&](const std::string& geometry, const std::string& more = "") {
    return city_json(R"("b": {"type": "Building", "geometry": [)" + geometry + "]}", vertices,
                     more);
  };
  // A GeometryInstance of template `index` at vertex 0, by the 16 numbers `matrix`.
  auto instance = [](int index, const std::string& matrix) {
    return R"({"type": "GeometryInstance", "template": )" + std::to_string(index) +
           R"(, "boundaries": [0], "transformationMatrix": [)" + matrix + "]}";
  };
  const std::string kOneTemplate = R"("geometry-templates": {"templates": [
      {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}],
      "vertices-templates": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},)";
  const std::vector<Case> cases = {
      {"index.city.json",
       one(R"({"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 3]]]})"),
       "CityObjects['b'].geometry[0].boundaries[0][0][2]: vertex index 3 is out of range: the "
       "file has 3 vertices"},
      {"depth.city.json", one(R"({"type": "Solid", "lod": "1", "boundaries": [[[0, 1, 2]]]})"),
       "CityObjects['b'].geometry[0].boundaries[0][0][0]: expected a ring (an array), found a "
       "number: a Solid's boundaries are shells of surfaces of rings of vertex indices"},
      {"deep.city.json",
       one(R"({"type": "MultiSurface", "lod": "1", "boundaries": [[[[0, 1, 2]]]]})"),
       "CityObjects['b'].geometry[0].boundaries[0][0][0]: expected a vertex index, found an "
       "array: a MultiSurface's boundaries are surfaces of rings of vertex indices"},
      {"type.city.json", one(R"({"type": "Polyhedron", "lod": "1", "boundaries": []})"),
       "CityObjects['b'].geometry[0].type: unknown geometry type 'Polyhedron' (CityJSON's are "
       "MultiPoint, MultiLineString, MultiSurface, CompositeSurface, Solid, MultiSolid, "
       "CompositeSolid, GeometryInstance)"},
      {"template.city.json",
       one(instance(2, "1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1"), kOneTemplate),
       "CityObjects['b'].geometry[0].template: template index 2 is out of range: "
       "geometry-templates has 1 templates"},
      {"no-templates.city.json", one(instance(0, "1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1")),
       "CityObjects['b'].geometry[0].template: a GeometryInstance needs the file's "
       "geometry-templates, and it has none"},
      {"matrix.city.json",
       one(instance(0, "1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1"), kOneTemplate),
       "CityObjects['b'].geometry[0].transformationMatrix: the last row must be 0, 0, 0, 1: a "
       "template is placed by an affine map"},
      {"semantic.city.json",
       one(R"({"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]],
               "semantics": {"surfaces": [{"type": "RoofSurface"}], "values": [1]}})"),
       "CityObjects['b'].geometry[0].semantics.values[0]: semantic surface index 1 is out of "
       "range: semantics.surfaces has 1"},
      {"values.city.json",
       one(R"({"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]], [[0, 2, 1]]],
               "semantics": {"surfaces": [{"type": "RoofSurface"}], "values": [0]}})"),
       "CityObjects['b'].geometry[0].semantics.values: holds 1 semantic values for the 2 "
       "surfaces of the boundaries"},
      {"lod.city.json", one(R"({"type": "MultiSurface", "lod": "high", "boundaries": []})"),
       "CityObjects['b'].geometry[0].lod: 'high' is not a level of detail: CityJSON writes a "
       "number such as \"2\" or \"2.2\""},
      {"scale.city.json",
       R"({"type": "CityJSON", "version": "2.0", "transform": {"scale": [1, 0, 1],
           "translate": [0, 0, 0]}, "CityObjects": {}, "vertices": []})",
       "transform.scale[1]: a transform's scale must be above 0 (the size of one integer step "
       "of the coordinates)"},
      {"huge.city.json",
       R"({"type": "CityJSON", "version": "2.0", "transform": {"scale": [1e300, 1, 1],
           "translate": [0, 0, 0]}, "CityObjects": {}, "vertices": [[0, 0, 0], [1e10, 0, 0]]})",
       "vertices[1]: the transform takes this vertex beyond the range of a double"},
      {"version.city.json",
       R"({"type": "CityJSON", "version": "0.9", "CityObjects": {}, "vertices": []})",
       "version: CityJSON version '0.9' is not one shadowgen reads (1.0, 1.1, 2.0)"},
      {"crs.city.json",
       R"({"type": "CityJSON", "version": "2.0", "metadata": {"referenceSystem": "EPSG:7415"},
           "CityObjects": {}, "vertices": []})",
       "metadata.referenceSystem: 'EPSG:7415' is not a CRS as CityJSON names one: "
       "https://www.opengis.net/def/crs/EPSG/0/7415 (or in version 1.0 "
       "urn:ogc:def:crs:EPSG::7415)"},
      {"twice.city.json",
       R"({"type": "CityJSON", "version": "2.0", "CityObjects": {"a": {"type": "Building",
           "type": "Bridge"}}, "vertices": []})",
       "CityObjects.a: the key 'type' is given twice (a key may appear once in an object)"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(error_of(c.name, c.text), write(c.name, c.text) + ": " + c.message);
  }
}

TEST(CityJsonReader, BadCityJsonSeqLinesAreNamedByTheirLine) {
  const std::string header =
      R"({"type": "CityJSON", "version": "2.0", "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]}, "CityObjects": {}, "vertices": []})";
  const std::string feature =
      R"({"type": "CityJSONFeature", "id": "a", "CityObjects": {"a": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}]}}, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]})";
  struct Case {
    const char* name;
    std::string text;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"no-transform.city.jsonl",
       R"({"type": "CityJSON", "version": "2.0", "CityObjects": {}, "vertices": []})"
       "\n" +
           feature + "\n",
       "line 1: missing 'transform': a CityJSONSeq file's first line needs one, its features' "
       "vertices are integers it scales"},
      {"not-feature.city.jsonl", header + "\n" + feature + "\n" + header + "\n",
       "line 3: type: expected a CityJSONFeature, found 'CityJSON': after its first line a "
       "CityJSONSeq file holds one feature a line"},
      {"again.city.jsonl", header + "\n" + feature + "\n\n" + feature + "\n",
       "line 4: CityObjects['a']: city object 'a' is given again (first on line 2)"},
      {"broken.city.jsonl", header + "\n" + feature + "\n" + R"({"type": "CityJSONFeature",)",
       "line 3, column 28: invalid JSON: syntax error while parsing object key - unexpected end "
       "of input; expected string literal"},
      {"index.city.jsonl",
       header + "\n" +
           R"({"type": "CityJSONFeature", "id": "a", "CityObjects": {"a": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 5]]]}]}}, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]})",
       "line 2: CityObjects['a'].geometry[0].boundaries[0][0][2]: vertex index 5 is out of "
       "range: the feature has 3 vertices"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(error_of(c.name, c.text), write(c.name, c.text) + ": " + c.message);
  }
}

}  // namespace
}  // namespace shadowgen::cityjson
