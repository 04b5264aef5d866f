#include "detail/distinct_ids.h"

#include <tbb/parallel_sort.h>

#include <string>
#include <vector>

#include "hsr/parallel.h"

namespace shadowgen::scene::detail {

bool ids_distinct(std::span<const Face> faces) {
  std::vector<const std::string*> ids(faces.size());
  hsr::for_each_in_parallel(faces.size(), [&](std::size_t i) { ids[i] = &faces[i].id; });
  tbb::parallel_sort(ids.begin(), ids.end(),
                     [](const std::string* a, const std::string* b) { return *a < *b; });
  std::vector<char> clash(ids.size(), 0);
  hsr::for_each_in_parallel(ids.size(),
                            [&](std::size_t i) { clash[i] = i > 0 && *ids[i] == *ids[i - 1]; });
  for (const char c : clash) {
    if (c) return false;
  }
  return true;
}

}  // namespace shadowgen::scene::detail
