// A closed surface's self-contact check: its triangles' boxes in a grid of cubes, and
// each candidate pair checked exactly once, in the cube of the higher low corner.

#include "touches_itself.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/common.hpp>
#include <utility>

namespace shadowgen::shadows::detail {
namespace {

struct Box {
  glm::dvec3 low, high;
};

Box box_of(const hsr::Triangle3& t) {
  return {glm::min(glm::min(t[0], t[1]), t[2]), glm::max(glm::max(t[0], t[1]), t[2])};
}

bool boxes_meet(const Box& a, const Box& b) {
  return a.low.x <= b.high.x && b.low.x <= a.high.x && a.low.y <= b.high.y && b.low.y <= a.high.y &&
         a.low.z <= b.high.z && b.low.z <= a.high.z;
}

}  // namespace

bool touches_itself(const std::vector<hsr::Triangle3>& triangles, const std::vector<int>& planes) {
  std::vector<std::uint32_t> items;
  std::vector<Box> boxes;
  std::vector<double> sizes;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if (hsr::degenerate(triangles[i])) continue;
    items.push_back(static_cast<std::uint32_t>(i));
    boxes.push_back(box_of(triangles[i]));
    const glm::dvec3 e = boxes.back().high - boxes.back().low;
    sizes.push_back(std::max({e.x, e.y, e.z}));
  }
  if (items.size() < 2) return false;
  Box all = boxes.front();
  for (const Box& b : boxes) {
    all.low = glm::min(all.low, b.low);
    all.high = glm::max(all.high, b.high);
  }
  // Cubes as wide as the median triangle, but no more than 64 along the widest side, and
  // wider while the boxes would fill more than 16 cubes each on average.
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2),
                   sizes.end());
  const glm::dvec3 extent = all.high - all.low;
  double cube = std::max(sizes[sizes.size() / 2], std::max({extent.x, extent.y, extent.z}) / 64.0);
  if (!(cube > 0.0)) cube = 1.0;
  auto cell = [&](double v, double low) {
    return static_cast<std::uint64_t>(std::min(std::floor((v - low) / cube), 1048575.0));
  };
  auto cell_of = [&](const glm::dvec3& p) {
    return std::array<std::uint64_t, 3>{cell(p.x, all.low.x), cell(p.y, all.low.y),
                                        cell(p.z, all.low.z)};
  };
  auto key = [](const std::array<std::uint64_t, 3>& c) {
    return (c[0] << 40) | (c[1] << 20) | c[2];
  };
  for (;;) {
    std::uint64_t filled = 0;
    for (const Box& b : boxes) {
      const auto low = cell_of(b.low), high = cell_of(b.high);
      filled += (high[0] - low[0] + 1) * (high[1] - low[1] + 1) * (high[2] - low[2] + 1);
    }
    if (filled <= 16 * boxes.size() + 4096) break;
    cube *= 2.0;
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
  std::vector<std::array<std::uint64_t, 3>> low_cell(boxes.size());
  for (std::uint32_t k = 0; k < boxes.size(); ++k) {
    const auto low = cell_of(boxes[k].low), high = cell_of(boxes[k].high);
    low_cell[k] = low;
    for (std::uint64_t x = low[0]; x <= high[0]; ++x) {
      for (std::uint64_t y = low[1]; y <= high[1]; ++y) {
        for (std::uint64_t z = low[2]; z <= high[2]; ++z) entries.emplace_back(key({x, y, z}), k);
      }
    }
  }
  // Past a budget of candidate pairs (many triangles crowding one cube, as around a vertex
  // of thousands of neighbours) the surface is taken as touching itself: no solid, and
  // the parts simply occlude.
  std::uint64_t budget = 256 * static_cast<std::uint64_t>(boxes.size()) + 65536;
  std::sort(entries.begin(), entries.end());
  for (std::size_t g = 0, e = 0; g < entries.size(); g = e) {
    for (e = g + 1; e < entries.size() && entries[e].first == entries[g].first; ++e) {
    }
    const std::uint64_t here = (e - g) * (e - g - 1) / 2;
    if (here > budget) return true;
    budget -= here;
    for (std::size_t i = g; i < e; ++i) {
      for (std::size_t j = i + 1; j < e; ++j) {
        const std::uint32_t p = entries[i].second, q = entries[j].second;
        if (!boxes_meet(boxes[p], boxes[q])) continue;
        // The cube of the higher low corner: the greater cell index on each axis.
        const std::array<std::uint64_t, 3> owner = {std::max(low_cell[p][0], low_cell[q][0]),
                                                    std::max(low_cell[p][1], low_cell[q][1]),
                                                    std::max(low_cell[p][2], low_cell[q][2])};
        if (key(owner) != entries[g].first) continue;
        const int plane = planes[items[p]];
        if (hsr::triangles_overlap_beyond_shared(triangles[items[p]], triangles[items[q]],
                                                 plane >= 0 && plane == planes[items[q]])) {
          return true;
        }
      }
    }
  }
  return false;
}

}  // namespace shadowgen::shadows::detail
