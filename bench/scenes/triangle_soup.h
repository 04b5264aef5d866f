#pragma once

// Benchmark scene: a soup of random triangles in the unit cube. Each triangle has a
// centre uniform in [0, 1]³ and its three vertices uniform in the cube of half-side r
// around that centre, r log-uniform in [0.003, 0.03] whatever the count (a fixed size
// distribution: mean area about 6e-5, projected about half that, so the depth
// complexity grows in proportion to the count, about 0.03 per 1000 triangles). Triangles
// cross each other freely: interpenetration is the norm, not the exception. Seeded,
// deterministic.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hsr/polygon3.h"

namespace shadowgen::bench {

std::vector<hsr::Polygon3> triangle_soup(std::size_t count, std::uint64_t seed = 1);

}  // namespace shadowgen::bench
