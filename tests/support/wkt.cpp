#include "tests/support/wkt.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace shadowgen::test {
namespace {

using clipper::Loop2;
using clipper::Point2;
using clipper::PolygonWithHoles2;

class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}

  ParsedGeometry read() {
    ParsedGeometry geometry;
    geometry.type = word();
    if (geometry.type.empty()) fail("a geometry type");
    if (geometry.type != "POLYGON" && geometry.type != "MULTIPOLYGON") return geometry;
    geometry.areal = true;
    if (!try_empty()) {
      if (geometry.type == "POLYGON") {
        if (std::optional<PolygonWithHoles2> p = polygon_body()) geometry.polygons.push_back(*p);
      } else {
        expect('(');
        do {
          if (try_empty()) continue;
          if (std::optional<PolygonWithHoles2> p = polygon_body()) {
            geometry.polygons.push_back(std::move(*p));
          }
        } while (try_consume(','));
        expect(')');
      }
    }
    skip_space();
    if (pos_ != text_.size()) fail("the end of the text");
    geometry.empty = geometry.polygons.empty();
    return geometry;
  }

 private:
  // '(' ring {',' ring} ')' where the first ring is the shell. A polygon whose shell is
  // EMPTY is skipped with its holes.
  std::optional<PolygonWithHoles2> polygon_body() {
    expect('(');
    PolygonWithHoles2 polygon;
    bool first = true;
    bool has_shell = false;
    do {
      std::optional<Loop2> loop = ring();
      if (first) {
        has_shell = loop.has_value();
        if (loop) polygon.outer = std::move(*loop);
      } else if (loop) {
        polygon.holes.push_back(std::move(*loop));
      }
      first = false;
    } while (try_consume(','));
    expect(')');
    if (!has_shell) return std::nullopt;
    return polygon;
  }

  std::optional<Loop2> ring() {
    if (try_empty()) return std::nullopt;
    expect('(');
    Loop2 loop;
    do {
      const double x = number();
      const double y = number();
      loop.push_back({x, y});
    } while (try_consume(','));
    expect(')');
    if (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
    return loop;
  }

  double number() {
    skip_space();
    const std::string token(text_.substr(pos_, text_.find_first_of(" \t\r\n,()", pos_) - pos_));
    if (token.empty()) fail("a number");
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || errno == ERANGE) fail("a number");
    pos_ += token.size();
    return value;
  }

  std::string word() {
    skip_space();
    std::string result;
    while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_]))) {
      result += static_cast<char>(std::toupper(static_cast<unsigned char>(text_[pos_])));
      ++pos_;
    }
    return result;
  }

  bool try_empty() {
    const std::size_t saved = pos_;
    if (word() == "EMPTY") return true;
    pos_ = saved;
    return false;
  }

  bool try_consume(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  void expect(char c) {
    if (!try_consume(c)) fail(std::string("'") + c + "'");
  }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  [[noreturn]] void fail(const std::string& expected) const {
    throw std::runtime_error("WKT: expected " + expected + " at offset " + std::to_string(pos_) +
                             " near \"" + std::string(text_.substr(pos_, 30)) + "\"");
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

ParsedGeometry read_wkt(std::string_view text) { return Reader(text).read(); }

std::string to_wkt(const clipper::PolygonSet2& polygons) {
  if (polygons.empty()) return "MULTIPOLYGON EMPTY";
  std::ostringstream out;
  out.precision(17);
  auto ring = [&out](const Loop2& loop) {
    out << '(';
    for (const Point2& p : loop) out << p.x << ' ' << p.y << ", ";
    if (!loop.empty()) out << loop.front().x << ' ' << loop.front().y;
    out << ')';
  };
  out << "MULTIPOLYGON (";
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    out << (i == 0 ? "(" : ", (");
    ring(polygons[i].outer);
    for (const Loop2& hole : polygons[i].holes) {
      out << ", ";
      ring(hole);
    }
    out << ')';
  }
  out << ')';
  return out.str();
}

}  // namespace shadowgen::test
