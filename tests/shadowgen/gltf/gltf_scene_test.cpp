// A scene naming a glTF model, end to end: read through the scene reader (told a .glb by
// its content, the entry's transform applied after the node hierarchy), its faces' ids,
// origins and vertices those of the same geometry written as plain polygons, and its lit
// areas the exact ones of the CGAL shadow oracle on the plain scene.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gltf_builder.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/shadows/shadow_check.h"
#include "tests/shadowgen/shadows/shadow_oracle.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

constexpr double kTolerance = 1e-9;

const test::TempFolder& folder() {
  static const test::TempFolder temp("shadowgen-gltf-scene");
  return temp;
}

// In glTF's +y up: a 10 m ground square, and a unit roof tile (facing +y) placed twice:
// by node "canopy" (translation (3, 3, -3), scale (2, 1, 2)) and by node "mirrored",
// child of "frame" (rotation 90° about +y: (x, y, z) -> (z, y, -x)), translation
// (7, 2, 8) and scale (-2, 1, 2), a mirror. Tile corner (x, 0, z) of "mirrored" goes to
// (7 - 2x, 2, 8 + 2z), then (8 + 2z, 2, 2x - 7), then, +z up, (8 + 2z, 7 - 2x, 2).
std::string house_glb() {
  test::GltfBuilder b;
  const int ground = b.positions({{0, 0, 0}, {10, 0, 0}, {10, 0, -10}, {0, 0, -10}});
  const int tile = b.positions({{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {0, 0, -1}});
  const int quad = b.indices({0, 1, 2, 0, 2, 3});
  auto mesh = [&](const char* name, int positions) {
    return "{\"name\": \"" + std::string(name) +
           "\", \"primitives\": [{\"attributes\": {\"POSITION\": " + std::to_string(positions) +
           "}, \"indices\": " + std::to_string(quad) + "}]}";
  };
  return b.glb(R"("scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
    "nodes": [
      {"name": "ground", "mesh": 0},
      {"name": "canopy", "mesh": 1, "translation": [3, 3, -3], "scale": [2, 1, 2]},
      {"name": "frame", "rotation": [0, 0.7071067811865476, 0, 0.7071067811865476],
       "children": [3]},
      {"name": "mirrored", "mesh": 1, "translation": [7, 2, 8], "scale": [-2, 1, 2]}],
    "meshes": [)" +
               mesh("plane", ground) + ", " + mesh("tile", tile) + "]");
}

// The lights, in the scene's coordinates after the entry's transform (x + 100).
const char* const kLights = R"("lights": [
    {"id": "sun", "type": "directional", "direction": [-0.3, 0.2, -1]},
    {"id": "lamp", "type": "point", "position": [105, 5, 8], "intensity": [1, 1, 1]}])";

// The same faces as plain polygons, in the reader's order, each triangle's corners as the
// reader takes them (the mirrored tile's reversed), shifted by the transform.
const char* const kPlainPolygons = R"("polygons": [
    {"id": "ground_0", "outer": [[100, 0, 0], [110, 0, 0], [110, 10, 0]]},
    {"id": "ground_1", "outer": [[100, 0, 0], [110, 10, 0], [100, 10, 0]]},
    {"id": "canopy_0", "outer": [[103, 3, 3], [105, 3, 3], [105, 5, 3]]},
    {"id": "canopy_1", "outer": [[103, 3, 3], [105, 5, 3], [103, 5, 3]]},
    {"id": "mirrored_0", "outer": [[108, 7, 2], [106, 5, 2], [108, 5, 2]]},
    {"id": "mirrored_1", "outer": [[108, 7, 2], [106, 7, 2], [106, 5, 2]]}])";

TEST(GltfScene, LitAreasAreThoseOfTheSameGeometryAsPolygons) {
  folder().write("house.model", house_glb());  // told by its content, not its name
  const ReadResult model = read_scene(folder().write("model.json", std::string(R"({
    "format": "shadowgen-scene/1",
    "meshes": [{"id": "house", "file": "house.model",
                "transform": [[1, 0, 0, 100], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}],
    )") + kLights + "}"));
  const ReadResult plain =
      read_scene(folder().write("plain.json", std::string(R"({"format": "shadowgen-scene/1", )") +
                                                  kPlainPolygons + ", " + kLights + "}"));
  EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();

  const std::vector<std::string> ids = {"house/ground/0", "house/ground/1",   "house/canopy/0",
                                        "house/canopy/1", "house/mirrored/0", "house/mirrored/1"};
  ASSERT_EQ(model.scene.faces.size(), ids.size());
  ASSERT_EQ(plain.scene.faces.size(), ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const Face& face = model.scene.faces[i];
    EXPECT_EQ(face.id, ids[i]);
    ASSERT_EQ(face.parts.size(), 1u);
    const hsr::Loop3& ours = face.parts[0].outer;
    const hsr::Loop3& theirs = plain.scene.faces[i].parts[0].outer;
    ASSERT_EQ(ours.size(), theirs.size()) << face.id;
    for (std::size_t v = 0; v < ours.size(); ++v) {
      EXPECT_NEAR(ours[v].x, theirs[v].x, 1e-13) << face.id;
      EXPECT_NEAR(ours[v].y, theirs[v].y, 1e-13) << face.id;
      EXPECT_NEAR(ours[v].z, theirs[v].z, 1e-13) << face.id;
    }
  }
  EXPECT_EQ(model.scene.faces[4].origin, (FaceOrigin{"gltf", "mirrored", "tile", ""}));
  EXPECT_EQ(model.scene.faces[0].origin, (FaceOrigin{"gltf", "ground", "plane", ""}));

  // Our lit regions on the imported scene against the exact ones.
  const ShadowedScene shadowed = generate_shadows(model.scene).shadowed;
  const test::OracleCheck check = test::check_against_oracle(model.scene, shadowed, kTolerance);
  std::printf("[ %-24s ] %s\n", "glTF house", test::summary(check).c_str());
  EXPECT_EQ(check.failures, 0u) << check.report;

  // The same lit areas as the plain polygons have, exactly (CGAL), light by light.
  const test::ShadowOracle oracle(plain.scene);
  const auto fractions = test::lit_fractions(shadowed);
  double shaded = 0.0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t light = 0; light < plain.scene.lights.size(); ++light) {
      const test::ExactLit exact = oracle.lit(i, light);
      const double ours = fractions.at({ids[i], plain.scene.lights[light].id});
      EXPECT_NEAR(ours, exact.lit_fraction, kTolerance) << ids[i];
      shaded += exact.face_area - exact.lit_area;
    }
  }
  EXPECT_GT(shaded, 8.0);  // both tiles' shadows fall on the ground, under both lights
}

}  // namespace
}  // namespace shadowgen
