#pragma once

// Lines of a text file, as the text readers (mesh files, weather files) walk them: ending
// in "\n", "\r\n" or a lone "\r" (old Mac files), given without their ending, numbered
// from 1 for messages.

#include <cstddef>
#include <string_view>

namespace shadowgen {

class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  // The next line; false at the end of the text.
  bool next(std::string_view& line);
  std::size_t number() const { return number_; }  // 1-based, of the line last returned
  std::size_t offset() const { return pos_; }     // where the next line begins

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

}  // namespace shadowgen
