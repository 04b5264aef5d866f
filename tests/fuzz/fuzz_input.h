#pragma once

// How the clip fuzzer reads arbitrary bytes as two polygon sets. make_corpus.py writes
// the same format; keep the two in step.
//
//   header   1 byte: mode = header & 3, parameter = header >> 2
//   subject  a set, then
//   clip     a set
//   set      1 byte: polygon count = byte % 4 (0 to 3), then each polygon:
//   polygon  1 byte: hole count = byte % 3 (0 to 2), then the outer loop and the holes
//   loop     1 byte: vertex count = 3 + (byte & 0x7f) % 22 (3 to 24); when byte & 0x80 the
//            vertices are reordered as a fan around the lexicographically smallest one
//            (star-shaped, so usually simple), then the vertices: x, then y
//
// Coordinates by mode, each chosen to provoke a kind of degeneracy:
//   0  grid:      1 byte, c = byte % 17 - 8. Shared vertices, collinear overlaps and exact
//                 touches galore; every crossing is a rational of small denominator.
//   1  scaled:    1 byte, c = offset + (byte % 17 - 8) * step, with step = kSteps[p & 7]
//                 and offset = kOffsets[(p >> 3) & 7]: a grid that doubles cannot hold
//                 exactly (0.1, 1/3 at offset 1e6), so "collinear" is only nearly so.
//   2  perturbed: 2 bytes g, e: c = g % 17 - 8 + int8(e) * 2^-(4 + p % 48): a grid point
//                 nudged by a few units of a chosen binade, near-degenerate on purpose.
//   3  raw:       8 bytes, a little-endian double; not finite -> 0, |c| > 1e9 -> fmod(c,
//                 1e9) (exact), 0 < |c| < 1e-9 -> 0. The range keeps orient2d exact and
//                 exact_area.h's products free of overflow and underflow.
//
// Input that ends inside a structure is rejected (std::nullopt); trailing bytes are
// ignored.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>

#include "clipper/polygon.h"
#include "clipper/predicates.h"

namespace shadowgen::fuzz {

enum class CoordinateMode { kGrid = 0, kScaled = 1, kPerturbed = 2, kRaw = 3 };

struct FuzzInput {
  CoordinateMode mode = CoordinateMode::kGrid;
  clipper::PolygonSet2 subject;
  clipper::PolygonSet2 clip;
};

inline constexpr double kSteps[8] = {1.0, 0.5, 0.1, 1e-3, 1.0 / 3.0, 1e-7, 1e5, 3.0};
inline constexpr double kOffsets[8] = {0.0, 1.0, -0.3, 1e3, 1e6, -7.25e5, 1e8, 0.1};

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  bool read(std::uint8_t& out) {
    if (next_ >= bytes_.size()) return false;
    out = bytes_[next_++];
    return true;
  }

  bool read(double& out) {
    if (bytes_.size() - next_ < 8) return false;
    std::uint64_t bits = 0;
    for (int k = 7; k >= 0; --k) bits = (bits << 8) | bytes_[next_ + static_cast<std::size_t>(k)];
    next_ += 8;
    std::memcpy(&out, &bits, sizeof out);
    return true;
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t next_ = 0;
};

class InputDecoder {
 public:
  explicit InputDecoder(std::span<const std::uint8_t> bytes) : reader_(bytes) {}

  std::optional<FuzzInput> decode() {
    std::uint8_t header = 0;
    if (!reader_.read(header)) return std::nullopt;
    FuzzInput input;
    input.mode = static_cast<CoordinateMode>(header & 3);
    mode_ = input.mode;
    parameter_ = header >> 2;
    if (!read_set(input.subject) || !read_set(input.clip)) return std::nullopt;
    return input;
  }

 private:
  bool read_set(clipper::PolygonSet2& set) {
    std::uint8_t count = 0;
    if (!reader_.read(count)) return false;
    set.resize(count % 4);
    for (clipper::PolygonWithHoles2& polygon : set) {
      std::uint8_t holes = 0;
      if (!reader_.read(holes)) return false;
      polygon.holes.resize(holes % 3);
      if (!read_loop(polygon.outer)) return false;
      for (clipper::Loop2& hole : polygon.holes) {
        if (!read_loop(hole)) return false;
      }
    }
    return true;
  }

  bool read_loop(clipper::Loop2& loop) {
    std::uint8_t count = 0;
    if (!reader_.read(count)) return false;
    loop.resize(3 + (count & 0x7f) % 22);
    for (clipper::Point2& p : loop) {
      if (!read_coordinate(p.x) || !read_coordinate(p.y)) return false;
    }
    if (count & 0x80) make_fan(loop);
    return true;
  }

  // Sorted by angle around the smallest vertex, which sees all others within a half-plane
  // (so the comparison is a strict weak order); ties by distance.
  static void make_fan(clipper::Loop2& loop) {
    auto pivot = std::min_element(loop.begin(), loop.end());
    std::iter_swap(loop.begin(), pivot);
    const clipper::Point2 p = loop.front();
    std::sort(loop.begin() + 1, loop.end(),
              [&p](const clipper::Point2& a, const clipper::Point2& b) {
                const clipper::Orientation o = clipper::orient2d(p, a, b);
                if (o != clipper::Orientation::kCollinear)
                  return o == clipper::Orientation::kCounterClockwise;
                return a < b;
              });
  }

  bool read_coordinate(double& c) {
    std::uint8_t g = 0;
    switch (mode_) {
      case CoordinateMode::kGrid:
        if (!reader_.read(g)) return false;
        c = g % 17 - 8;
        return true;
      case CoordinateMode::kScaled:
        if (!reader_.read(g)) return false;
        c = kOffsets[(parameter_ >> 3) & 7] + (g % 17 - 8) * kSteps[parameter_ & 7];
        return true;
      case CoordinateMode::kPerturbed: {
        std::uint8_t e = 0;
        if (!reader_.read(g) || !reader_.read(e)) return false;
        const int nudge = static_cast<std::int8_t>(e);
        c = (g % 17 - 8) + std::ldexp(nudge, -(4 + parameter_ % 48));
        return true;
      }
      case CoordinateMode::kRaw:
        if (!reader_.read(c)) return false;
        if (!std::isfinite(c)) c = 0.0;
        if (std::fabs(c) > 1e9) c = std::fmod(c, 1e9);
        if (std::fabs(c) < 1e-9) c = 0.0;
        return true;
    }
    return false;
  }

  ByteReader reader_;
  CoordinateMode mode_ = CoordinateMode::kGrid;
  int parameter_ = 0;
};

inline std::optional<FuzzInput> decode_fuzz_input(std::span<const std::uint8_t> bytes) {
  return InputDecoder(bytes).decode();
}

}  // namespace shadowgen::fuzz
