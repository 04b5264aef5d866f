// Which reader a meshes[] file goes to (shadowgen/scene/detail/source_format.h): the
// content where it says, the extension otherwise.

#include "shadowgen/scene/detail/source_format.h"

#include <gtest/gtest.h>

#include <string>

namespace shadowgen::scene::detail {
namespace {

TEST(SourceFormat, BinaryGltfByItsMagicWhateverTheName) {
  EXPECT_EQ(format_of(std::string("glTF\x02\0\0\0", 8), "model.obj"), SourceFormat::kGltf);
}

TEST(SourceFormat, JsonFormatsByTheirKeys) {
  EXPECT_EQ(format_of(R"({"asset": {"version": "2.0"}, "nodes": []})", "m.json"),
            SourceFormat::kGltf);
  EXPECT_EQ(format_of(R"({"type":"CityJSON","version":"2.0"})", "district.json"),
            SourceFormat::kCityJson);
  EXPECT_EQ(format_of(R"({"type":"CityJSONFeature","id":"b1"})", "district.txt"),
            SourceFormat::kCityJson);
  EXPECT_EQ(format_of("\xEF\xBB\xBF  {\"Version\": {\"Version 1\": {\"version_identifier\" : "
                      "\"23.2\"}}}",
                      "house.json"),
            SourceFormat::kEnergyPlus);
}

TEST(SourceFormat, IdfByItsVersionObjectAfterComments) {
  EXPECT_EQ(format_of("!- Generator IDFEditor 1.51\n\n  VERSION ,23.2;\n", "house.txt"),
            SourceFormat::kEnergyPlus);
  EXPECT_EQ(format_of("Version;\n", "house"), SourceFormat::kEnergyPlus);
  // An OBJ whose first word is not "version" stays a mesh.
  EXPECT_EQ(format_of("# Version, 2\nv 0 0 0\n", "m.obj"), SourceFormat::kMesh);
  EXPECT_EQ(format_of("versions, 2\n", "m.obj"), SourceFormat::kMesh);
}

TEST(SourceFormat, ExtensionWhenTheContentDoesNotSay) {
  EXPECT_EQ(format_of("", "A.IDF"), SourceFormat::kEnergyPlus);
  EXPECT_EQ(format_of("", "a.epJSON"), SourceFormat::kEnergyPlus);
  EXPECT_EQ(format_of("", "a.glb"), SourceFormat::kGltf);
  EXPECT_EQ(format_of("{}", "a.gltf"), SourceFormat::kGltf);
  EXPECT_EQ(format_of("", "a.city.jsonl"), SourceFormat::kCityJson);
  EXPECT_EQ(format_of("{}", "a.city.json"), SourceFormat::kCityJson);
  EXPECT_EQ(format_of("v 0 0 0\n", "a.obj"), SourceFormat::kMesh);
  EXPECT_EQ(format_of("solid x\n", "a.stl"), SourceFormat::kMesh);
  EXPECT_EQ(format_of("", "a.om"), SourceFormat::kMesh);
}

}  // namespace
}  // namespace shadowgen::scene::detail
