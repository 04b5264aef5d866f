#include "shadowgen/json/document.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <system_error>

#include "detail/json_parse.h"
#include "shadowgen/compressed/decompressed_input.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen {
namespace {

using Json = nlohmann::json;

// SAX handler that stops at the value of the top-level "format" key. Returning false
// from any event ends the scan.
class FormatScanner {
 public:
  explicit FormatScanner(json::detail::Locate locate) : locate_(std::move(locate)) {}

  // The outcome once the scan has stopped: the format, or why there is none.
  std::optional<std::string> format;
  std::string problem = "no \"format\" key";

  bool null() { return value("null"); }
  bool boolean(bool) { return value("a boolean"); }
  bool number_integer(Json::number_integer_t) { return value("a number"); }
  bool number_unsigned(Json::number_unsigned_t) { return value("a number"); }
  bool number_float(Json::number_float_t, const Json::string_t&) { return value("a number"); }
  bool binary(Json::binary_t&) { return value("binary data"); }
  bool string(Json::string_t& s) {
    if (depth_ == 1 && expecting_format_) {
      format = s;
      return false;
    }
    return value("a string");
  }
  bool start_object(std::size_t) { return open("an object"); }
  bool end_object() { return close(); }
  bool start_array(std::size_t) {
    if (depth_ == 0) {
      problem = "the top level is an array, not an object";
      return false;
    }
    return open("an array");
  }
  bool end_array() { return close(); }
  bool key(Json::string_t& k) {
    if (depth_ == 1) expecting_format_ = (k == "format");
    return true;
  }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& e) {
    problem = json::detail::describe_parse_error(locate_, position, last_token, e.id, e.what());
    error_end = position;
    return false;
  }

  // The bytes read up to a syntax error (a NUL byte among them ends the text for the
  // parser); nullopt where there was none.
  std::optional<std::size_t> error_end;

 private:
  bool value(const char* what) {
    if (depth_ == 0) {
      problem = std::string("the top level is ") + what + ", not an object";
      return false;
    }
    return check_format_value(what);
  }
  bool check_format_value(const char* what) {
    if (depth_ == 1 && expecting_format_) {
      problem = std::string("\"format\" is ") + what + ", not a string";
      return false;
    }
    return true;
  }

  json::detail::Locate locate_;
  bool open(const char* what) {
    if (!check_format_value(what)) return false;
    ++depth_;
    return true;
  }
  bool close() {
    --depth_;
    return true;
  }

  int depth_ = 0;
  bool expecting_format_ = false;
};

// InputError naming `path` for a scan that found no format: what the scanner found, or
// the NUL byte that ended the text for the parser where one did (`text`: the text scanned,
// or the stream it was read from).
template <class Text>
[[noreturn]] void refuse(const FormatScanner& scanner, Text& text,
                         const std::filesystem::path& path) {
  std::optional<std::string> nul;
  if (scanner.error_end) nul = json::detail::nul_problem(text, *scanner.error_end);
  throw InputError(path.string(), "", nul.value_or(scanner.problem));
}

}  // namespace

std::optional<std::string> unreadable_input(const std::filesystem::path& path) {
  std::error_code error;
  switch (std::filesystem::status(path, error).type()) {  // of what a link leads to
    case std::filesystem::file_type::not_found:
      return "no such file";
    case std::filesystem::file_type::directory:
      return "is a folder, not a file";
    case std::filesystem::file_type::character:
      return "is not a regular file (a character device)";
    case std::filesystem::file_type::block:
      return "is not a regular file (a block device)";
    case std::filesystem::file_type::socket:
      return "is not a regular file (a socket)";
    default:  // a regular file, a FIFO, or one whose kind is unknown: opening it tells
      return std::nullopt;
  }
}

std::ifstream open_input_file(const std::filesystem::path& path, std::string_view what) {
  if (std::optional<std::string> why = unreadable_input(path)) {
    throw InputError(path.string(), "", *why);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open the " + std::string(what));
  return in;
}

namespace {

[[noreturn]] void throw_too_large(const std::filesystem::path& path, std::string_view what,
                                  std::size_t max_bytes) {
  throw InputError(path.string(), "",
                   "is larger than a " + std::string(what) + " can be (more than " +
                       std::to_string(max_bytes) + " bytes)");
}

// Appends to `text` what `in` reads up to its end, in pieces, so that a stream without
// end is refused once `text` would hold more than `max_bytes`.
void read_rest(std::istream& in, std::string& text, const std::filesystem::path& path,
               std::string_view what, std::size_t max_bytes) {
  constexpr std::size_t kPiece = std::size_t{1} << 16;
  std::string piece(kPiece, '\0');
  while (in) {
    in.read(piece.data(), static_cast<std::streamsize>(kPiece));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got > max_bytes - std::min(max_bytes, text.size())) throw_too_large(path, what, max_bytes);
    text.append(piece, 0, got);
  }
  if (in.bad()) {
    throw InputError(
        path.string(), "",
        path == "-" ? "cannot read standard input" : "cannot read the " + std::string(what));
  }
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path, std::string_view what,
                           std::size_t max_bytes) {
  std::string text;
  if (path == "-") {
    read_rest(std::cin, text, path, what, max_bytes);
    return text;
  }
  std::ifstream in = open_input_file(path, what);
  std::error_code error;
  // A regular file is read into a string of its size: a growing buffer would hold up to
  // twice a large database at once.
  if (std::filesystem::is_regular_file(path, error)) {
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error) {
      if (size > max_bytes) throw_too_large(path, what, max_bytes);
      text.resize(static_cast<std::size_t>(size));
      in.read(text.data(), static_cast<std::streamsize>(size));
      text.resize(static_cast<std::size_t>(in.gcount()));  // shorter if it shrank meanwhile
      if (in.bad()) throw InputError(path.string(), "", "cannot read the " + std::string(what));
      in.clear();
    }
  }
  read_rest(in, text, path, what, max_bytes);  // all of a stream, what a file grew by
  return text;
}

std::string document_format(const std::string& json_text, const std::filesystem::path& path) {
  FormatScanner scanner([&json_text](std::size_t offset) {
    return json::detail::line_column(std::string_view(json_text), offset);
  });
  Json::sax_parse(json_text, &scanner);
  if (!scanner.format) refuse(scanner, json_text, path);
  return *scanner.format;
}

std::string file_format(const std::filesystem::path& path) {
  compressed::DecompressedInput in(open_input_file(path), path.string());
  FormatScanner scanner(
      [&in](std::size_t offset) { return json::detail::line_column(in, offset); });
  Json::sax_parse(in, &scanner);
  if (!scanner.format) refuse(scanner, in, path);
  return *scanner.format;
}

Document read_document(const std::filesystem::path& path) {
  Document document;
  document.path = path;
  document.text = compressed::decompressed_text(read_text_file(path), path.string());
  document.format = document_format(document.text, path);
  return document;
}

}  // namespace shadowgen
