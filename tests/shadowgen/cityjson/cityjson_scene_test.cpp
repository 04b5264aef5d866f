// A CityJSON file through a scene (shadowgen/scene/scene_reader.h, meshes[] naming it;
// docs/cityjson.md): the faces it gives are those of the same geometry written as a
// scene's own polygons, vertex for vertex; their lit areas are the same, and the exact
// shadow oracle's; and a scene that gives only its time zone takes the rest of its site
// from the file's CRS, its sun lights placed by it.

#include <gtest/gtest.h>

#include <glm/vec3.hpp>
#include <map>
#include <string>
#include <vector>

#include "shadowgen/geo/projected_site.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/output/report.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/shadows/shadow_check.h"
#include "tests/support/temp_folder.h"

namespace shadowgen::test {
namespace {

using glm::dvec3;

const TempFolder& folder() {
  static const TempFolder f("shadowgen-cityjson-scene");
  return f;
}

// Where the district stands: a corner in Amersfoort / RD New (EPSG:7415), near Delft.
const dvec3 kCorner(84500, 447200, 0);
// The transform's step: a quarter metre on each axis, so that every coordinate below is a
// whole number of steps and every placed vertex is exact in binary.
constexpr double kStep = 0.25;

using Loop = std::vector<dvec3>;

struct Surface {
  Loop outer;  // counter-clockwise seen from outside, local metres
  std::vector<Loop> holes;
  std::string semantic;
};

// A box's six surfaces, outward: ground, roof, then the walls facing -y, +x, +y, -x.
std::vector<Surface> box(dvec3 a, dvec3 b) {
  const dvec3 p[8] = {{a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, b.y, a.z}, {a.x, b.y, a.z},
                      {a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z}};
  const int order[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::vector<Surface> out;
  for (int f = 0; f < 6; ++f) {
    out.push_back({{p[order[f][0]], p[order[f][1]], p[order[f][2]], p[order[f][3]]},
                   {},
                   f == 0   ? "GroundSurface"
                   : f == 1 ? "RoofSurface"
                            : "WallSurface"});
  }
  return out;
}

// A house with its ridge along x: ground, south wall, east gable, north wall, west gable,
// south and north roofs, each counter-clockwise seen from outside.
std::vector<Surface> gabled(double x0, double y0, double x1, double y1, double eaves,
                            double ridge) {
  const double ym = 0.5 * (y0 + y1);
  const dvec3 p0(x0, y0, 0), p1(x1, y0, 0), p2(x1, y1, 0), p3(x0, y1, 0);
  const dvec3 p4(x0, y0, eaves), p5(x1, y0, eaves), p6(x1, y1, eaves), p7(x0, y1, eaves);
  const dvec3 r0(x0, ym, ridge), r1(x1, ym, ridge);
  return {{{p0, p3, p2, p1}, {}, "GroundSurface"},   {{p0, p1, p5, p4}, {}, "WallSurface"},
          {{p1, p2, p6, r1, p5}, {}, "WallSurface"}, {{p2, p3, p7, p6}, {}, "WallSurface"},
          {{p3, p0, p4, r0, p7}, {}, "WallSurface"}, {{p4, p5, r1, r0}, {}, "RoofSurface"},
          {{p6, p7, r0, r1}, {}, "RoofSurface"}};
}

// The tree template, in its own metres: a crown, an octahedron 4 m across from 2 m to
// 7 m up (its eight faces outward), and a trunk's two crossed panels.
std::vector<Surface> tree() {
  const dvec3 e(2, 0, 4.5), n(0, 2, 4.5), w(-2, 0, 4.5), s(0, -2, 4.5), top(0, 0, 7),
      bottom(0, 0, 2);
  return {{{e, n, top}, {}, ""},
          {{n, w, top}, {}, ""},
          {{w, s, top}, {}, ""},
          {{s, e, top}, {}, ""},
          {{n, e, bottom}, {}, ""},
          {{w, n, bottom}, {}, ""},
          {{s, w, bottom}, {}, ""},
          {{e, s, bottom}, {}, ""},
          {{{-0.25, 0, 0}, {0.25, 0, 0}, {0.25, 0, 2}, {-0.25, 0, 2}}, {}, ""}};
}

// The tree instance: scaled by 1.5 and stood at (8, 30, 0).
constexpr double kTreeScale = 1.5;
const dvec3 kTreeAt(8, 30, 0);

// The district, surfaces by the object holding them, in the order of the objects' ids
// (the order the CityJSON reader gives them in). Tree surfaces are placed.
std::map<std::string, std::vector<Surface>> district() {
  std::map<std::string, std::vector<Surface>> out;
  // The ground with a pond cut out of it (a hole, written clockwise).
  out["ground"] = {{{{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0}},
                    {{{30, 30, 0}, {30, 35, 0}, {35, 35, 0}, {35, 30, 0}}},
                    ""}};
  out["house"] = gabled(10, 10, 22, 18, 6, 9.5);
  out["shed-part"] = box({26, 6, 0}, {30, 12, 3});
  for (Surface s : tree()) {
    for (dvec3& p : s.outer) p = kTreeScale * p + kTreeAt;
    out["tree"].push_back(s);
  }
  return out;
}

std::string point(const dvec3& p) {
  std::string out = "[";
  out += std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + "]";
  return out;
}

// CityJSON 2.0 of the district: the house with an LoD 1 block besides its LoD 2.2 Solid,
// the shed a Building made of one BuildingPart, the tree a GeometryInstance.
std::string city_json() {
  std::vector<dvec3> vertices;
  auto ring = [&](const Loop& loop) {
    std::string out = "[";
    for (const dvec3& p : loop) {
      if (out.size() > 1) out += ", ";
      out += std::to_string(vertices.size());
      vertices.push_back(p / kStep);  // whole numbers of steps
    }
    return out + "]";
  };
  auto surfaces = [&](const std::vector<Surface>& list, bool semantics) {
    std::string boundaries, values;
    for (const Surface& s : list) {
      boundaries += (boundaries.empty() ? "[" : ", [") + ring(s.outer);
      for (const Loop& h : s.holes) boundaries += ", " + ring(h);
      boundaries += "]";
      values += values.empty() ? "" : ", ";
      values += s.semantic == "GroundSurface" ? "0" : s.semantic == "WallSurface" ? "1" : "2";
    }
    std::string out = "\"boundaries\": [[" + boundaries + "]]";
    if (semantics) {
      out += R"(, "semantics": {"surfaces": [{"type": "GroundSurface"}, {"type": "WallSurface"},
               {"type": "RoofSurface"}], "values": [[)" +
             values + "]]}";
    }
    return out;
  };
  const std::map<std::string, std::vector<Surface>> d = district();
  std::string ground_boundaries;
  {
    const Surface& g = d.at("ground")[0];
    ground_boundaries = "[[" + ring(g.outer) + ", " + ring(g.holes[0]) + "]]";
  }
  const std::string house_lod1 = surfaces(box({10, 10, 0}, {22, 18, 8}), false);
  const std::string house = surfaces(d.at("house"), true);
  const std::string shed = surfaces(d.at("shed-part"), true);
  const std::size_t tree_point = vertices.size();
  vertices.push_back(kTreeAt / kStep);
  std::string template_boundaries, template_vertices;
  std::size_t next = 0;
  for (const Surface& s : tree()) {
    std::string r;
    for (const dvec3& p : s.outer) {
      r += (r.empty() ? "" : ", ") + std::to_string(next++);
      template_vertices += (template_vertices.empty() ? "" : ", ") + point(p);
    }
    template_boundaries += (template_boundaries.empty() ? "[[" : ", [[") + r + "]]";
  }
  std::string vertex_text;
  for (const dvec3& v : vertices) vertex_text += (vertex_text.empty() ? "" : ", ") + point(v);
  return R"({"type": "CityJSON", "version": "2.0",
  "transform": {"scale": [0.25, 0.25, 0.25], "translate": [84500, 447200, 0]},
  "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
  "geometry-templates": {"templates": [{"type": "MultiSurface", "lod": "2", "boundaries": [)" +
         template_boundaries + R"(]}], "vertices-templates": [)" + template_vertices + R"(]},
  "CityObjects": {
    "ground": {"type": "TINRelief", "geometry": [{"type": "MultiSurface", "lod": "1",
      "boundaries": )" +
         ground_boundaries + R"(}]},
    "house": {"type": "Building", "geometry": [
      {"type": "Solid", "lod": "1", )" +
         house_lod1 + R"(},
      {"type": "Solid", "lod": "2.2", )" +
         house + R"(}]},
    "shed": {"type": "Building", "children": ["shed-part"]},
    "shed-part": {"type": "BuildingPart", "parents": ["shed"], "geometry": [
      {"type": "Solid", "lod": "2.2", )" +
         shed + R"(}]},
    "tree": {"type": "SolitaryVegetationObject", "geometry": [
      {"type": "GeometryInstance", "template": 0, "boundaries": [)" +
         std::to_string(tree_point) + R"(],
       "transformationMatrix": [1.5, 0, 0, 0, 0, 1.5, 0, 0, 0, 0, 1.5, 0, 0, 0, 0, 1]}]}},
  "vertices": [)" +
         vertex_text + "]}";
}

const char* const kLights = R"(
  "lights": [
    {"id": "low", "type": "directional", "direction": [-0.5, 0.8, -0.6]},
    {"id": "high", "type": "directional", "direction": [0.6, 0.3, -1.5]}])";

// The same district as a scene's own polygons, in projected coordinates.
std::string plain_scene() {
  std::string polygons;
  std::size_t k = 0;
  auto loop = [](const Loop& l) {
    std::string out = "[";
    for (const dvec3& p : l) out += (out.size() > 1 ? ", " : "") + point(p + kCorner);
    return out + "]";
  };
  for (const auto& [object, surfaces] : district()) {
    for (const Surface& s : surfaces) {
      polygons += polygons.empty() ? "" : ",\n";
      polygons += R"({"id": "p)" + std::to_string(k++) + R"(", "outer": )" + loop(s.outer);
      if (!s.holes.empty()) polygons += R"(, "holes": [)" + loop(s.holes[0]) + "]";
      polygons += "}";
    }
  }
  return R"({"format": "shadowgen-scene/1", "polygons": [)" + polygons + "]," + kLights + "}";
}

ReadResult read_district(const std::string& scene_name, const std::string& scene_text) {
  folder().write("district.city.json", city_json());
  const auto path = folder().write(scene_name, scene_text);
  return read_scene(path);
}

TEST(CityJsonScene, AModelGivesTheFacesAndLitAreasOfItsGeometryWrittenAsPolygons) {
  const ReadResult city = read_district("city.json", R"({"format": "shadowgen-scene/1",
        "meshes": [{"id": "d", "file": "district.city.json"}],)" +
                                                         std::string(kLights) + "}");
  const ReadResult plain = read_district("plain.json", plain_scene());
  EXPECT_TRUE(city.warnings.empty()) << city.warnings.front();
  // 1 ground, 7 house, 6 shed and 9 tree surfaces, in that order, vertex for vertex.
  ASSERT_EQ(city.scene.faces.size(), 23u);
  ASSERT_EQ(plain.scene.faces.size(), 23u);
  for (std::size_t i = 0; i < 23; ++i) {
    SCOPED_TRACE(city.scene.faces[i].id);
    const std::vector<hsr::Polygon3>& ours = city.scene.faces[i].parts;
    const std::vector<hsr::Polygon3>& theirs = plain.scene.faces[i].parts;
    ASSERT_EQ(ours.size(), 1u);  // planar: not split
    ASSERT_EQ(theirs.size(), 1u);
    EXPECT_EQ(ours[0].outer, theirs[0].outer);
    EXPECT_EQ(ours[0].holes, theirs[0].holes);
  }
  EXPECT_EQ(city.scene.faces[0].id, "d/ground/0");
  EXPECT_EQ(city.scene.faces[13].id, "d/shed-part/5");
  EXPECT_EQ(city.scene.faces[13].origin,
            (FaceOrigin{"cityjson", "shed-part", "shed", "WallSurface"}));
  EXPECT_EQ(city.scene.faces[14].id, "d/tree/0");

  const ShadowedScene city_shadows = generate_shadows(city.scene).shadowed;
  const ShadowedScene plain_shadows = generate_shadows(plain.scene).shadowed;
  const std::vector<ReportRow> city_rows = report_rows(city_shadows);
  const std::vector<ReportRow> plain_rows = report_rows(plain_shadows);
  ASSERT_EQ(city_rows.size(), plain_rows.size());
  double ground_shaded = 0.0;
  for (std::size_t r = 0; r < city_rows.size(); ++r) {
    EXPECT_EQ(city_rows[r].area, plain_rows[r].area);
    EXPECT_EQ(city_rows[r].lit_area, plain_rows[r].lit_area);
    if (city_rows[r].face == 0) ground_shaded += city_rows[r].area - city_rows[r].lit_area;
  }
  // The ground, 40 × 40 less its 5 × 5 pond, is shaded by the buildings and the tree.
  EXPECT_EQ(city_rows[0].area, 1575.0);
  EXPECT_GT(ground_shaded, 100.0);

  // The coordinates stand near 10^5.7: each lit vertex is placed to about 1e-10 m, so
  // the bound allows that much movement of every lit vertex besides 1e-9 of the area.
  const OracleCheck check = check_against_oracle(city.scene, city_shadows, 1e-9, 1e-10);
  EXPECT_EQ(check.failures, 0u) << summary(check) << "\n" << check.report;
  EXPECT_EQ(check.pairs, 46u);
}

TEST(CityJsonScene, ASceneGivingOnlyItsTimeZoneTakesTheSiteFromTheCrs) {
  const std::string sun = R"(,
    "lights": [{"id": "noon", "type": "sun", "time": "2026-06-21T13:40"}]})";
  const ReadResult derived = read_district("derived.json", R"({"format": "shadowgen-scene/1",
      "meshes": [{"id": "d", "file": "district.city.json"}],
      "site": {"utc_offset_h": 1})" + sun);
  // The faces span (84500, 447200) to (84540, 447240): the site is RD's at the middle.
  const geo::ProjectedSite expected = geo::projected_site("EPSG:7415", 84520, 447220);
  ASSERT_TRUE(derived.scene.site);
  EXPECT_EQ(derived.scene.site->latitude_deg, *expected.site.latitude_deg);
  EXPECT_EQ(derived.scene.site->longitude_deg, *expected.site.longitude_deg);
  EXPECT_EQ(derived.scene.site->north_axis_deg, *expected.site.north_axis_deg);
  EXPECT_EQ(derived.scene.site->utc_offset_h, 1.0);
  EXPECT_NEAR(derived.scene.site->latitude_deg, 52.01, 0.01);  // Delft
  EXPECT_NEAR(derived.scene.site->longitude_deg, 4.36, 0.01);
  EXPECT_NEAR(derived.scene.site->north_axis_deg, -0.81, 0.01);  // west of Amersfoort

  // The same sun as a scene that writes the derived site out in full.
  const std::string site = R"("site": {"utc_offset_h": 1, "latitude_deg": )" +
                           shortest(*expected.site.latitude_deg) + R"(, "longitude_deg": )" +
                           shortest(*expected.site.longitude_deg) + R"(, "north_axis_deg": )" +
                           shortest(*expected.site.north_axis_deg) + "}";
  const ReadResult written = read_district(
      "written.json",
      R"({"format": "shadowgen-scene/1", "meshes": [{"id": "d", "file": "district.city.json"}], )" +
          site + sun);
  ASSERT_EQ(derived.scene.lights.size(), 1u);
  ASSERT_EQ(written.scene.lights.size(), 1u);
  EXPECT_EQ(derived.scene.lights[0].direction, written.scene.lights[0].direction);
  // Near solar noon in Delft (4.36°E, UTC+1) the sun stands about south: it travels north,
  // turned 0.81° by the grid's convergence.
  EXPECT_GT(derived.scene.lights[0].direction.y, 0.0);

  // A key the scene gives wins over the file's.
  const ReadResult own_axis = read_district("own-axis.json", R"({"format": "shadowgen-scene/1",
      "meshes": [{"id": "d", "file": "district.city.json"}],
      "site": {"utc_offset_h": 1, "north_axis_deg": 0})" + sun);
  EXPECT_EQ(own_axis.scene.site->north_axis_deg, 0.0);
  EXPECT_EQ(own_axis.scene.site->latitude_deg, *expected.site.latitude_deg);
}

}  // namespace
}  // namespace shadowgen::test
