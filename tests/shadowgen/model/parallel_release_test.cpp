#include "shadowgen/model/parallel_release.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <string>
#include <utility>
#include <vector>

namespace shadowgen {
namespace {

hsr::Polygon3 triangle(double x) { return {{{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}}, {}}; }

// 1,000 faces of two parts each, lit under lights 0 and 2 of three (light 1 not kept):
// released on one thread and on four, every face and kept list is left empty, the table's
// shape and the sun paths as they were.
TEST(ParallelRelease, EmptiesEveryFaceAndKeptListOnAnyThreads) {
  for (const int threads : {1, 4}) {
    Scene lights_only;
    lights_only.lights.resize(3);
    ShadowedScene shadowed(std::move(lights_only), LitTable(0, 3, {true, false, true}));
    shadowed.sun_paths.resize(1);
    for (std::size_t f = 0; f < 1000; ++f) {
      Face face;
      face.id = "face number " + std::to_string(f);
      face.parts = {triangle(0.0), triangle(2.0)};
      shadowed.add_face(std::move(face));
      shadowed.lit_at(f, 0).push_back({0, triangle(0.0)});
      shadowed.lit_at(f, 2).push_back({1, triangle(2.0)});
    }
    tbb::task_arena arena(threads);
    arena.execute([&] { release_faces_in_parallel(shadowed); });
    ASSERT_EQ(shadowed.scene().faces.size(), 1000u) << threads;
    EXPECT_EQ(shadowed.lit().size(), 1000u) << threads;
    EXPECT_EQ(shadowed.sun_paths.size(), 1u) << threads;
    for (std::size_t f = 0; f < 1000; ++f) {
      EXPECT_TRUE(shadowed.scene().faces[f].id.empty()) << f;
      EXPECT_TRUE(shadowed.scene().faces[f].parts.empty()) << f;
      for (std::size_t l = 0; l < 3; ++l) {
        EXPECT_TRUE(shadowed.lit().at(f, l).empty()) << f;
      }
    }
  }
}

}  // namespace
}  // namespace shadowgen
