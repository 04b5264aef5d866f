#pragma once

// What the text mesh readers (OBJ, ASCII STL, OFF, PLY) share: telling text from binary
// junk and UTF-16, lines, tokens and numbers.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_reader.h"
#include "shadowgen/model/line_reader.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::scene::detail {

// Why `bytes` is not text, or nullopt when it is. Text is ASCII or UTF-8 (any byte from
// 0x80 up passes, so a Latin-1 comment does too) without control characters other than
// tab, line feed, vertical tab, form feed and carriage return. A UTF-16 or UTF-32 byte
// order mark or a NUL byte says "not a text file (UTF-16?)"; other control bytes say
// "not a text file (binary?)", with the line they are on.
std::optional<std::string> text_problem(std::string_view bytes);

// Throws InputError(file, "", the problem) when `bytes` is not text.
void require_text(std::string_view bytes, const std::string& file);

// Tokens separated by spaces, tabs, vertical tabs and form feeds.
std::vector<std::string_view> split_tokens(std::string_view line);

// What every mesh parser keeps: the file and mesh id its errors name, and the soup it fills.
class MeshParser {
 public:
  MeshParser(const std::filesystem::path& file, const std::string& mesh_id)
      : file_(file.string()), mesh_id_(mesh_id) {}

 protected:
  // "<mesh id>/<index>" of the face being read next.
  std::string face_id() const;
  // Throws InputError(file, the next face's id when in_face or "", what).
  [[noreturn]] void fail(const std::string& what, bool in_face = false) const;
  // As fail, with "line <line>: " before what.
  [[noreturn]] void fail_at(std::size_t line, const std::string& what, bool in_face = false) const;

  std::string file_;
  std::string mesh_id_;
  MeshSoup soup_;
};

}  // namespace shadowgen::scene::detail
