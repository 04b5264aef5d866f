// Cutting a document at one top-level array member (shadowgen/json/array_member_cut.h):
// the elements' texts exactly as written, the rest with the array emptied, and no cut
// where the structure does not scan.

#include "shadowgen/json/array_member_cut.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowgen {
namespace {

std::vector<std::string> elements_of(const ArrayMemberCut& cut) {
  return {cut.elements.begin(), cut.elements.end()};
}

TEST(ArrayMemberCut, GivesEachElementAsWrittenAndTheRestWithTheArrayEmptied) {
  const std::string text =
      "{\"format\": \"f\", \"a\": {\"polygons\": [9]},\n \"polygons\" :\t[ {\"id\": \"x]},\\\"\","
      " \"v\": [1, [2]]} ,\"s,]\\\\\" ,\r\n-1.5e3,[[]], null ], \"lights\": []}";
  const std::optional<ArrayMemberCut> cut = cut_array_member(text, "polygons");
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(elements_of(*cut), (std::vector<std::string>{"{\"id\": \"x]},\\\"\", \"v\": [1, [2]]}",
                                                         "\"s,]\\\\\"", "-1.5e3", "[[]]", "null"}));
  EXPECT_EQ(
      cut->rest,
      "{\"format\": \"f\", \"a\": {\"polygons\": [9]},\n \"polygons\" :\t[], \"lights\": []}");
}

// Bytes of any value inside strings (UTF-8, and the bytes above 0x7f in general) are
// passed over as characters of the string, brackets and quotes beside them seen as such.
TEST(ArrayMemberCut, PassesOverBytesOfAnyValueInStrings) {
  const std::string text =
      "{\"\xC3\xA9t\xC3\xA9\": 1, \"polygons\": [{\"id\": \"\xFF]\\\\\", \"x\": \"\x80{\"}, "
      "\"\xE2\x82\xAC\\\"]\"]}";
  const std::optional<ArrayMemberCut> cut = cut_array_member(text, "polygons");
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(elements_of(*cut),
            (std::vector<std::string>{"{\"id\": \"\xFF]\\\\\", \"x\": \"\x80{\"}",
                                      "\"\xE2\x82\xAC\\\"]\""}));
  EXPECT_EQ(cut->rest, "{\"\xC3\xA9t\xC3\xA9\": 1, \"polygons\": []}");
}

TEST(ArrayMemberCut, AnEmptyArrayHasNoElements) {
  const std::optional<ArrayMemberCut> cut =
      cut_array_member(R"({"polygons": [ ], "format": "f"})", "polygons");
  ASSERT_TRUE(cut.has_value());
  EXPECT_TRUE(cut->elements.empty());
  EXPECT_EQ(cut->rest, R"({"polygons": [], "format": "f"})");
}

// The first member of that name is cut; the second stays in the rest, where the parse
// of the rest refuses the key given twice.
TEST(ArrayMemberCut, CutsTheFirstOfTwoMembersOfThatName) {
  const std::optional<ArrayMemberCut> cut =
      cut_array_member(R"({"polygons": 5, "polygons": [1, 2]})", "polygons");
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(elements_of(*cut), (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(cut->rest, R"({"polygons": 5, "polygons": []})");
}

// A bracket inside an element that does not match, or two values between two commas, is
// the element's parse to refuse: the cut keeps the element whole up to the bracket that
// closes its depth, or the next comma.
TEST(ArrayMemberCut, LeavesAnElementsOwnMistakesToItsParse) {
  const std::optional<ArrayMemberCut> cut =
      cut_array_member(R"({"polygons": [[1}, tru, {"a" 1}, 1 2, "a" [3]]})", "polygons");
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(elements_of(*cut),
            (std::vector<std::string>{"[1}", "tru", "{\"a\" 1}", "1 2", "\"a\" [3]"}));
}

// An array of many chunks' length (the scan's chunks are 256 KiB, scanned in parallel):
// strings that hold brackets, commas and escaped quotes, and runs of backslashes, cross
// the chunks' edges wherever they fall; the elements are the same on one thread and on
// four, each exactly as written.
TEST(ArrayMemberCut, CutsAnArrayOfManyChunksTheSameOnAnyThreads) {
  std::vector<std::string> expected;
  std::string text = R"({"format": "f", "polygons": [)";
  for (int i = 0; i < 40000; ++i) {
    std::string element =
        i % 3 == 0 ? R"({"id": "p)" + std::to_string(i) + R"(", "outer": [[0, 1, 2], [3, 4, 5]]})"
        : i % 3 == 1
            ? R"({"id": "q)" + std::to_string(i) + R"(,]}\"[{\\", "x": ["a\"", {"b": []}]})"
            : R"("s)" + std::string(static_cast<std::size_t>(i % 37), '\\') +
                  std::string(static_cast<std::size_t>(i % 37), '\\') + R"(]\"")";
    text += (i == 0 ? "" : i % 5 == 0 ? " ,\n  " : ",") + element;
    expected.push_back(std::move(element));
  }
  text += R"(], "lights": []})";
  ASSERT_GT(text.size(), std::size_t{4} << 18);
  for (const int threads : {1, 4}) {
    tbb::task_arena arena(threads);
    const std::optional<ArrayMemberCut> cut =
        arena.execute([&] { return cut_array_member(text, "polygons"); });
    ASSERT_TRUE(cut.has_value()) << threads;
    EXPECT_EQ(elements_of(*cut), expected) << threads;
    EXPECT_EQ(cut->rest, R"({"format": "f", "polygons": [], "lights": []})") << threads;
  }
}

TEST(ArrayMemberCut, RefusesWhatDoesNotScanOrHoldsNoSuchArray) {
  for (const std::string_view text : {
           R"([{"polygons": [1]}])",              // not an object
           R"({"lights": [1]})",                  // no such member
           R"({"polygons": {"a": 1}})",           // not an array
           R"({"polygon\u0073": [1]})",           // the key written with an escape
           R"({"polygons": [1,, 2]})",            // an empty element
           R"({"polygons": [1, 2,]})",            // a comma before the end
           R"({"polygons": [1, 2)",               // the array not closed
           R"({"polygons": ["open, 2]})",         // a string not closed
           R"({"lights" [1], "polygons": [1]})",  // no colon before it
           R"({"lights": [1] "polygons": [1]})",  // no comma before it
           "\xEF\xBB\xBF{\"polygons\": [1]}",     // a byte order mark first
       }) {
    EXPECT_FALSE(cut_array_member(text, "polygons").has_value()) << text;
  }
}

}  // namespace
}  // namespace shadowgen
