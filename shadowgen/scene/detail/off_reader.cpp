#include "off_reader.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "mesh_text.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

namespace {

// What the header keyword announces.
struct Layout {
  bool texture = false;      // ST: s t after the vertex
  bool colour = false;       // C: a colour after the vertex
  bool normal = false;       // N: a normal after the vertex
  bool homogeneous = false;  // 4: x y z w
  bool dimension = false;    // n: Ndim before the counts
};

// "[ST][C][N][4][n]OFF", and in `rest` whatever the token has after "OFF".
std::optional<Layout> header_keyword(std::string_view token, std::string_view& rest) {
  auto take = [&token](std::string_view prefix) {
    if (!token.starts_with(prefix)) return false;
    token.remove_prefix(prefix.size());
    return true;
  };
  Layout layout;
  layout.texture = take("ST");
  layout.colour = take("C");
  layout.normal = take("N");
  layout.homogeneous = take("4");
  layout.dimension = take("n");
  if (!take("OFF")) return std::nullopt;
  rest = token;
  return layout;
}

std::string counted(std::int64_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

class OffParser : MeshParser {
 public:
  using MeshParser::MeshParser;

  MeshSoup parse(std::string_view bytes) {
    if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);  // a UTF-8 byte order mark
    {
      // Binary OFF says so on its first line; its body is not text.
      LineReader first(bytes);
      std::string_view line;
      first.next(line);
      const std::vector<std::string_view> tokens = split_tokens(line.substr(0, line.find('#')));
      std::string_view rest;
      if (tokens.size() == 2 && tokens[1] == "BINARY") {
        if (const std::optional<Layout> layout = header_keyword(tokens[0], rest);
            layout && rest.empty()) {
          require_text(bytes.substr(0, first.offset()), file_);
          return parse_binary(bytes.substr(first.offset()), *layout);
        }
      }
    }
    require_text(bytes, file_);
    return parse_text(bytes);
  }

 private:
  // ---- Text ------------------------------------------------------------------------

  // The next line with something on it besides a comment, split into tokens_.
  bool next_record() {
    std::string_view line;
    while (lines_->next(line)) {
      tokens_ = split_tokens(line.substr(0, line.find('#')));
      if (!tokens_.empty()) return true;
    }
    return false;
  }

  std::int64_t count(std::string_view token, const char* what) const {
    const std::optional<std::int64_t> n = parse_integer(token);
    if (!n) {
      fail_at(lines_->number(),
              std::string("the ") + what + " count '" + std::string(token) + "' is not an integer");
    }
    if (*n < 0) {
      fail_at(lines_->number(),
              std::string("the ") + what + " count is negative (" + std::string(token) + ")");
    }
    return *n;
  }

  MeshSoup parse_text(std::string_view text) {
    LineReader lines(text);
    lines_ = &lines;
    if (!next_record()) fail("not an OFF file: it is empty");
    std::vector<std::string_view> header = tokens_;
    const Layout layout = read_keyword(header);
    const auto [vertex_count, face_count] = read_counts(header, layout);
    const auto room = static_cast<std::int64_t>(text.size() / 2);
    soup_.vertices.reserve(static_cast<std::size_t>(std::min(vertex_count, room)));
    soup_.faces.reserve(static_cast<std::size_t>(std::min(face_count, room)));

    for (std::int64_t v = 0; v < vertex_count; ++v) {
      if (!next_record()) {
        fail("the file ends after " + std::to_string(v) + " of the " +
             counted(vertex_count, "vertex", "vertices") + " its header announces (truncated?)");
      }
      read_text_vertex(layout);
    }
    for (std::int64_t f = 0; f < face_count; ++f) {
      if (!next_record()) {
        fail("the file ends after " + std::to_string(f) + " of the " +
             counted(face_count, "face", "faces") + " its header announces (truncated?)");
      }
      read_text_face();
    }
    if (next_record()) {
      fail_at(lines.number(), "more data after the " + counted(vertex_count, "vertex", "vertices") +
                                  " and " + counted(face_count, "face", "faces") +
                                  " the header announces");
    }
    return std::move(soup_);
  }

  // The header keyword, optional in text OFF, from the first record (`header`, which is
  // left with the tokens after it); the counts may follow it on its line, even run
  // together with it.
  Layout read_keyword(std::vector<std::string_view>& header) const {
    std::string_view rest;
    const std::optional<Layout> keyword = header_keyword(tokens_[0], rest);
    if (keyword ? !rest.empty() && !parse_integer(rest) : !parse_integer(tokens_[0])) {
      fail_at(lines_->number(), "not an OFF file: it begins with '" + std::string(tokens_[0]) +
                                    "', not 'OFF' (or its variants) nor its counts");
    }
    if (keyword) {
      header.erase(header.begin());
      if (!rest.empty()) header.insert(header.begin(), rest);
    }
    for (const std::string_view token : header) {
      if (token == "BINARY") fail_at(lines_->number(), "'BINARY' must follow the header keyword");
    }
    return keyword.value_or(Layout{});
  }

  // [Ndim] NVertices NFaces, then NEdges if on NFaces' line; `header` holds the tokens
  // left on the keyword's line. Returns NVertices and NFaces.
  std::pair<std::int64_t, std::int64_t> read_counts(std::vector<std::string_view> header,
                                                    const Layout& layout) {
    const std::size_t wanted = layout.dimension ? 3 : 2;
    std::vector<std::int64_t> counts;
    std::size_t at = 0;
    while (counts.size() < wanted) {
      if (at == header.size()) {
        if (!next_record()) fail("the file ends in its header, before the vertex and face counts");
        header = tokens_;
        at = 0;
        continue;
      }
      const char* what = counts.size() + 2 == wanted   ? "vertex"
                         : counts.size() + 1 == wanted ? "face"
                                                       : "dimension";
      counts.push_back(count(header[at++], what));
    }
    if (at < header.size()) count(header[at++], "edge");
    if (at < header.size()) {
      fail_at(lines_->number(), "unexpected '" + std::string(header[at]) + "' after the counts");
    }
    if (layout.dimension && counts[0] != 3) {
      fail_at(lines_->number(), "only 3-dimensional OFF is read; this one has dimension " +
                                    std::to_string(counts[0]));
    }
    return {counts[wanted - 2], counts[wanted - 1]};
  }

  // One vertex line, in tokens_.
  void read_text_vertex(const Layout& layout) {
    const std::size_t coordinates = layout.homogeneous ? 4 : 3;
    const std::size_t fixed = (layout.normal ? 3 : 0) + (layout.texture ? 2 : 0);
    const std::size_t least = coordinates + fixed + (layout.colour ? 1 : 0);
    const std::size_t most = coordinates + fixed + (layout.colour ? 4 : 0);
    if (tokens_.size() < least || tokens_.size() > most) {
      fail_at(lines_->number(),
              "a vertex line here has " +
                  (least == most ? std::to_string(least)
                                 : std::to_string(least) + " to " + std::to_string(most)) +
                  " numbers; this one has " + std::to_string(tokens_.size()));
    }
    double xyzw[4] = {0, 0, 0, 1};
    for (std::size_t i = 0; i < tokens_.size(); ++i) {
      const std::optional<double> x = parse_number(tokens_[i]);
      if (!x || (i < coordinates && !std::isfinite(*x))) {
        fail_at(lines_->number(), (i < coordinates ? "coordinate '" : "'") +
                                      std::string(tokens_[i]) + "' is not a finite number");
      }
      if (i < coordinates) xyzw[i] = *x;
    }
    soup_.vertices.push_back(point(xyzw, layout.homogeneous, lines_->number()));
  }

  // One face line, in tokens_: its vertex count, indices and an optional colour.
  void read_text_face() {
    const std::size_t line = lines_->number();
    const std::optional<std::int64_t> k = parse_integer(tokens_[0]);
    if (!k || *k < 0) {
      fail_at(
          line,
          "the face's vertex count '" + std::string(tokens_[0]) + "' is not a non-negative integer",
          true);
    }
    const auto listed = static_cast<std::int64_t>(tokens_.size()) - 1;
    if (listed < *k) {
      fail_at(line,
              "the face announces " + counted(*k, "vertex index", "vertex indices") +
                  " but lists " + std::to_string(listed),
              true);
    }
    if (listed - *k > 4) {
      fail_at(line,
              "the face has " + std::to_string(listed - *k) + " numbers after its " +
                  counted(*k, "vertex index", "vertex indices") + "; a colour has at most 4",
              true);
    }
    MeshFaceRecord face;
    face.line = line;
    face.vertices.reserve(static_cast<std::size_t>(*k));
    for (std::size_t i = 1; i < tokens_.size(); ++i) {
      if (static_cast<std::int64_t>(i) <= *k) {
        const std::optional<std::int64_t> index = parse_integer(tokens_[i]);
        if (!index) {
          fail_at(line, "vertex index '" + std::string(tokens_[i]) + "' is not an integer", true);
        }
        face.vertices.push_back(*index);
      } else if (!parse_number(tokens_[i])) {
        fail_at(line, "colour '" + std::string(tokens_[i]) + "' is not a number", true);
      }
    }
    soup_.faces.push_back(std::move(face));
  }

  glm::dvec3 point(const double (&xyzw)[4], bool homogeneous, std::size_t line) const {
    if (!homogeneous || xyzw[3] == 1.0) return {xyzw[0], xyzw[1], xyzw[2]};
    const double w = xyzw[3];
    const glm::dvec3 p(xyzw[0] / w, xyzw[1] / w, xyzw[2] / w);
    if (w == 0.0 || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      const std::string where = line > 0 ? "line " + std::to_string(line) + ": " : "";
      fail(where + "the homogeneous vertex is at infinity, or beyond a double's range");
    }
    return p;
  }

  // ---- Binary ----------------------------------------------------------------------

  class Cursor {
   public:
    Cursor(std::string_view bytes, bool big_endian) : bytes_(bytes), big_(big_endian) {}
    bool i32(std::int32_t& value) {
      std::uint32_t u = 0;
      if (!u32(u)) return false;
      value = std::bit_cast<std::int32_t>(u);
      return true;
    }
    bool f32(float& value) {
      std::uint32_t u = 0;
      if (!u32(u)) return false;
      value = std::bit_cast<float>(u);
      return true;
    }
    std::size_t left() const { return bytes_.size() - pos_; }

   private:
    bool u32(std::uint32_t& value) {
      if (left() < 4) return false;
      value = 0;
      for (int i = 0; i < 4; ++i) {
        const auto byte = static_cast<unsigned char>(bytes_[pos_ + (big_ ? i : 3 - i)]);
        value = (value << 8) | byte;
      }
      pos_ += 4;
      return true;
    }
    std::string_view bytes_;
    std::size_t pos_ = 0;
    bool big_;
  };

  MeshSoup parse_binary(std::string_view body, const Layout& layout) {
    MeshSoup big;
    Cursor big_in(body, true);
    const std::optional<std::string> big_problem = read_binary(big_in, layout, big);
    if (!big_problem) return big;
    MeshSoup little;
    Cursor little_in(body, false);
    const std::optional<std::string> little_problem = read_binary(little_in, layout, little);
    if (!little_problem) return little;
    // Neither reads the file: the one that got further is the file's byte order, most
    // likely, and its problem the file's.
    if (little_in.left() < big_in.left()) fail("binary OFF (little-endian): " + *little_problem);
    fail("binary OFF (big-endian): " + *big_problem);
  }

  // Reads the whole body into `out`; what is wrong otherwise.
  std::optional<std::string> read_binary(Cursor& in, const Layout& layout, MeshSoup& out) const {
    const std::string truncated = "the file ends early (truncated?)";
    std::int32_t counts[4] = {3, 0, 0, 0};
    for (int i = layout.dimension ? 0 : 1; i < 4; ++i) {
      if (!in.i32(counts[i])) return truncated;
    }
    if (counts[0] != 3) return "only 3-dimensional OFF is read";
    if (counts[1] < 0 || counts[2] < 0) return "a negative vertex or face count";
    const std::size_t floats = (layout.homogeneous ? 4 : 3) + (layout.normal ? 3 : 0) +
                               (layout.colour ? 4 : 0) + (layout.texture ? 2 : 0);
    if (static_cast<std::uint64_t>(counts[1]) * floats * 4 > in.left()) {
      return "the file ends before the " + counted(counts[1], "vertex", "vertices") +
             " its header announces end (truncated?)";
    }
    out.vertices.reserve(static_cast<std::size_t>(counts[1]));
    for (std::int32_t v = 0; v < counts[1]; ++v) {
      double xyzw[4] = {0, 0, 0, 1};
      for (std::size_t i = 0; i < floats; ++i) {
        float x = 0;
        in.f32(x);
        if (i < (layout.homogeneous ? 4u : 3u)) {
          if (!std::isfinite(x)) return "vertex " + std::to_string(v) + " is not finite";
          xyzw[i] = x;
        }
      }
      if (layout.homogeneous &&
          (xyzw[3] == 0.0 || !std::isfinite(xyzw[0] / xyzw[3]) ||
           !std::isfinite(xyzw[1] / xyzw[3]) || !std::isfinite(xyzw[2] / xyzw[3]))) {
        return "vertex " + std::to_string(v) + " is at infinity";
      }
      out.vertices.push_back(point(xyzw, layout.homogeneous, 0));
    }
    for (std::int32_t f = 0; f < counts[2]; ++f) {
      std::int32_t k = 0;
      if (!in.i32(k)) {
        return "the file ends after " + std::to_string(f) + " of the " +
               counted(counts[2], "face", "faces") + " its header announces (truncated?)";
      }
      if (k < 0 || static_cast<std::uint64_t>(k) * 4 > in.left()) {
        return "face " + std::to_string(f) + " announces " + std::to_string(k) +
               " vertices, more than the file holds";
      }
      MeshFaceRecord face;
      face.vertices.reserve(static_cast<std::size_t>(k));
      for (std::int32_t i = 0; i < k; ++i) {
        std::int32_t index = 0;
        in.i32(index);
        face.vertices.push_back(index);
      }
      std::int32_t colours = 0;
      if (!in.i32(colours)) return truncated;
      if (colours < 0 || colours > 4) {
        return "face " + std::to_string(f) + " has a colour of " + std::to_string(colours) +
               " numbers; at most 4";
      }
      for (std::int32_t i = 0; i < colours; ++i) {
        float c = 0;
        if (!in.f32(c)) return truncated;
      }
      out.faces.push_back(std::move(face));
    }
    if (in.left() != 0) {
      return std::to_string(in.left()) + " bytes after the last face the header announces";
    }
    return std::nullopt;
  }

  MeshSoup soup_;
  LineReader* lines_ = nullptr;
  std::vector<std::string_view> tokens_;
};

}  // namespace

MeshSoup parse_off(std::string_view bytes, const std::filesystem::path& file,
                   const std::string& mesh_id) {
  return OffParser(file, mesh_id).parse(bytes);
}

}  // namespace shadowgen::scene::detail
