// The thread count changes nothing but the time, from end to end: a scene's polygons read
// in parallel, its shadows, the report's rows and the database written are the same bytes
// on one thread as on several, and a scene with mistakes gets the same first error.

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "cli_harness.h"

namespace shadowgen::test {
namespace {

class CliThreads : public CliFolderTest<> {
 protected:
  CliThreads() : CliFolderTest("threads") {}
};

// A small city: `lots` × `lots` lots, each a ground square of side 10 and a box building
// on it (four walls and a roof), under a low sun: several chunks of polygons and of rows.
// `odd(i, text)` may replace polygon i's text.
template <class Odd>
std::string city(int lots, Odd&& odd) {
  std::vector<std::string> polygons;
  const auto n = [](double v) { return std::to_string(v); };
  const auto point = [&](double x, double y, double z) {
    return "[" + n(x) + "," + n(y) + "," + n(z) + "]";
  };
  for (int i = 0; i < lots; ++i) {
    for (int j = 0; j < lots; ++j) {
      const double x = 10.0 * i, y = 10.0 * j, h = 3.0 + (i * 7 + j * 3) % 11;
      const double a = x + 2 + (i + j) % 3, b = x + 7, c = y + 3, d = y + 6 + (i * j) % 3;
      const std::string lot = "lot" + std::to_string(i) + "_" + std::to_string(j);
      const auto add = [&](const std::string& id, const std::vector<std::string>& outer) {
        std::string text = R"({"id": ")" + lot + "." + id + R"(", "outer": [)";
        for (std::size_t k = 0; k < outer.size(); ++k) text += (k ? "," : "") + outer[k];
        polygons.push_back(text + "]}");
      };
      add("ground",
          {point(x, y, 0), point(x + 10, y, 0), point(x + 10, y + 10, 0), point(x, y + 10, 0)});
      add("roof", {point(a, c, h), point(b, c, h), point(b, d, h), point(a, d, h)});
      add("south", {point(a, c, 0), point(b, c, 0), point(b, c, h), point(a, c, h)});
      add("east", {point(b, c, 0), point(b, d, 0), point(b, d, h), point(b, c, h)});
      add("north", {point(b, d, 0), point(a, d, 0), point(a, d, h), point(b, d, h)});
      add("west", {point(a, d, 0), point(a, c, 0), point(a, c, h), point(a, d, h)});
    }
  }
  std::string text = R"({"format": "shadowgen-scene/1", "polygons": [)";
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    odd(i, polygons[i]);
    text += (i ? ",\n" : "") + polygons[i];
  }
  return text + R"(], "lights": [{"id": "sun", "type": "directional",
                                  "direction": [-0.66, -0.38, -0.64]},
                                 {"id": "lamp", "type": "point", "position": [52, 47, 5]}]})";
}

// Gives the polygon whose text is `polygon` the id `id`.
void rename(std::string& polygon, const std::string& id) {
  const std::size_t first = polygon.find("\"id\": \"") + 7;
  polygon.replace(first, polygon.find('"', first) - first, id);
}

std::string city(int lots) {
  return city(lots, [](std::size_t, std::string&) {});
}

TEST_F(CliThreads, ReportsAndDatabasesAreTheSameBytesOnAnyThreads) {
  const std::string scene = write("city.json", city(20)).string();  // 2,400 faces
  for (const std::string format : {"csv", "json", "table"}) {
    std::vector<std::string> outputs;
    for (const std::string threads : {"1", "2"}) {
      const Outcome report = run({"report", scene, "--format", format, "--threads", threads});
      ASSERT_EQ(report.code, 0) << report.err;
      outputs.push_back(report.out);
    }
    EXPECT_GT(outputs[0].size(), format == "table" ? 1000u : 2400u * 20) << format;
    EXPECT_EQ(outputs[1], outputs[0]) << format;
    if (format != "csv") continue;
    // Rows face by face in file order, each face's lights in scene order.
    const std::vector<ReportRow> rows = parse_report(outputs[0]);
    ASSERT_EQ(rows.size(), 4800u);
    const char* kinds[] = {"ground", "roof", "south", "east", "north", "west"};
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const std::size_t face = k / 2, lot = face / 6;
      ASSERT_EQ(rows[k].face, "lot" + std::to_string(lot / 20) + "_" + std::to_string(lot % 20) +
                                  "." + kinds[face % 6]);
      ASSERT_EQ(rows[k].light, k % 2 == 0 ? "sun" : "lamp");
    }
  }
  std::vector<std::string> databases;
  for (const std::string threads : {"1", "2"}) {
    const std::string db = (dir_ / ("city." + threads + ".db.json")).string();
    const Outcome generate = run({"generate", scene, "-o", db, "--threads", threads});
    ASSERT_EQ(generate.code, 0) << generate.err;
    databases.push_back(contents(db));
  }
  EXPECT_EQ(databases[1], databases[0]);
}

// The first mistake in file order, whichever thread read it: a polygon's own problem
// before a later clash of ids, a clash before a later polygon's problem.
TEST_F(CliThreads, AScenesFirstMistakeIsTheSameOnAnyThreads) {
  const fs::path bad = write("bad.json", city(20, [](std::size_t i, std::string& polygon) {
                               if (i == 2000) polygon = R"({"id": "late", "outer": [[0,0,0]]})";
                               if (i == 1500) rename(polygon, "lot0_1.west");
                               if (i == 900) polygon.insert(polygon.size() - 1, R"(, "holes": {})");
                             }));
  const fs::path clash = write("clash.json", city(20, [](std::size_t i, std::string& polygon) {
                                 if (i == 2000) polygon = R"({"id": "late", "outer": 7})";
                                 if (i == 1500) rename(polygon, "lot0_1.roof");
                               }));
  for (const std::string threads : {"1", "2"}) {
    const Outcome first = run({"report", bad.string(), "--threads", threads});
    EXPECT_EQ(first.code, 1);
    EXPECT_EQ(first.err, "shadowgen: " + bad.string() +
                             ": face 'lot7_10.ground': polygons[900].holes: expected an array, "
                             "found an object\n");
    const Outcome second = run({"report", clash.string(), "--threads", threads});
    EXPECT_EQ(second.code, 1);
    EXPECT_EQ(second.err, "shadowgen: " + clash.string() +
                              ": polygons[1500].id: duplicate id 'lot0_1.roof' (already used by "
                              "polygon 'lot0_1.roof')\n");
    EXPECT_EQ(files(), (std::vector<std::string>{"bad.json", "clash.json"}));
  }
}

}  // namespace
}  // namespace shadowgen::test
