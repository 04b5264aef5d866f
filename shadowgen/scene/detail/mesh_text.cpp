#include "mesh_text.h"

#include <cstdio>

#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

std::optional<std::string> text_problem(std::string_view bytes) {
  if (bytes.starts_with("\xFF\xFE") || bytes.starts_with("\xFE\xFF")) {
    return "not a text file (UTF-16?): it begins with a UTF-16 byte order mark; save it as "
           "UTF-8 or ASCII";
  }
  std::size_t line = 1;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c == '\n' || (c == '\r' && (i + 1 == bytes.size() || bytes[i + 1] != '\n'))) {
      ++line;
      continue;
    }
    if (c >= 0x20 && c != 0x7F) continue;
    if (c == '\t' || c == '\v' || c == '\f' || c == '\r') continue;
    if (c == 0) {
      return "not a text file (UTF-16?): a NUL byte on line " + std::to_string(line) +
             "; a text mesh file must be ASCII or UTF-8";
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", c);
    return "not a text file (binary?): control byte " + std::string(hex) + " on line " +
           std::to_string(line);
  }
  return std::nullopt;
}

void require_text(std::string_view bytes, const std::string& file) {
  if (std::optional<std::string> problem = text_problem(bytes))
    throw InputError(file, "", *problem);
}

std::vector<std::string_view> split_tokens(std::string_view line) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; };
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !space(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

std::string MeshParser::face_id() const {
  return mesh_id_ + "/" + std::to_string(soup_.faces.size());
}

void MeshParser::fail(const std::string& what, bool in_face) const {
  throw InputError(file_, in_face ? face_id() : "", what);
}

void MeshParser::fail_at(std::size_t line, const std::string& what, bool in_face) const {
  fail("line " + std::to_string(line) + ": " + what, in_face);
}

}  // namespace shadowgen::scene::detail
