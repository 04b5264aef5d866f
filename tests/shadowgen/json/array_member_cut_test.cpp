// Cutting a document at one top-level array member (shadowgen/json/array_member_cut.h):
// the elements' texts exactly as written, the rest with the array emptied, and no cut
// where the structure does not scan.

#include "shadowgen/json/array_member_cut.h"

#include <gtest/gtest.h>

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

// A bracket inside an element that does not match is the element's parse to refuse: the
// cut keeps the element whole up to the bracket that closes its depth.
TEST(ArrayMemberCut, LeavesAnElementsOwnMistakesToItsParse) {
  const std::optional<ArrayMemberCut> cut =
      cut_array_member(R"({"polygons": [[1}, tru, {"a" 1}]})", "polygons");
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(elements_of(*cut), (std::vector<std::string>{"[1}", "tru", "{\"a\" 1}"}));
}

TEST(ArrayMemberCut, RefusesWhatDoesNotScanOrHoldsNoSuchArray) {
  for (const std::string_view text : {
           R"([{"polygons": [1]}])",              // not an object
           R"({"lights": [1]})",                  // no such member
           R"({"polygons": {"a": 1}})",           // not an array
           R"({"polygon\u0073": [1]})",           // the key written with an escape
           R"({"polygons": [1 2]})",              // no comma between elements
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
