#include "tests/support/wkb.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadowgen::test {
namespace {

using clipper::Loop2;
using clipper::Point2;
using clipper::PolygonWithHoles2;

constexpr std::uint32_t kSridFlag = 0x20000000;
constexpr std::uint32_t kZFlag = 0x80000000;
constexpr std::uint32_t kMFlag = 0x40000000;

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
    text.remove_prefix(1);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
    text.remove_suffix(1);
  }
  return text;
}

class Reader {
 public:
  explicit Reader(std::vector<unsigned char> bytes) : bytes_(std::move(bytes)) {}

  ParsedGeometry read() {
    ParsedGeometry geometry;
    const std::uint32_t type = header();
    if (type == 3) {
      geometry.type = "POLYGON";
      geometry.areal = true;
      if (std::optional<PolygonWithHoles2> p = polygon_body()) geometry.polygons.push_back(*p);
    } else if (type == 6) {
      geometry.type = "MULTIPOLYGON";
      geometry.areal = true;
      const std::uint32_t count = u32();
      for (std::uint32_t i = 0; i < count; ++i) {
        if (header() != 3) fail("a polygon inside the multipolygon");
        if (std::optional<PolygonWithHoles2> p = polygon_body()) geometry.polygons.push_back(*p);
      }
    } else {
      static const char* const kNames[] = {
          "GEOMETRY",   "POINT",           "LINESTRING",   "POLYGON",
          "MULTIPOINT", "MULTILINESTRING", "MULTIPOLYGON", "GEOMETRYCOLLECTION"};
      geometry.type = type < 8 ? kNames[type] : "WKB type " + std::to_string(type);
      return geometry;
    }
    if (pos_ != bytes_.size()) fail("the end of the data");
    geometry.empty = geometry.polygons.empty();
    return geometry;
  }

 private:
  // Byte order and type; returns the base type with the flags removed.
  std::uint32_t header() {
    if (pos_ >= bytes_.size()) fail("a byte-order mark");
    const unsigned char order = bytes_[pos_++];
    if (order > 1) fail("a byte-order mark of 0 or 1");
    little_endian_ = order == 1;
    std::uint32_t type = u32();
    if ((type & (kZFlag | kMFlag)) != 0 || (type & 0xffff) > 1000) {
      fail("2D coordinates (Z and M are not supported)");
    }
    if ((type & kSridFlag) != 0) u32();  // the SRID
    return type & 0xffff;
  }

  std::optional<PolygonWithHoles2> polygon_body() {
    const std::uint32_t rings = u32();
    PolygonWithHoles2 polygon;
    bool has_shell = false;
    for (std::uint32_t r = 0; r < rings; ++r) {
      Loop2 loop;
      const std::uint32_t points = u32();
      for (std::uint32_t i = 0; i < points; ++i) {
        const double x = f64();
        const double y = f64();
        loop.push_back({x, y});
      }
      if (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
      if (r == 0) {
        has_shell = !loop.empty();
        polygon.outer = std::move(loop);
      } else if (!loop.empty()) {
        polygon.holes.push_back(std::move(loop));
      }
    }
    if (!has_shell) return std::nullopt;
    return polygon;
  }

  std::uint64_t unsigned_of(std::size_t size) {
    if (bytes_.size() - pos_ < size) fail(std::to_string(size) + " more bytes");
    std::uint64_t value = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const std::size_t at = little_endian_ ? pos_ + size - 1 - i : pos_ + i;
      value = (value << 8) | bytes_[at];
    }
    pos_ += size;
    return value;
  }

  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_of(4)); }

  double f64() {
    const std::uint64_t bits = unsigned_of(8);
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  [[noreturn]] void fail(const std::string& expected) const {
    throw std::runtime_error("WKB: expected " + expected + " at byte " + std::to_string(pos_));
  }

  std::vector<unsigned char> bytes_;
  std::size_t pos_ = 0;
  bool little_endian_ = true;
};

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

bool looks_like_wkb_hex(std::string_view text) {
  text = trimmed(text);
  if (text.empty()) return false;
  for (char c : text) {
    if (hex_digit(c) < 0) return false;
  }
  return true;
}

ParsedGeometry read_wkb_hex(std::string_view hex) {
  hex = trimmed(hex);
  if (!looks_like_wkb_hex(hex) || hex.size() % 2 != 0) {
    throw std::runtime_error("WKB: not an even number of hex digits");
  }
  std::vector<unsigned char> bytes(hex.size() / 2);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    bytes[i] = static_cast<unsigned char>(hex_digit(hex[2 * i]) * 16 + hex_digit(hex[2 * i + 1]));
  }
  return Reader(std::move(bytes)).read();
}

}  // namespace shadowgen::test
