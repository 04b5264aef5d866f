#include "ply_reader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "mesh_text.h"
#include "ply_header.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

namespace {

using ply::Element;
using ply::Format;
using ply::is_integer;
using ply::Property;
using ply::range_of;
using ply::Role;
using ply::size_of;
using ply::Type;

// "'<token>' (property '<name>') <what>", built by appending (GCC 12 warns wrongly about
// the same as a chain of operator+ once inlined).
std::string bad_value(std::string_view token, const std::string& property, const char* what) {
  std::string s = "'";
  s.append(token).append("' (property '").append(property).append("') ").append(what);
  return s;
}

// One value as read: both forms, since a property of any type may carry either.
struct Value {
  double real = 0.0;
  std::int64_t integer = 0;
};

class PlyParser : MeshParser {
 public:
  using MeshParser::MeshParser;

  MeshSoup parse(std::string_view bytes) {
    if (!bytes.starts_with("ply\n") && !bytes.starts_with("ply\r")) {
      fail("not a PLY file: it does not begin with a line 'ply'");
    }
    const std::size_t end = bytes.find("end_header");
    if (end == std::string_view::npos) {
      fail("the PLY header has no 'end_header' line (truncated, or not a PLY file)");
    }
    require_text(bytes.substr(0, end), file_);
    LineReader lines(bytes);
    ply::Header header = ply::read_header(lines, file_);
    format_ = header.format;
    elements_ = std::move(header.elements);
    const std::string_view body = bytes.substr(lines.offset());
    if (format_ == Format::kAscii) {
      read_ascii(body, lines.number());
    } else {
      read_binary(body);
    }
    return std::move(soup_);
  }

 private:
  // ---- The elements, as the body gives them ------------------------------------------

  // Where one element's values go as they are read.
  struct Sink {
    glm::dvec3 point{0.0};
    MeshFaceRecord face;
  };

  void keep(const Element& e, Sink& sink) {
    if (e.name == "vertex") {
      soup_.vertices.push_back(sink.point);
    } else if (e.name == "face") {
      soup_.faces.push_back(std::move(sink.face));
    }
  }

  void reserve(const Element& e, std::size_t room) {
    const auto n =
        static_cast<std::size_t>(std::min<std::int64_t>(e.count, static_cast<std::int64_t>(room)));
    if (e.name == "vertex") soup_.vertices.reserve(n);
    if (e.name == "face") soup_.faces.reserve(n);
  }

  std::string ends_early(const Element& e, std::int64_t read) const {
    return "the file ends after " + std::to_string(read) + " of the " + std::to_string(e.count) +
           " '" + e.name + "' elements the header announces (truncated?)";
  }

  // ---- ASCII -------------------------------------------------------------------------

  void read_ascii(std::string_view body, std::size_t header_lines) {
    require_text(body, file_);
    LineReader lines(body);
    std::vector<std::string_view> t;
    auto next_line = [&]() {
      std::string_view line;
      while (lines.next(line)) {
        t = split_tokens(line);
        if (!t.empty()) return true;
      }
      return false;
    };
    for (const Element& e : elements_) {
      reserve(e, body.size() / 2);
      const bool face = e.name == "face";
      for (std::int64_t i = 0; i < e.count; ++i) {
        if (!next_line()) fail(ends_early(e, i));
        const std::size_t at = header_lines + lines.number();
        Sink sink;
        sink.face.line = at;
        std::size_t k = 0;
        auto value = [&](Type type, const Property& p) {
          if (k == t.size()) {
            fail_at(at, "the '" + e.name + "' element has fewer values than its properties need",
                    face);
          }
          const std::string_view token = t[k++];
          Value v;
          if (is_integer(type)) {
            const std::optional<std::int64_t> n = parse_integer(token);
            const auto [lo, hi] = range_of(type);
            if (!n || *n < lo || *n > hi) {
              fail_at(at, bad_value(token, p.name, "is not an integer of its type"), face);
            }
            v.integer = *n;
            v.real = static_cast<double>(*n);
          } else {
            const std::optional<double> x = parse_number(token);
            if (!x) {
              fail_at(at, bad_value(token, p.name, "is not a number"), face);
            }
            v.real = *x;
          }
          return v;
        };
        for (const Property& p : e.properties) {
          if (!p.list) {
            store(p, value(p.type, p), sink, at);
            continue;
          }
          const std::int64_t n = value(p.count_type, p).integer;
          if (n < 0) fail_at(at, "list '" + p.name + "' has a negative count", face);
          for (std::int64_t j = 0; j < n; ++j) {
            const Value item = value(p.type, p);
            if (p.role == Role::kIndices) sink.face.vertices.push_back(item.integer);
          }
        }
        if (k != t.size()) {
          fail_at(at,
                  "the '" + e.name + "' element has " + std::to_string(t.size() - k) +
                      " more values than its properties take",
                  face);
        }
        keep(e, sink);
      }
    }
    if (next_line()) {
      fail_at(header_lines + lines.number(), "more data after the elements the header announces");
    }
  }

  void store(const Property& p, const Value& v, Sink& sink, std::size_t line) const {
    if (p.role != Role::kX && p.role != Role::kY && p.role != Role::kZ) return;
    if (!std::isfinite(v.real)) {
      const std::string where = line > 0 ? "line " + std::to_string(line) + ": " : "";
      fail(where + "vertex " + std::to_string(soup_.vertices.size()) + ": coordinate " + p.name +
           " is not finite");
    }
    sink.point[p.role == Role::kX ? 0 : p.role == Role::kY ? 1 : 2] = v.real;
  }

  // ---- Binary ------------------------------------------------------------------------

  class Cursor {
   public:
    Cursor(std::string_view bytes, bool big_endian) : bytes_(bytes), big_(big_endian) {}
    std::size_t left() const { return bytes_.size() - pos_; }
    bool read(Type type, Value& v) {
      const std::size_t n = size_of(type);
      if (left() < n) return false;
      std::uint64_t u = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const auto byte = static_cast<unsigned char>(bytes_[pos_ + (big_ ? i : n - 1 - i)]);
        u = (u << 8) | byte;
      }
      pos_ += n;
      switch (type) {
        case Type::kInt8:
          v.integer = static_cast<std::int8_t>(u);
          break;
        case Type::kInt16:
          v.integer = static_cast<std::int16_t>(u);
          break;
        case Type::kInt32:
          v.integer = static_cast<std::int32_t>(u);
          break;
        case Type::kUint8:
        case Type::kUint16:
        case Type::kUint32:
          v.integer = static_cast<std::int64_t>(u);
          break;
        case Type::kFloat32:
          v.real = std::bit_cast<float>(static_cast<std::uint32_t>(u));
          return true;
        case Type::kFloat64:
          v.real = std::bit_cast<double>(u);
          return true;
      }
      v.real = static_cast<double>(v.integer);
      return true;
    }

   private:
    std::string_view bytes_;
    std::size_t pos_ = 0;
    bool big_;
  };

  void read_binary(std::string_view body) {
    Cursor in(body, format_ == Format::kBigEndian);
    for (const Element& e : elements_) {
      std::size_t least = 0;  // bytes an element takes at least
      for (const Property& p : e.properties) least += size_of(p.list ? p.count_type : p.type);
      if (least > 0 && static_cast<std::uint64_t>(e.count) > in.left() / least) {
        fail("the file ends before the " + std::to_string(e.count) + " '" + e.name +
             "' elements the header announces end (truncated?)");
      }
      reserve(e, in.left());
      const bool face = e.name == "face";
      for (std::int64_t i = 0; i < e.count; ++i) {
        Sink sink;
        for (const Property& p : e.properties) {
          Value v;
          if (!p.list) {
            if (!in.read(p.type, v)) fail(ends_early(e, i));
            store(p, v, sink, 0);
            continue;
          }
          if (!in.read(p.count_type, v)) fail(ends_early(e, i));
          if (v.integer < 0) {
            fail("'" + e.name + "' element " + std::to_string(i) + ": list '" + p.name +
                     "' has a negative count",
                 face);
          }
          if (static_cast<std::uint64_t>(v.integer) * size_of(p.type) > in.left()) {
            fail(ends_early(e, i));
          }
          for (std::int64_t j = 0, n = v.integer; j < n; ++j) {
            Value item;
            in.read(p.type, item);
            if (p.role == Role::kIndices) sink.face.vertices.push_back(item.integer);
          }
        }
        keep(e, sink);
      }
    }
    if (in.left() != 0) {
      fail(std::to_string(in.left()) + " bytes after the last element the header announces");
    }
  }

  Format format_ = Format::kAscii;
  std::vector<Element> elements_;
};

}  // namespace

MeshSoup parse_ply(std::string_view bytes, const std::filesystem::path& file,
                   const std::string& mesh_id) {
  return PlyParser(file, mesh_id).parse(bytes);
}

}  // namespace shadowgen::scene::detail
