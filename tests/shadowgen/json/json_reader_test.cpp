// The JSON layer the scene and database readers share (shadowgen/json/json_reader.h):
// typed reads that fail naming the file, the face and the path; unknown keys reported
// with the key probably meant; a key given twice refused while parsing.

#include "shadowgen/json/json_reader.h"

#include <gtest/gtest.h>

#include <istream>
#include <streambuf>
#include <string>
#include <vector>

#include "shadowgen/json/detail/json_parse.h"
#include "shadowgen/json/detail/key_suggestion.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen {
namespace {

// The message of the InputError `read` throws, or "(no error)".
template <class Read>
std::string error_of(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string parse_error(const std::string& text) {
  return error_of([&] { const JsonDocument document(text, {"in.json"}); });
}

TEST(JsonReader, TypedReadsNameThePathOfWhatIsWrong) {
  const JsonDocument document(R"({"lights": [{"id": "lamp", "range": {"end": "far"}},
                                             {"id": "sun", "direction": [0, 1]}],
                                  "n": 2.5, "i": 3, "neg": -1})",
                              {"in.json"});
  JsonObject top = document.root().object();
  const JsonArray lights = top.get("lights").array();
  ASSERT_EQ(lights.size(), 2u);
  JsonObject lamp = lights.at(0).object();
  EXPECT_EQ(lamp.get("id").string(), "lamp");
  lamp.name("light 'lamp'", "lamp");
  JsonObject range = lamp.get("range").object();
  EXPECT_EQ(range.value().path(), "lights[0] ('lamp').range");
  EXPECT_EQ(error_of([&] { (void)range.get("end").number(); }),
            "in.json: light 'lamp': lights[0] ('lamp').range.end: expected a number, found a "
            "string");
  EXPECT_EQ(error_of([&] { (void)range.get("exponent"); }),
            "in.json: light 'lamp': lights[0] ('lamp').range: missing 'exponent'");
  JsonObject sun = lights.at(1).object();
  sun.for_face("sun");
  EXPECT_EQ(error_of([&] { (void)sun.get("direction").vec3(); }),
            "in.json: face 'sun': lights[1].direction: expected an array of 3 numbers, found an "
            "array of 2");
  EXPECT_EQ(top.get("n").number(), 2.5);
  EXPECT_EQ(top.get("i").index(), 3u);
  EXPECT_EQ(error_of([&] { (void)top.get("neg").index(); }),
            "in.json: neg: expected a non-negative integer, found a number");
  EXPECT_EQ(error_of([&] { (void)top.get("n").array(); }),
            "in.json: n: expected an array, found a number");
}

TEST(JsonReader, PointListsNameTheBadPoint) {
  const JsonDocument document(R"({"outer": [[0, 0, 0], [1, 0, 0], [1, null, 0]]})", {"in.json"});
  JsonObject top = document.root().object();
  EXPECT_EQ(error_of([&] { (void)top.get("outer").vec3_list(); }),
            "in.json: outer[2][1]: expected a number, found null");
}

TEST(JsonReader, UnknownKeysWarnWithTheKeyMeantOrFailWhenStrict) {
  const std::string text = R"({"rnage": 1, "range": 2, "colour": 3})";
  std::vector<std::string> warnings;
  {
    const JsonDocument document(text, {"in.json", false, &warnings});
    JsonObject top = document.root().object();
    (void)top.find("range");
    (void)top.find("holes");  // asked for, absent: still a candidate for "did you mean"
    top.finish();
  }
  EXPECT_EQ(warnings,
            (std::vector<std::string>{"in.json: unknown key 'colour'",
                                      "in.json: unknown key 'rnage' (did you mean 'range'?)"}));

  const JsonDocument strict(text, {"in.json", true, &warnings});
  JsonObject top = strict.root().object();
  (void)top.find("range");
  EXPECT_EQ(error_of([&] { top.finish(); }), "in.json: unknown key 'colour'");
}

TEST(JsonReader, EntriesOfAMapAreAllKnown) {
  std::vector<std::string> warnings;
  const JsonDocument document(R"({"lit": {"sun": [], "lamp": []}})", {"in.json", true, &warnings});
  JsonObject lit = document.root().object().get("lit").object();
  const auto entries = lit.entries();
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].first, "lamp");
  EXPECT_EQ(entries[0].second.path(), "lit['lamp']");
  lit.finish();
  EXPECT_TRUE(warnings.empty());
}

TEST(JsonReader, AKeyGivenTwiceIsRefusedWithItsPath) {
  EXPECT_EQ(parse_error(R"({"a": 1, "a": 2})"),
            "in.json: the key 'a' is given twice (a key may appear once in an object)");
  EXPECT_EQ(
      parse_error(R"({"lights": [{"id": "x"}, {"id": "lamp", "range": {"end": 1, "end": 2}}]})"),
      "in.json: lights[1] ('lamp').range: the key 'end' is given twice (a key may appear "
      "once in an object)");
  EXPECT_EQ(
      parse_error(R"({"faces": [[{"k": 1}], [{"k": 1, "k": 1}]]})"),
      "in.json: faces[1][0]: the key 'k' is given twice (a key may appear once in an object)");
  // The same key in different objects is fine.
  EXPECT_EQ(parse_error(R"({"a": {"k": 1}, "b": {"k": 1}, "c": [{"k": 1}, {"k": 2}]})"),
            "(no error)");
}

// Nesting is limited (json::detail::kMaxJsonDepth): a file of nothing but '[' is refused at
// the limit, with the path of the innermost container, not built to its end (20 million
// of them once took 2.4 GB).
TEST(JsonReader, NestingBeyondTheLimitIsRefusedAtTheLimit) {
  std::string at_limit = R"({"a": )";
  for (std::size_t i = 1; i < json::detail::kMaxJsonDepth; ++i) at_limit += '[';
  at_limit += std::string(json::detail::kMaxJsonDepth - 1, ']') + "}";
  EXPECT_EQ(parse_error(at_limit), "(no error)");

  const std::string deep = R"({"faces": [{"id": "w", "k": )" + std::string(20'000'000, '[');
  const std::string message = parse_error(deep);
  EXPECT_EQ(message.rfind("in.json: faces[0] ('w').k[0][0]", 0), 0u) << message.substr(0, 200);
  EXPECT_NE(message.find(": arrays and objects nested deeper than 64 levels (the limit)"),
            std::string::npos)
      << message.substr(0, 200);
  EXPECT_LT(message.size(), 1000u);
}

// nlohmann's parser stops at a NUL byte as at the end of the text: what followed it was
// ignored, and a scene with junk after a NUL byte read as valid.
TEST(JsonReader, ANulByteAnywhereIsRefusedWhereItIs) {
  using namespace std::string_literals;
  EXPECT_EQ(parse_error("{\"a\": 1}\n\0garbage"s),
            "in.json: line 2, column 1: invalid JSON: a NUL byte (JSON text has none; is this a "
            "binary file?)");
  EXPECT_EQ(parse_error("{\"a\": \"x\0y\"}"s),
            "in.json: line 1, column 9: invalid JSON: a NUL byte (JSON text has none; is this a "
            "binary file?)");
}

// A text handed out 100 bytes at a time, counting the bytes handed out; it rewinds to its
// start, as a file (or a gzip file inflated as it is read) does.
class CountingText : public std::streambuf {
 public:
  explicit CountingText(std::string text) : text_(std::move(text)) {}
  std::size_t handed_out = 0;

 protected:
  int_type underflow() override {
    if (at_ >= text_.size()) return traits_type::eof();
    const std::size_t n = std::min<std::size_t>(100, text_.size() - at_);
    setg(text_.data() + at_, text_.data() + at_, text_.data() + at_ + n);
    at_ += n;
    handed_out += n;
    return traits_type::to_int_type(*gptr());
  }
  pos_type seekpos(pos_type at, std::ios_base::openmode) override {
    if (at != pos_type(0)) return pos_type(off_type(-1));
    at_ = 0;
    setg(nullptr, nullptr, nullptr);
    return at;
  }
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
    if (off == 0 && dir == std::ios_base::beg) return seekpos(0, std::ios_base::in);
    return pos_type(off_type(-1));
  }

 private:
  std::string text_;
  std::size_t at_ = 0;
};

// The message of what a streamed parse of `text` throws, or "(no error)".
std::string streamed_parse_error(const std::string& text) {
  CountingText source(text);
  std::istream in(&source);
  return error_of(
      [&] { JsonDocument(in, {"in.json"}, "faces", [](auto&, auto&) { return true; }); });
}

// A file is read once as it is parsed (a gzip database inflated once), not once to look for
// NUL bytes and again to parse.
TEST(JsonReader, AStreamedFileIsReadOnce) {
  std::string text = "{\"format\": \"x\", \"faces\": [";
  for (int i = 0; i < 1000; ++i) text += (i ? ", " : "") + std::string("{\"id\": \"f\"}");
  text += "]}\n";
  CountingText source(text);
  std::istream in(&source);
  int faces = 0;
  const JsonDocument document(in, {"in.json"}, "faces", [&faces](auto&, auto&) {
    ++faces;
    return true;
  });
  EXPECT_EQ(faces, 1000);
  EXPECT_EQ(source.handed_out, text.size());
}

TEST(JsonReader, ANulByteInAStreamedFileIsRefusedWhereItIs) {
  using namespace std::string_literals;
  const std::string nul = ": invalid JSON: a NUL byte (JSON text has none; is this a binary file?)";
  EXPECT_EQ(streamed_parse_error("{\"a\": 1}\n\0garbage"s), "in.json: line 2, column 1" + nul);
  EXPECT_EQ(streamed_parse_error("{\"a\": 1}\0"s), "in.json: line 1, column 9" + nul);
  EXPECT_EQ(streamed_parse_error("{\"a\": \"x\0y\"}"s), "in.json: line 1, column 9" + nul);
  // Where the syntax fails before it, the NUL is still what is said.
  EXPECT_EQ(streamed_parse_error("{\"a\": ]" + std::string(300, ' ') + "\0"s),
            "in.json: line 1, column 308" + nul);
  EXPECT_EQ(streamed_parse_error("{\"a\": ]}"),
            "in.json: line 1, column 7: invalid JSON: syntax error while parsing value - "
            "unexpected ']'; expected '[', '{', or a literal");
}

TEST(JsonReader, SyntaxErrorsAndOverflowsAreLocated) {
  EXPECT_EQ(parse_error("{\n  \"a\": [1,,]\n}"),
            "in.json: line 2, column 11: invalid JSON: syntax error while parsing value - "
            "unexpected ','; expected '[', '{', or a literal");
  EXPECT_EQ(parse_error("{\"a\":\n [1, -1e999]}"),
            "in.json: line 2, column 6: invalid JSON: the number -1e999 is out of the range of a "
            "double");
  EXPECT_EQ(parse_error(""),
            "in.json: line 1, column 1: invalid JSON: syntax error while parsing value - "
            "unexpected end of input; expected '[', '{', or a literal");
}

TEST(KeySuggestion, TyposAreCloseOtherWordsAreNot) {
  const std::vector<std::string> known = {"id", "outer", "holes", "range", "transform", "up"};
  EXPECT_EQ(json::detail::closest_key("rnage", known), "range");         // two letters swapped
  EXPECT_EQ(json::detail::closest_key("tranform", known), "transform");  // one left out
  EXPECT_EQ(json::detail::closest_key("hole", known), "holes");
  EXPECT_EQ(json::detail::closest_key("Outer", known), "outer");
  EXPECT_EQ(json::detail::closest_key("colour", known), std::nullopt);
  EXPECT_EQ(json::detail::closest_key("ip", known), "id");  // one edit: the first of equals
  EXPECT_EQ(json::detail::closest_key("xy", known), std::nullopt);
  EXPECT_EQ(json::detail::edit_distance("abc", "acb"), 1u);
  EXPECT_EQ(json::detail::edit_distance("", "abc"), 3u);
}

}  // namespace
}  // namespace shadowgen
