// Writing JSON (shadowgen/json/json_writer.h): the layout, and numbers that read back to
// the same double bit for bit.

#include "shadowgen/json/json_writer.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowgen/json/json_reader.h"

namespace shadowgen {
namespace {

using Layout = JsonWriter::Layout;

TEST(JsonWriter, LinesAndInlineContainers) {
  JsonWriter out;
  out.begin_object(Layout::kLines).key("format").value("x/1");
  out.key("items").begin_array(Layout::kLines);
  out.begin_object().key("id").value("a").key("p").value(glm::dvec3(1, -0.0, 0.5)).end_object();
  out.begin_object().key("id").value("b").key("n").value(std::uint64_t{3}).end_object();
  out.end_array();
  out.key("empty").begin_array(Layout::kLines).end_array();
  out.key("map").begin_object(Layout::kLines);
  out.key("k").begin_array(Layout::kLines).value(1e-300).end_array();
  out.end_object();
  out.key("none").begin_object().end_object();
  out.end_object();
  EXPECT_EQ(out.take(), R"({
  "format": "x/1",
  "items": [
    {"id":"a","p":[1.0,-0.0,0.5]},
    {"id":"b","n":3}
  ],
  "empty": [],
  "map": {
    "k": [
      1e-300
    ]
  },
  "none": {}
}
)");
}

TEST(JsonWriter, StringsAreEscaped) {
  JsonWriter out;
  out.begin_array().value("say \"hi\"\n\\").value("caf\xc3\xa9").value("bad \xff byte").end_array();
  EXPECT_EQ(out.take(), "[\"say \\\"hi\\\"\\n\\\\\",\"caf\xc3\xa9\",\"bad \xef\xbf\xbd byte\"]\n");
}

TEST(JsonWriter, NonFiniteNumbersAreRefused) {
  JsonWriter out;
  out.begin_array();
  EXPECT_THROW(out.value(std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(out.value(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// Every double written reads back (JsonValue::number) to the same bits.
void expect_round_trip(const std::vector<double>& values) {
  JsonWriter out;
  out.begin_array();
  for (const double v : values) out.value(v);
  out.end_array();
  const std::string text = out.take();
  const JsonDocument document(text, {"numbers.json"});
  const JsonArray back = document.root().array();
  ASSERT_EQ(back.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(bits(back.at(i).number()), bits(values[i])) << values[i] << " in " << text;
  }
}

TEST(JsonWriter, ExtremeDoublesRoundTrip) {
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kMin = std::numeric_limits<double>::min();
  constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();
  expect_round_trip({-0.0,
                     0.0,
                     0.1,
                     -0.1,
                     1e-300,
                     -1e-300,
                     kDenormMin,
                     -kDenormMin,
                     kMin,
                     kMin / 3.0,
                     kMax,
                     -kMax,
                     1.0 / 3.0,
                     2.0 / 3.0,
                     1e21,
                     1e22,
                     123456789012345678.0,
                     9007199254740993.0,
                     0.30000000000000004,
                     5e-324 * 12345.0,
                     1e308,
                     std::nextafter(1.0, 2.0),
                     std::nextafter(1.0, 0.0),
                     1e8 + 0.1,
                     28.0});
}

TEST(JsonWriter, RandomBitPatternsRoundTrip) {
  std::mt19937_64 random(20240611);
  std::vector<double> values;
  while (values.size() < 3000) {
    const double v = std::bit_cast<double>(random());
    if (std::isfinite(v)) values.push_back(v);
  }
  expect_round_trip(values);
}

// With a sink the text arrives in pieces of about a mebibyte (a piece is passed on at the
// first value after it reaches that size), and together they are the document take()
// gives.
TEST(JsonWriter, ASinkReceivesTheDocumentInPieces) {
  auto write = [](JsonWriter& out) {
    out.begin_object(Layout::kLines).key("numbers").begin_array(Layout::kLines);
    for (int i = 0; i < 200000; ++i) out.value(i * 0.1);
    out.end_array().key("end").value("here").end_object();
  };
  JsonWriter whole;
  write(whole);
  const std::string expected = whole.take();
  std::vector<std::string> pieces;
  JsonWriter streamed([&pieces](std::string_view piece) { pieces.emplace_back(piece); });
  write(streamed);
  streamed.finish();
  ASSERT_GE(pieces.size(), 3u);
  std::string joined;
  for (const std::string& piece : pieces) {
    EXPECT_LE(piece.size(), (std::size_t{1} << 20) + 64);
    joined += piece;
  }
  EXPECT_EQ(joined, expected);
  // Every piece but the last is a whole mebibyte at least.
  EXPECT_LE(pieces.size() - 1, expected.size() >> 20);
}

}  // namespace
}  // namespace shadowgen
