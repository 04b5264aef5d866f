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
    // Every bit of the result depends on every bit of both coordinates (y's halves swapped,
    // so that the informative high bits of each land apart, then the finalizer of
    // MurmurHash3): the coordinates of a grid, small integers or binary fractions, have
    // dozens of trailing zero bits, and a multiplicative hash left the low bits, which
    // PointIndex masks a slot from, the same for all of them.
    auto mix = [](std::uint64_t z) {
      z ^= z >> 33;
      z *= 0xFF51AFD7ED558CCDull;
      z ^= z >> 33;
      z *= 0xC4CEB9FE1A85EC53ull;
      return z ^ (z >> 33);
    };
    const std::uint64_t y = bits(p.y);
    return static_cast<std::size_t>(mix(bits(p.x) ^ ((y << 32) | (y >> 32))));
  }
};

}  // namespace shadowgen::clipper
