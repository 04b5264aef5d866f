#include "shadowgen/scene/detail/distinct_ids.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <string>
#include <vector>

namespace shadowgen::scene::detail {
namespace {

std::vector<Face> faces_with_ids(const std::vector<std::string>& ids) {
  std::vector<Face> faces(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) faces[i].id = ids[i];
  return faces;
}

TEST(DistinctIds, SmallSets) {
  EXPECT_TRUE(ids_distinct({}));
  EXPECT_TRUE(ids_distinct(faces_with_ids({"a"})));
  EXPECT_TRUE(ids_distinct(faces_with_ids({"b", "a", "ab", "A"})));
  EXPECT_FALSE(ids_distinct(faces_with_ids({"b", "a", "b"})));
  EXPECT_FALSE(ids_distinct(faces_with_ids({"x", "x"})));
}

// 20,000 ids, with and without one clash between the first and the last, on one thread
// and on four: the same answer.
TEST(DistinctIds, ACityOnAnyThreads) {
  std::vector<std::string> ids;
  for (int i = 0; i < 20000; ++i) ids.push_back("p" + std::to_string(i));
  const std::vector<Face> distinct = faces_with_ids(ids);
  ids.back() = ids.front();
  const std::vector<Face> clash = faces_with_ids(ids);
  for (const int threads : {1, 4}) {
    tbb::task_arena arena(threads);
    EXPECT_TRUE(arena.execute([&] { return ids_distinct(distinct); })) << threads;
    EXPECT_FALSE(arena.execute([&] { return ids_distinct(clash); })) << threads;
  }
}

}  // namespace
}  // namespace shadowgen::scene::detail
