#pragma once

// A shadowgen JSON file as the command line meets it: a scene (`shadowgen-scene/1`) or a
// shadowed database (its versions: shadowgen/database/database_format.h), told apart by
// the top-level "format" key (docs/scene-format.md).

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

namespace shadowgen {

inline constexpr std::string_view kSceneFormat = "shadowgen-scene/1";

struct Document {
  std::filesystem::path path;
  std::string text;
  std::string format;  // the value of the top-level "format" key
};

// No bound on the bytes read_text_file reads.
inline constexpr std::size_t kNoSizeLimit = static_cast<std::size_t>(-1);

// Why `path` cannot be read as an input file, as InputError's problem words it: "no such
// file", "is a folder, not a file", or, for a device or a socket, "is not a regular file
// (a character device)" (a device reads without end or not at all: /dev/zero,
// /dev/urandom, a terminal). nullopt for a regular file or a FIFO (a pipe, as a shell's
// <(...) gives one), which are read.
std::optional<std::string> unreadable_input(const std::filesystem::path& path);

// The whole bytes of a file, or of standard input for "-"; InputError naming the file
// when it cannot be read (`what` says what it is in the message: "file", "mesh file"),
// or when it holds more than `max_bytes`: "is larger than a <what> can be (more than N
// bytes)", found from a regular file's size before reading, and from a stream once
// max_bytes + 1 bytes are read, so that one without end is not read on.
std::string read_text_file(const std::filesystem::path& path, std::string_view what = "file",
                           std::size_t max_bytes = kNoSizeLimit);

// A file opened for reading, in binary; InputError naming it, as read_text_file words
// it, when unreadable_input says why it cannot be read or it cannot be opened.
std::ifstream open_input_file(const std::filesystem::path& path, std::string_view what = "file");

// The value of the top-level "format" key. The text is scanned only up to that key,
// without building the document, so a large file costs one pass of the tokenizer.
// InputError (naming `path`) when the text is not a JSON object, has no "format" key
// before a syntax error or a NUL byte (placed by line and column, as the JSON reader
// places one), or the key is not a string.
std::string document_format(const std::string& json_text, const std::filesystem::path& path);

// The same for a file (not "-"), read only up to that key.
std::string file_format(const std::filesystem::path& path);

Document read_document(const std::filesystem::path& path);

}  // namespace shadowgen
