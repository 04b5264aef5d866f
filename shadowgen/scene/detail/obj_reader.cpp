#include "obj_reader.h"

#include <charconv>
#include <cmath>
#include <vector>

#include "mesh_text.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

namespace {

class ObjParser : MeshParser {
 public:
  using MeshParser::MeshParser;

  MeshSoup parse(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte order mark
    // Unknown statements are skipped, as OBJ allows; so binary junk or UTF-16 text would
    // pass as a file of unknown statements if it were not refused here.
    require_text(text, file_);
    LineReader lines(text);
    std::string_view line;
    std::string statement;  // a statement may continue over lines ending in '\'
    std::size_t statement_line = 0;
    while (lines.next(line)) {
      if (statement.empty()) statement_line = lines.number();
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
  void handle(std::string_view statement, std::size_t line) {
    if (const std::size_t hash = statement.find('#'); hash != std::string_view::npos) {
      statement = statement.substr(0, hash);
    }
    const std::vector<std::string_view> tokens = split_tokens(statement);
    if (tokens.empty()) return;
    if (tokens[0] == "v") {
      // x y z, then an optional weight or colour (r g b, maybe a), which we do not use but
      // check: something else there (two vertices run together) would be lost unseen.
      if (tokens.size() < 4) fail_at(line, "a vertex needs 3 coordinates", false);
      if (tokens.size() > 8) {
        fail_at(line,
                "a vertex has 3 coordinates and at most a weight or a colour; this one has " +
                    std::to_string(tokens.size() - 1) + " numbers",
                false);
      }
      for (std::size_t i = 4; i < tokens.size(); ++i) {
        if (!parse_number(tokens[i])) {
          fail_at(line,
                  "'" + std::string(tokens[i]) + "' after a vertex's coordinates is not a number",
                  false);
        }
      }
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
      fail_at(line, "coordinate '" + std::string(token) + "' is out of the range of a double",
              false);
    }
    if (error != std::errc() || end != digits.data() + digits.size()) {
      fail_at(line, "coordinate '" + std::string(token) + "' is not a number", false);
    }
    if (!std::isfinite(value))
      fail_at(line, "coordinate '" + std::string(token) + "' is not finite", false);
    return value;
  }

  // "i", "i/t", "i/t/n" or "i//n": the vertex index i, 1-based, or negative counting back
  // from the last vertex read so far.
  std::int64_t index(std::string_view token, std::size_t line) const {
    const std::string_view digits = token.substr(0, token.find('/'));
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size()) {
      fail_at(line, "vertex index '" + std::string(token) + "' is not an integer", true);
    }
    const auto count = static_cast<std::int64_t>(soup_.vertices.size());
    if (value == 0) fail_at(line, "vertex index 0 (OBJ counts vertices from 1)", true);
    if (value < 0) {
      if (value < -count) {
        fail_at(
            line,
            "relative vertex index " + std::to_string(value) + " reaches before the first vertex",
            true);
      }
      return count + value;
    }
    return value - 1;
  }
};

}  // namespace

MeshSoup parse_obj(std::string_view text, const std::filesystem::path& file,
                   const std::string& mesh_id) {
  return ObjParser(file, mesh_id).parse(text);
}

}  // namespace shadowgen::scene::detail
