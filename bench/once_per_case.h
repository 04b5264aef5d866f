#pragma once

// What a benchmark needs per case (a scene with one of its lights, the exact result for
// it) is made on first use and kept for the run, so that it is made outside any timing
// and once however many benchmarks share it. Every call site passes its own lambda and so
// gets its own store (a static of this template's instance for that lambda's type).

#include <map>
#include <utility>

namespace shadowgen::bench {

template <class Make>
const auto& once_per_case(int scene, int light, Make make) {
  static std::map<std::pair<int, int>, decltype(make())> made;
  auto it = made.find({scene, light});
  if (it == made.end()) it = made.emplace(std::pair{scene, light}, make()).first;
  return it->second;
}

}  // namespace shadowgen::bench
