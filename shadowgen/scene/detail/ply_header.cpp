#include "ply_header.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <string_view>

#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail::ply {

namespace {

std::optional<Type> type_named(std::string_view name) {
  if (name == "char" || name == "int8") return Type::kInt8;
  if (name == "uchar" || name == "uint8") return Type::kUint8;
  if (name == "short" || name == "int16") return Type::kInt16;
  if (name == "ushort" || name == "uint16") return Type::kUint16;
  if (name == "int" || name == "int32") return Type::kInt32;
  if (name == "uint" || name == "uint32") return Type::kUint32;
  if (name == "float" || name == "float32") return Type::kFloat32;
  if (name == "double" || name == "float64") return Type::kFloat64;
  return std::nullopt;
}

class HeaderReader {
 public:
  explicit HeaderReader(const std::string& file) : file_(file) {}

  Header read(LineReader& lines) {
    std::string_view line;
    lines.next(line);  // "ply"
    bool has_format = false;
    for (;;) {
      if (!lines.next(line)) fail("the PLY header has no 'end_header' line (truncated?)");
      const std::size_t at = lines.number();
      const std::vector<std::string_view> t = split_tokens(line);
      if (t.empty()) continue;
      if (t[0] == "end_header") {
        if (t.size() != 1) fail_at(at, "unexpected text after 'end_header'");
        break;
      }
      if (t[0] == "comment" || t[0] == "obj_info") continue;
      if (t[0] == "format") {
        if (t.size() != 3 || t[2] != "1.0") fail_at(at, "expected 'format <kind> 1.0'");
        if (t[1] == "ascii") {
          header_.format = Format::kAscii;
        } else if (t[1] == "binary_little_endian") {
          header_.format = Format::kLittleEndian;
        } else if (t[1] == "binary_big_endian") {
          header_.format = Format::kBigEndian;
        } else {
          fail_at(at, "unknown format '" + std::string(t[1]) + "'");
        }
        has_format = true;
      } else if (t[0] == "element") {
        const std::optional<std::int64_t> count =
            t.size() == 3 ? parse_integer(t[2]) : std::nullopt;
        if (!count || *count < 0) fail_at(at, "expected 'element <name> <count>', count >= 0");
        const std::string name(t[1]);
        for (const Element& e : header_.elements) {
          if (e.name == name) fail_at(at, "a second element '" + name + "'");
        }
        if (name == "tristrips") fail_at(at, "'tristrips' elements are not read; use faces");
        header_.elements.push_back({name, *count, {}});
      } else if (t[0] == "property") {
        if (header_.elements.empty()) fail_at(at, "a property before any element");
        read_property(t, at, header_.elements.back());
      } else {
        fail_at(at, "unknown header line '" + std::string(line) + "'");
      }
    }
    if (!has_format) fail("the PLY header has no 'format' line");
    for (Element& e : header_.elements) {
      auto has = [&e](Role role) {
        return std::any_of(e.properties.begin(), e.properties.end(),
                           [role](const Property& p) { return p.role == role; });
      };
      if (e.name == "vertex" && !(has(Role::kX) && has(Role::kY) && has(Role::kZ))) {
        fail("the vertex element has no x, y and z properties");
      }
      if (e.name == "face" && !has(Role::kIndices)) {
        fail("the face element has no 'vertex_indices' list of integers");
      }
    }
    return std::move(header_);
  }

  void read_property(const std::vector<std::string_view>& t, std::size_t at, Element& e) {
    Property p;
    if (t.size() == 5 && t[1] == "list") {
      const std::optional<Type> count = type_named(t[2]);
      const std::optional<Type> item = type_named(t[3]);
      if (!count || !item) fail_at(at, "unknown type in a list property");
      if (!is_integer(*count)) fail_at(at, "a list's count must have an integer type");
      p = {std::string(t[4]), *item, true, *count};
    } else if (t.size() == 3) {
      const std::optional<Type> type = type_named(t[1]);
      if (!type) fail_at(at, "unknown type '" + std::string(t[1]) + "'");
      p = {std::string(t[2]), *type};
    } else {
      fail_at(at, "expected 'property <type> <name>' or 'property list <type> <type> <name>'");
    }
    if (e.name == "vertex" && !p.list) {
      p.role = p.name == "x"   ? Role::kX
               : p.name == "y" ? Role::kY
               : p.name == "z" ? Role::kZ
                               : Role::kNone;
    }
    if (e.name == "face" && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
      if (!is_integer(p.type)) fail_at(at, "vertex indices must have an integer type");
      p.role = Role::kIndices;
    }
    for (const Property& q : e.properties) {
      if (q.name == p.name) fail_at(at, "a second property '" + p.name + "'");
      if (p.role != Role::kNone && q.role == p.role) {
        fail_at(at, "a second vertex index list ('" + p.name + "' and '" + q.name + "')");
      }
    }
    e.properties.push_back(std::move(p));
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, "", what); }
  [[noreturn]] void fail_at(std::size_t line, const std::string& what) const {
    fail("line " + std::to_string(line) + ": " + what);
  }

  const std::string& file_;
  Header header_;
};

}  // namespace

std::size_t size_of(Type t) {
  switch (t) {
    case Type::kInt8:
    case Type::kUint8:
      return 1;
    case Type::kInt16:
    case Type::kUint16:
      return 2;
    case Type::kInt32:
    case Type::kUint32:
    case Type::kFloat32:
      return 4;
    case Type::kFloat64:
      return 8;
  }
  return 8;
}

bool is_integer(Type t) { return t != Type::kFloat32 && t != Type::kFloat64; }

std::pair<std::int64_t, std::int64_t> range_of(Type t) {
  switch (t) {
    case Type::kInt8:
      return {-128, 127};
    case Type::kUint8:
      return {0, 255};
    case Type::kInt16:
      return {-32768, 32767};
    case Type::kUint16:
      return {0, 65535};
    case Type::kInt32:
      return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
    default:
      return {0, std::numeric_limits<std::uint32_t>::max()};
  }
}

Header read_header(LineReader& lines, const std::string& file) {
  return HeaderReader(file).read(lines);
}

}  // namespace shadowgen::scene::detail::ply
