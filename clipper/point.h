#pragma once

// 2D points in double precision: the coordinates every clip works in.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>

namespace shadowgen::clipper {

struct Point2 {
  double x = 0.0;
  double y = 0.0;

  friend bool operator==(const Point2&, const Point2&) = default;
  // Lexicographic (x, then y): the order of the sweep and of canonical output.
  friend bool operator<(const Point2& a, const Point2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  }
};

// The affine function a·x + b·y + c on the plane of points.
struct Affine2 {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  double at(const Point2& p) const { return a * p.x + b * p.y + c; }
};

// Hash on the exact bit patterns; +0.0 and -0.0 are folded together because they
// compare equal.
struct Point2Hash {
  std::size_t operator()(const Point2& p) const noexcept {
    auto bits = [](double v) {
      if (v == 0.0) v = 0.0;
      std::uint64_t u;
      std::memcpy(&u, &v, sizeof u);
      return u;
    };
    std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
    h ^= bits(p.y) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

}  // namespace shadowgen::clipper
