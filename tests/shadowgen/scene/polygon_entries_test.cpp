// A scene's polygons read in parallel chunks (shadowgen/scene/detail/polygon_entries.h,
// through parse_scene): the same faces, warnings and first error as reading them one by
// one, on any number of threads.

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/scene/scene_reader.h"

namespace shadowgen {
namespace {

constexpr std::size_t kPolygons = 1500;  // several chunks of polygons

// Polygon i: a unit square at x = 2i, "p<i>"; `odd(i)` may replace its text.
template <class Odd>
std::string city_scene(Odd&& odd, const std::string& after = "") {
  std::string text = R"({"format": "shadowgen-scene/1", "polygons": [)";
  for (std::size_t i = 0; i < kPolygons; ++i) {
    if (i > 0) text += ",\n";
    const std::string x = std::to_string(2 * i), x1 = std::to_string(2 * i + 1);
    std::string polygon = R"({"id": "p)" + std::to_string(i) + R"(", "outer": [[)" + x + ",0,0],[" +
                          x1 + ",0,0],[" + x1 + ",1,0],[" + x + ",1,0]]}";
    odd(i, polygon);
    text += polygon;
  }
  return text + R"(], "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}])" +
         after + "}";
}

std::string plain_scene() {
  return city_scene([](std::size_t, std::string&) {});
}

ReadResult read_on(int threads, const std::string& text) {
  tbb::task_arena arena(threads);
  return arena.execute([&] { return parse_scene(text, "city.json"); });
}

std::string error_on(int threads, const std::string& text) {
  try {
    (void)read_on(threads, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ScenePolygonsInParallel, GiveEveryFaceInFileOrderOnAnyThreads) {
  for (const int threads : {1, 2, 4}) {
    const ReadResult read = read_on(threads, plain_scene());
    ASSERT_EQ(read.scene.faces.size(), kPolygons);
    for (std::size_t i = 0; i < kPolygons; ++i) {
      const Face& face = read.scene.faces[i];
      ASSERT_EQ(face.id, "p" + std::to_string(i));
      ASSERT_EQ(face.parts.size(), 1u);
      ASSERT_EQ(face.parts[0].outer.size(), 4u);
      EXPECT_EQ(face.parts[0].outer[2], glm::dvec3(static_cast<double>(2 * i + 1), 1, 0));
    }
    EXPECT_TRUE(read.warnings.empty());
  }
}

// Unknown keys warn in file order, before the faces' own warnings summed by kind.
TEST(ScenePolygonsInParallel, WarnInFileOrder) {
  const std::string text = city_scene([](std::size_t i, std::string& polygon) {
    if (i == 3 || i == 1200) polygon.insert(polygon.size() - 1, R"(, "colour": "red")");
    if (i == 700) polygon = R"({"id": "p700", "outer": [[0,5,0],[1,5,0],[2,5,0]]})";
  });
  const std::vector<std::string> expected = {
      "city.json: face 'p3': polygons[3]: unknown key 'colour'",
      "city.json: face 'p1200': polygons[1200]: unknown key 'colour'",
      "city.json: face 'p700': zero area (collinear vertices): kept, with area 0",
  };
  for (const int threads : {1, 2, 4}) EXPECT_EQ(read_on(threads, text).warnings, expected);
}

// The first polygon's problem in file order, whichever thread met which first.
TEST(ScenePolygonsInParallel, NameTheFirstBadPolygonInFileOrder) {
  const std::string text = city_scene([](std::size_t i, std::string& polygon) {
    if (i == 1400) polygon = R"({"id": "p1400", "outer": [[0,0,0],[1,0,0]]})";
    if (i == 900) polygon = R"({"id": "p900", "outer": [[0,0,0],[1,0,0],[1,1,0]], "holes": 3})";
  });
  for (const int threads : {1, 2, 4}) {
    EXPECT_EQ(error_on(threads, text),
              "city.json: face 'p900': polygons[900].holes: expected an array, found a number");
  }
}

// A clash of ids is found once every polygon is read, and named where reading in order
// meets it: before a later polygon's own problem, after an earlier one's.
TEST(ScenePolygonsInParallel, NameAClashOfIdsWhereReadingInOrderMeetsIt) {
  const std::string text = city_scene([](std::size_t i, std::string& polygon) {
    if (i == 800) polygon.replace(polygon.find("p800"), 4, "p12");
    if (i == 1300) polygon = R"({"id": "p1300", "outer": 7})";
  });
  for (const int threads : {1, 2, 4}) {
    EXPECT_EQ(error_on(threads, text),
              "city.json: polygons[800].id: duplicate id 'p12' (already used by polygon 'p12')");
  }
}

// The whole document is JSON before any polygon is read: a syntax error after the
// polygons, or a key given twice, comes before every polygon's problem.
TEST(ScenePolygonsInParallel, PutTheDocumentsSyntaxBeforeAnyPolygon) {
  const auto bad_polygon = [](std::size_t i, std::string& polygon) {
    if (i == 10) polygon = R"({"id": "p10", "outer": 7})";
  };
  for (const int threads : {1, 2}) {
    EXPECT_EQ(error_on(threads, city_scene(bad_polygon, R"(, "views": [,])")),
              "city.json: line 1500, column 158: invalid JSON: syntax error while parsing value - "
              "unexpected ','; expected '[', '{', or a literal");
    EXPECT_EQ(error_on(threads, city_scene(bad_polygon, R"(, "polygons": [])")),
              "city.json: the key 'polygons' is given twice (a key may appear once in an object)");
    EXPECT_EQ(error_on(threads, city_scene([](std::size_t i, std::string& polygon) {
                         if (i == 1000) polygon.insert(polygon.size() - 1, R"(, "id": "again")");
                         if (i == 10) polygon = R"({"id": "p10", "outer": 7})";
                       })),
              "city.json: polygons[1000] ('p1000'): the key 'id' is given twice (a key may "
              "appear once in an object)");
  }
}

}  // namespace
}  // namespace shadowgen
