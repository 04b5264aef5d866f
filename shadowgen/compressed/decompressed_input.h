#pragma once

// Input read as it was written, gzip (RFC 1952) or not: a file whose first two bytes are
// gzip's magic (1f 8b) is decompressed as it is read, every member of it in turn (as
// `zcat` reads concatenated members); any other file is read as it is. The name plays no
// part, so a renamed file reads the same.
//
// Errors are InputError naming the file: "FILE: the gzip data ends before its last member
// does (a truncated file)", "FILE: corrupt gzip data in the member at byte N: WHAT" (zlib's
// words: "incorrect data check" for a wrong CRC-32, "invalid block type", ...), or
// "FILE: cannot read the file". They are thrown from the stream's reads and pass through
// std::istream (whose badbit is made to throw): a reader never mistakes a broken file for
// its end.

#include <cstddef>
#include <fstream>
#include <istream>
#include <memory>
#include <string>
#include <string_view>

namespace shadowgen::compressed {

// Whether `bytes` begins as a gzip file does (1f 8b).
bool is_gzip(std::string_view bytes);

// An input stream over `source`, decompressed where it is gzip. It can be rewound
// (seekg(0)) to be read again from the start, and tells how far it has read (tellg, in
// decompressed bytes); no other seek.
class DecompressedInput : public std::istream {
 public:
  // `name`: the file as messages name it.
  DecompressedInput(std::unique_ptr<std::istream> source, std::string name);
  DecompressedInput(std::ifstream file, std::string name);
  ~DecompressedInput() override;

  // Whether the source is gzip.
  bool compressed() const;

 private:
  class Buffer;
  std::unique_ptr<Buffer> buffer_;
};

// `text` itself, or decompressed where it is gzip; errors as above, naming `name`.
std::string decompressed_text(std::string text, const std::string& name);

}  // namespace shadowgen::compressed
