// A scene's "groups" (shadowgen/scene/detail/group_entry.h, through the scene reader): read
// in order, kept in the database and read back from it, and every mistake named at its JSON
// path before any shadow is computed.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/scene/database_reader.h"
#include "shadowgen/scene/scene_reader.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

std::string scene_with_groups(const std::string& groups) {
  return R"({"format": "shadowgen-scene/1",
    "polygons": [
      {"id": "garden", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
      {"id": "garden-bed", "outer": [[0,11,0],[2,11,0],[2,12,0],[0,12,0]]},
      {"id": "roof", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]]}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}],
    "groups": )" +
         groups + "}";
}

std::string error_of(const std::string& groups) {
  try {
    (void)parse_scene(scene_with_groups(groups), "scene.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(GroupEntries, AreReadInOrderAndKeptInTheDatabase) {
  const std::string groups =
      R"([{"id": "garden", "faces": ["garden*"]}, {"id": "roofs", "faces": ["roof", "r?of"]}])";
  const ShadowedScene shadowed = test::generated(scene_with_groups(groups));
  const std::vector<FaceGroupSpec> expected{{"garden", {"garden*"}}, {"roofs", {"roof", "r?of"}}};
  EXPECT_EQ(shadowed.scene().groups, expected);
  const std::string text = database_json(shadowed);
  EXPECT_NE(text.find("\"groups\": [\n    {\"id\":\"garden\",\"faces\":[\"garden*\"]},"),
            std::string::npos)
      << text;
  EXPECT_EQ(parse_database(text, "db.json").scene().groups, expected);
  // A database without groups has no "groups" key, as before groups were.
  EXPECT_EQ(database_json(test::generated(test::kTwoLights)).find("\"groups\""), std::string::npos);
}

TEST(GroupEntries, EachMistakeIsNamedAtItsPath) {
  EXPECT_EQ(error_of(R"([{"id": "garden", "faces": ["garden", "gardn*"]}])"),
            "scene.json: group 'garden': groups[0] ('garden').faces[1]: the pattern 'gardn*' "
            "matches no face id");
  EXPECT_EQ(
      error_of(R"([{"id": "garden", "faces": ["garden"]}, {"id": "garden", "faces": ["roof"]}])"),
      "scene.json: groups[1].id: duplicate id 'garden' (already used by another group)");
  EXPECT_EQ(error_of(R"([{"id": "garden", "faces": []}])"),
            "scene.json: group 'garden': groups[0] ('garden').faces: expected at least one face "
            "pattern");
  EXPECT_EQ(error_of(R"([{"id": "garden", "faces": ["garden\\"]}])"),
            "scene.json: group 'garden': groups[0] ('garden').faces[0]: a face pattern must not "
            "end in a lone '\\' (\"\\\\\" stands for a backslash)");
  EXPECT_EQ(error_of(R"([{"id": "garden"}])"),
            "scene.json: group 'garden': groups[0] ('garden'): missing 'faces'");
}

TEST(GroupEntries, ADatabaseGroupMatchingNoFaceIsRefused) {
  std::string text = database_json(test::generated(test::kTwoLights));
  text.insert(text.find("\"faces\": ["),
              "\"groups\": [{\"id\": \"g\", \"faces\": [\"lawn/*\"]}],\n");
  try {
    (void)parse_database(text, "db.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "db.json: group 'g': groups[0] ('g').faces[0]: the pattern 'lawn/*' matches no "
              "face id");
  }
}

}  // namespace
}  // namespace shadowgen
