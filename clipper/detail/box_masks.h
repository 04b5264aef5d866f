#pragma once

// Bit masks of which of up to 128 points, or boxes, meet one box, 64 at a time: snap
// rounding's shortcut tests every vertex of a small clip against every edge's box, and a
// mask of hits lets it visit only the few that matter. The coordinates are laid out one
// array per coordinate (MaskLane), so that two are compared in one SSE2 instruction where
// the target has it; the scalar loop gives the same bits everywhere else (comparisons are
// exact, and false for NaN either way).

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shadowgen::clipper::detail {

// Up to 128 values of one coordinate, padded with NaN to a multiple of four: a padded lane
// meets no box.
class MaskLane {
 public:
  static constexpr std::size_t kCapacity = 128;

  double& operator[](std::size_t i) { return values_[i]; }
  double operator[](std::size_t i) const { return values_[i]; }
  const double* data() const { return values_.data(); }

  // NaN from `count` to the next multiple of four.
  void pad(std::size_t count) {
    for (std::size_t i = count; i % 4 != 0; ++i)
      values_[i] = std::numeric_limits<double>::quiet_NaN();
  }

 private:
  alignas(16) std::array<double, kCapacity> values_;
};

// Bit k − first set where the closed box [xlo[k], xhi[k]] × [ylo[k], yhi[k]] meets
// [x0, x1] × [y0, y1], for k in [first, end): `first` a multiple of four, at most 64 boxes,
// and the lanes padded from their count on (`end` is that count or below it). A point is
// the box of itself (xlo == xhi).
inline std::uint64_t boxes_meeting_scalar(const MaskLane& xlo, const MaskLane& xhi,
                                          const MaskLane& ylo, const MaskLane& yhi,
                                          std::size_t first, std::size_t end, double x0, double x1,
                                          double y0, double y1) {
  std::uint64_t hits = 0;
  for (std::size_t k = first; k < end; ++k) {
    const bool in =
        static_cast<bool>(static_cast<int>(xlo[k] <= x1) & static_cast<int>(x0 <= xhi[k]) &
                          static_cast<int>(ylo[k] <= y1) & static_cast<int>(y0 <= yhi[k]));
    hits |= static_cast<std::uint64_t>(in) << (k - first);
  }
  return hits;
}

inline std::uint64_t boxes_meeting(const MaskLane& xlo, const MaskLane& xhi, const MaskLane& ylo,
                                   const MaskLane& yhi, std::size_t first, std::size_t end,
                                   double x0, double x1, double y0, double y1) {
#if defined(__SSE2__)
  const __m128d bx0 = _mm_set1_pd(x0), bx1 = _mm_set1_pd(x1);
  const __m128d by0 = _mm_set1_pd(y0), by1 = _mm_set1_pd(y1);
  auto pair = [&](std::size_t k) {
    const __m128d in = _mm_and_pd(_mm_and_pd(_mm_cmple_pd(_mm_load_pd(xlo.data() + k), bx1),
                                             _mm_cmple_pd(bx0, _mm_load_pd(xhi.data() + k))),
                                  _mm_and_pd(_mm_cmple_pd(_mm_load_pd(ylo.data() + k), by1),
                                             _mm_cmple_pd(by0, _mm_load_pd(yhi.data() + k))));
    return static_cast<std::uint64_t>(_mm_movemask_pd(in));
  };
  std::uint64_t hits = 0;
  for (std::size_t k = first; k < end; k += 4) {
    hits |= (pair(k) | pair(k + 2) << 2) << (k - first);
  }
  return hits;
#else
  return boxes_meeting_scalar(xlo, xhi, ylo, yhi, first, end, x0, x1, y0, y1);
#endif
}

// Calls visit(k) for every k in [from, count) whose box meets [x0, x1] × [y0, y1], in
// increasing order of k, 64 boxes to a mask; stops as soon as visit returns false, and
// returns whether none did. The lanes are padded from `count` on.
template <class Visit>
bool each_box_meeting(const MaskLane& xlo, const MaskLane& xhi, const MaskLane& ylo,
                      const MaskLane& yhi, std::size_t from, std::size_t count, double x0,
                      double x1, double y0, double y1, Visit&& visit) {
  for (std::size_t block = from & ~std::size_t{63}; block < count; block += 64) {
    std::uint64_t hits =
        boxes_meeting(xlo, xhi, ylo, yhi, block, std::min(count, block + 64), x0, x1, y0, y1);
    if (block < from) hits &= ~std::uint64_t{0} << (from - block);
    for (; hits != 0; hits &= hits - 1) {
      if (!visit(block + static_cast<std::size_t>(std::countr_zero(hits)))) return false;
    }
  }
  return true;
}

}  // namespace shadowgen::clipper::detail
