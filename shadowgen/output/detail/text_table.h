#pragma once

// Plain-text tables for reading in a terminal (report --format table, compare): columns as
// wide as their widest cell, counted in UTF-8 code points (continuation bytes 10xxxxxx take
// no room), so ids in any script line up in a monospaced terminal.

#include <string>
#include <utility>
#include <vector>

namespace shadowgen::output::detail {

class TextTable {
 public:
  // One entry per column: true where the column is right-aligned (numbers).
  explicit TextTable(std::vector<bool> right_aligned) : right_aligned_(std::move(right_aligned)) {}

  void add(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }

  // Each row on a line, columns two spaces apart, no trailing spaces.
  void append_to(std::string& out) const;

 private:
  std::vector<bool> right_aligned_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace shadowgen::output::detail
