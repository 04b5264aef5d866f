#include "stl_reader.h"

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <vector>

#include "mesh_text.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

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

class StlParser : MeshParser {
 public:
  using MeshParser::MeshParser;

  MeshSoup parse(std::string_view bytes) {
    // Binary when the size fits the triangle count, whatever the header says: many
    // binary files begin their 80-byte header with "solid" too.
    std::uint64_t count = 0;
    if (bytes.size() >= 84) {
      count = little_endian_u32(bytes.data() + 80);
      if (bytes.size() == 84 + 50 * count) return parse_binary(bytes, count);
    }
    if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);  // a UTF-8 byte order mark
    if (const std::optional<std::string> problem = text_problem(bytes)) {
      if (bytes.size() < 84) {
        throw InputError(file_, "",
                         "not an STL file: " + *problem +
                             ", and too short for binary STL (an 84-byte header, then 50 "
                             "bytes a triangle)");
      }
      throw InputError(file_, "",
                       "not an STL file: " + *problem + ", and as binary STL its size, " +
                           std::to_string(bytes.size()) + " bytes, does not match the " +
                           std::to_string(count) + " triangles its header announces (84 + 50 * " +
                           std::to_string(count) + " = " + std::to_string(84 + 50 * count) +
                           " bytes; truncated?)");
    }
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

  double coordinate(std::string_view token, std::size_t line) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value)) {
      fail_at(line, "coordinate '" + std::string(token) + "' is not a finite number", true);
    }
    return value;
  }

  // solid NAME, then per facet: facet normal N N N / outer loop / vertex X Y Z ... /
  // endloop / endfacet, then endsolid NAME; several solids may follow each other. Normals
  // are not used (nor checked: some writers put "nan" there for degenerate facets).
  MeshSoup parse_ascii(std::string_view text) {
    enum class State { kOutside, kSolid, kFacet, kLoop, kLoopDone };
    State state = State::kOutside;
    LineReader lines(text);
    std::string_view line;
    MeshFaceRecord face;
    auto expect = [&](bool ok, const std::string& keyword, const char* where) {
      if (!ok) {
        fail_at(lines.number(), "'" + keyword + "' " + where,
                state == State::kFacet || state == State::kLoop || state == State::kLoopDone);
      }
    };
    while (lines.next(line)) {
      const std::vector<std::string_view> tokens = split_tokens(line);
      if (tokens.empty()) continue;
      const std::string keyword = lower(tokens[0]);
      if (keyword == "solid") {
        expect(state == State::kOutside, keyword, "inside a solid");
        state = State::kSolid;
      } else if (keyword == "endsolid") {
        expect(state == State::kSolid, keyword, "outside a solid, or inside a facet");
        state = State::kOutside;
      } else if (keyword == "facet") {
        expect(state == State::kSolid, keyword, "outside a solid, or inside another facet");
        state = State::kFacet;
        face = MeshFaceRecord{};
        face.line = lines.number();
      } else if (keyword == "outer") {
        expect(state == State::kFacet, keyword, "outside a facet, or twice in one");
        state = State::kLoop;
      } else if (keyword == "vertex") {
        expect(state == State::kLoop, keyword, "outside a facet's 'outer loop'");
        if (tokens.size() != 4) fail_at(lines.number(), "a vertex needs 3 coordinates", true);
        face.vertices.push_back(static_cast<std::int64_t>(soup_.vertices.size()));
        soup_.vertices.emplace_back(coordinate(tokens[1], lines.number()),
                                    coordinate(tokens[2], lines.number()),
                                    coordinate(tokens[3], lines.number()));
      } else if (keyword == "endloop") {
        expect(state == State::kLoop, keyword, "without 'outer loop'");
        state = State::kLoopDone;
      } else if (keyword == "endfacet") {
        expect(state == State::kLoopDone, keyword, "without 'facet' and its loop");
        soup_.faces.push_back(std::move(face));
        state = State::kSolid;
      } else {
        fail_at(lines.number(), "unexpected '" + std::string(tokens[0]) + "'",
                state == State::kFacet || state == State::kLoop || state == State::kLoopDone);
      }
    }
    if (state == State::kSolid) {
      fail_at(lines.number(), "the file ends before 'endsolid' (truncated?)", false);
    }
    if (state != State::kOutside) fail_at(lines.number(), "the file ends inside a facet", true);
    return std::move(soup_);
  }
};

}  // namespace

MeshSoup parse_stl(std::string_view bytes, const std::filesystem::path& file,
                   const std::string& mesh_id) {
  return StlParser(file, mesh_id).parse(bytes);
}

}  // namespace shadowgen::scene::detail
