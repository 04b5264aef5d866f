#pragma once

// A shadowgen JSON file as the command line meets it: a scene (`shadowgen-scene/1`) or a
// shadowed database (`shadowgen-shadowed/1`), told apart by the top-level "format" key
// (docs/scene-format.md).

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace shadowgen {

inline constexpr std::string_view kSceneFormat = "shadowgen-scene/1";
inline constexpr std::string_view kShadowedFormat = "shadowgen-shadowed/1";

struct Document {
  std::filesystem::path path;
  std::string text;
  std::string format;  // the value of the top-level "format" key
};

// The whole bytes of a file, or of standard input for "-"; InputError naming the file
// when it cannot be read (`what` says what it is in the message: "file", "mesh file").
std::string read_text_file(const std::filesystem::path& path, std::string_view what = "file");

// A file opened for reading, in binary; InputError naming it, as read_text_file words
// it, when it is a folder, is not there or cannot be opened.
std::ifstream open_input_file(const std::filesystem::path& path, std::string_view what = "file");

// The value of the top-level "format" key. The text is scanned only up to that key,
// without building the document, so a large file costs one pass of the tokenizer.
// InputError (naming `path`) when the text is not a JSON object, has no "format" key
// before a syntax error, or the key is not a string.
std::string document_format(const std::string& json_text, const std::filesystem::path& path);

// The same for a file (not "-"), read only up to that key.
std::string file_format(const std::filesystem::path& path);

Document read_document(const std::filesystem::path& path);

}  // namespace shadowgen
