// Telling a scene from a shadowed database (shadowgen/document.h) by the "format" key,
// without building the document.

#include "shadowgen/json/document.h"

#include <gtest/gtest.h>

#include <string>

#include "shadowgen/model/input_error.h"

namespace shadowgen {
namespace {

std::string problem_of(const std::string& json) {
  try {
    (void)document_format(json, "doc.json");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "doc.json");
    return e.problem();
  }
  return "(no error)";
}

TEST(DocumentFormat, FindsTheTopLevelFormatKeyWherever) {
  EXPECT_EQ(document_format(R"({"format": "shadowgen-scene/1", "polygons": []})", "d"),
            kSceneFormat);
  EXPECT_EQ(document_format(R"({"polygons": [{"format": "nested"}], "lights": {"format": 1},
                               "format": "shadowgen-shadowed/1"})",
                            "d"),
            kShadowedFormat);
  EXPECT_EQ(document_format(R"({"format": "other/2"})", "d"), "other/2");
}

TEST(DocumentFormat, StopsAtTheFormatKey) {
  // What follows the key is not read: a truncated database still tells its format, and
  // the reader of that format reports the damage.
  EXPECT_EQ(document_format(R"({"format": "shadowgen-shadowed/1", "faces": [)", "d"),
            kShadowedFormat);
}

TEST(DocumentFormat, ExplainsWhatIsMissing) {
  EXPECT_EQ(problem_of(R"({"polygons": []})"), "no \"format\" key");
  EXPECT_EQ(problem_of(R"({"polygons": [{"format": "shadowgen-scene/1"}]})"), "no \"format\" key");
  EXPECT_EQ(problem_of(R"([{"format": "shadowgen-scene/1"}])"),
            "the top level is an array, not an object");
  EXPECT_EQ(problem_of("42"), "the top level is a number, not an object");
  EXPECT_EQ(problem_of(R"({"format": 1})"), "\"format\" is a number, not a string");
  EXPECT_EQ(problem_of(R"({"format": {"name": "x"}})"), "\"format\" is an object, not a string");
  // Worded as the readers word it (json_reader.h).
  EXPECT_EQ(problem_of(""),
            "line 1, column 1: invalid JSON: syntax error while parsing value - unexpected end "
            "of input; expected '[', '{', or a literal");
  EXPECT_EQ(problem_of(R"({"polygons": [1, 2,)"),
            "line 1, column 20: invalid JSON: syntax error while parsing value - unexpected end "
            "of input; expected '[', '{', or a literal");
}

TEST(ReadDocument, NamesAFileThatCannotBeRead) {
  try {
    (void)read_document("/nonexistent/scene.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/scene.json");
    EXPECT_EQ(e.problem(), "no such file");
  }
  try {
    (void)read_document(::testing::TempDir());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "is a folder, not a file");
  }
}

}  // namespace
}  // namespace shadowgen
