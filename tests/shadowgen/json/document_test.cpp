// Telling a scene from a shadowed database (shadowgen/document.h) by the "format" key,
// without building the document.

#include "shadowgen/json/document.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "shadowgen/model/input_error.h"
#include "tests/support/temp_folder.h"

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
            "shadowgen-shadowed/1");
  EXPECT_EQ(document_format(R"({"format": "other/2"})", "d"), "other/2");
}

TEST(DocumentFormat, StopsAtTheFormatKey) {
  // What follows the key is not read: a truncated database still tells its format, and
  // the reader of that format reports the damage.
  EXPECT_EQ(document_format(R"({"format": "shadowgen-shadowed/1", "faces": [)", "d"),
            "shadowgen-shadowed/1");
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

// nlohmann's parser takes a NUL byte for the end of the text; a file starting with one
// (a binary file) is said to hold it, placed as the JSON reader places one, not to end.
TEST(DocumentFormat, ANulByteBeforeTheFormatIsNamedWhereItIs) {
  const std::string nul_first("\0\0{\"format\": \"shadowgen-scene/1\"}", 33);
  const std::string nul_on_line_2("{\n  \0\"format\": \"shadowgen-scene/1\"}", 35);
  const std::string expected_first =
      "line 1, column 1: invalid JSON: a NUL byte (JSON text has none; is this a binary file?)";
  const std::string expected_on_line_2 =
      "line 2, column 3: invalid JSON: a NUL byte (JSON text has none; is this a binary file?)";
  EXPECT_EQ(problem_of(nul_first), expected_first);
  EXPECT_EQ(problem_of(nul_on_line_2), expected_on_line_2);
  // The same read from a file, only up to the key.
  const test::TempFolder folder("shadowgen-document");
  for (const auto& [text, expected] :
       {std::pair{nul_first, expected_first}, std::pair{nul_on_line_2, expected_on_line_2}}) {
    const std::filesystem::path path = folder.write("nul.json", text);
    try {
      (void)file_format(path);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path.string());
      EXPECT_EQ(e.problem(), expected);
    }
  }
  // A NUL byte after the key is the reader's to find: the format is told.
  EXPECT_EQ(document_format(std::string("{\"format\": \"shadowgen-scene/1\"\0}", 32), "d"),
            kSceneFormat);
}

// A device reads without end (/dev/zero) or not at all: refused before a byte is read,
// saying what it is.
TEST(ReadDocument, ADeviceIsNotARegularFile) {
  for (const char* device : {"/dev/zero", "/dev/null"}) {
    try {
      (void)read_document(device);
      ADD_FAILURE() << "no error for " << device;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), device);
      EXPECT_EQ(e.problem(), "is not a regular file (a character device)");
    }
  }
}

// A bound on the bytes read: a regular file over it is refused by its size, and a stream
// once it has given more.
TEST(ReadTextFile, MoreThanTheBoundIsRefusedNamingTheFile) {
  const test::TempFolder folder("shadowgen-document");
  const std::filesystem::path path = folder.write("ten.txt", "0123456789");
  EXPECT_EQ(read_text_file(path, "text file", 10), "0123456789");
  try {
    (void)read_text_file(path, "text file", 9);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ": is larger than a text file can be (more than 9 bytes)");
  }
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
