#include "stl_reader.h"

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <vector>

#include "shadowgen/model/input_error.h"

namespace shadowgen::detail {

namespace {

std::uint32_t little_endian_u32(const char* bytes) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[i]);
  return value;
}

float little_endian_float(const char* bytes) {
  return std::bit_cast<float>(little_endian_u32(bytes));
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

class StlParser {
 public:
  StlParser(const std::filesystem::path& file, const std::string& mesh_id)
      : file_(file.string()), mesh_id_(mesh_id) {}

  MeshSoup parse(std::string_view bytes) {
    if (bytes.size() >= 84) {
      const std::uint64_t count = little_endian_u32(bytes.data() + 80);
      if (bytes.size() == 84 + 50 * count) return parse_binary(bytes, count);
    }
    if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);  // a UTF-8 byte order mark
    std::size_t start = 0;
    while (start < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[start]))) ++start;
    if (lower(bytes.substr(start, 5)) != "solid") {
      throw InputError(file_, "",
                       "not an STL file: not binary STL (its size does not match the "
                       "triangle count in its header) and not ASCII STL (it does not begin "
                       "with 'solid')");
    }
    return parse_ascii(bytes);
  }

 private:
  std::string face_id() const { return mesh_id_ + "/" + std::to_string(soup_.faces.size()); }

  MeshSoup parse_binary(std::string_view bytes, std::uint64_t count) {
    soup_.vertices.reserve(3 * count);
    soup_.faces.reserve(count);
    for (std::uint64_t t = 0; t < count; ++t) {
      const char* record = bytes.data() + 84 + 50 * t + 12;  // after the facet normal
      MeshFaceRecord face;
      for (int corner = 0; corner < 3; ++corner) {
        glm::dvec3 v;
        for (int axis = 0; axis < 3; ++axis) {
          v[axis] = little_endian_float(record + 12 * corner + 4 * axis);
        }
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
          throw InputError(file_, face_id(), "a vertex coordinate is not finite");
        }
        face.vertices.push_back(static_cast<std::int64_t>(soup_.vertices.size()));
        soup_.vertices.push_back(v);
      }
      soup_.faces.push_back(std::move(face));
    }
    return std::move(soup_);
  }

  [[noreturn]] void fail(std::size_t line, const std::string& what, bool in_facet) const {
    throw InputError(file_, in_facet ? face_id() : "",
                     "line " + std::to_string(line) + ": " + what);
  }

  double coordinate(std::string_view token, std::size_t line) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value)) {
      fail(line, "coordinate '" + std::string(token) + "' is not a finite number", true);
    }
    return value;
  }

  MeshSoup parse_ascii(std::string_view text) {
    std::size_t pos = 0;
    std::size_t line_no = 0;
    bool in_facet = false;
    MeshFaceRecord face;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      const std::vector<std::string_view> tokens = split(text.substr(pos, end - pos));
      pos = end + 1;
      ++line_no;
      if (tokens.empty()) continue;
      const std::string keyword = lower(tokens[0]);
      if (keyword == "solid" || keyword == "endsolid" || keyword == "outer" ||
          keyword == "endloop") {
        continue;
      }
      if (keyword == "facet") {
        if (in_facet) fail(line_no, "'facet' before the previous facet's 'endfacet'", true);
        in_facet = true;
        face = MeshFaceRecord{};
        face.line = line_no;
      } else if (keyword == "vertex") {
        if (!in_facet) fail(line_no, "'vertex' outside a facet", false);
        if (tokens.size() < 4) fail(line_no, "a vertex needs 3 coordinates", true);
        face.vertices.push_back(static_cast<std::int64_t>(soup_.vertices.size()));
        soup_.vertices.emplace_back(coordinate(tokens[1], line_no), coordinate(tokens[2], line_no),
                                    coordinate(tokens[3], line_no));
      } else if (keyword == "endfacet") {
        if (!in_facet) fail(line_no, "'endfacet' without 'facet'", false);
        soup_.faces.push_back(std::move(face));
        in_facet = false;
      } else {
        fail(line_no, "unexpected '" + std::string(tokens[0]) + "'", in_facet);
      }
    }
    if (in_facet) fail(line_no, "the file ends inside a facet", true);
    return std::move(soup_);
  }

  std::string file_;
  std::string mesh_id_;
  MeshSoup soup_;
};

}  // namespace

MeshSoup parse_stl(std::string_view bytes, const std::filesystem::path& file,
                   const std::string& mesh_id) {
  return StlParser(file, mesh_id).parse(bytes);
}

}  // namespace shadowgen::detail
