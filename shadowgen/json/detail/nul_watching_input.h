#pragma once

// A stream that reads another in order and notes whether any byte it has handed on was a
// NUL, so that JSON read from a file is checked for NUL bytes in the same pass that parses
// it: a gzip database is then inflated once, not once for the check and again to parse.

#include <cstddef>
#include <istream>
#include <streambuf>
#include <vector>

namespace shadowgen::json::detail {

class NulWatchingInput : public std::istream {
 public:
  // Reads `source` from where it stands; `source` must outlive this stream.
  explicit NulWatchingInput(std::istream& source);

  // Whether a NUL byte was among the bytes read from `source` so far (the buffer reads
  // ahead of what this stream's reader has taken, never past the end of `source`).
  bool saw_nul() const { return buffer_.saw_nul; }

 private:
  struct Buffer : std::streambuf {
    explicit Buffer(std::istream& from);
    int_type underflow() override;

    std::istream& source;
    std::vector<char> bytes;
    bool saw_nul = false;
  };
  Buffer buffer_;
};

}  // namespace shadowgen::json::detail
