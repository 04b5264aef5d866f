#include "obj_reader.h"

#include <charconv>
#include <cmath>
#include <vector>

#include "shadowgen/model/input_error.h"

namespace shadowgen::detail {

namespace {

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

class ObjParser {
 public:
  ObjParser(const std::filesystem::path& file, const std::string& mesh_id)
      : file_(file.string()), mesh_id_(mesh_id) {}

  MeshSoup parse(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte order mark
    std::size_t pos = 0;
    std::size_t line_no = 0;
    std::string statement;  // a statement may continue over lines ending in '\'
    std::size_t statement_line = 0;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(pos, end - pos);
      pos = end + 1;
      ++line_no;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (statement.empty()) statement_line = line_no;
      if (!line.empty() && line.back() == '\\') {
        statement.append(line.substr(0, line.size() - 1));
        statement += ' ';
        continue;
      }
      statement.append(line);
      handle(statement, statement_line);
      statement.clear();
    }
    if (!statement.empty()) handle(statement, statement_line);
    return std::move(soup_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what, bool in_face) const {
    throw InputError(file_, in_face ? mesh_id_ + "/" + std::to_string(soup_.faces.size()) : "",
                     "line " + std::to_string(line) + ": " + what);
  }

  void handle(std::string_view statement, std::size_t line) {
    if (const std::size_t hash = statement.find('#'); hash != std::string_view::npos) {
      statement = statement.substr(0, hash);
    }
    const std::vector<std::string_view> tokens = split(statement);
    if (tokens.empty()) return;
    if (tokens[0] == "v") {
      // x y z, then an optional weight or colour, which we do not use.
      if (tokens.size() < 4) fail(line, "a vertex needs 3 coordinates", false);
      soup_.vertices.emplace_back(coordinate(tokens[1], line), coordinate(tokens[2], line),
                                  coordinate(tokens[3], line));
    } else if (tokens[0] == "f" || tokens[0] == "fo") {
      MeshFaceRecord face;
      face.line = line;
      for (std::size_t i = 1; i < tokens.size(); ++i)
        face.vertices.push_back(index(tokens[i], line));
      soup_.faces.push_back(std::move(face));
    }
  }

  double coordinate(std::string_view token, std::size_t line) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range) {
      fail(line, "coordinate '" + std::string(token) + "' is out of the range of a double", false);
    }
    if (error != std::errc() || end != digits.data() + digits.size()) {
      fail(line, "coordinate '" + std::string(token) + "' is not a number", false);
    }
    if (!std::isfinite(value))
      fail(line, "coordinate '" + std::string(token) + "' is not finite", false);
    return value;
  }

  // "i", "i/t", "i/t/n" or "i//n": the vertex index i, 1-based, or negative counting back
  // from the last vertex read so far.
  std::int64_t index(std::string_view token, std::size_t line) const {
    const std::string_view digits = token.substr(0, token.find('/'));
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size()) {
      fail(line, "vertex index '" + std::string(token) + "' is not an integer", true);
    }
    const auto count = static_cast<std::int64_t>(soup_.vertices.size());
    if (value == 0) fail(line, "vertex index 0 (OBJ counts vertices from 1)", true);
    if (value < 0) {
      if (value < -count) {
        fail(line,
             "relative vertex index " + std::to_string(value) + " reaches before the first vertex",
             true);
      }
      return count + value;
    }
    return value - 1;
  }

  std::string file_;
  std::string mesh_id_;
  MeshSoup soup_;
};

}  // namespace

MeshSoup parse_obj(std::string_view text, const std::filesystem::path& file,
                   const std::string& mesh_id) {
  return ObjParser(file, mesh_id).parse(text);
}

}  // namespace shadowgen::detail
