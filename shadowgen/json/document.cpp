#include "shadowgen/json/document.h"

#include <cstdint>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <system_error>

#include "detail/json_parse.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen {
namespace {

using Json = nlohmann::json;

// SAX handler that stops at the value of the top-level "format" key. Returning false
// from any event ends the scan.
class FormatScanner {
 public:
  explicit FormatScanner(detail::Locate locate) : locate_(std::move(locate)) {}

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
    problem = detail::describe_parse_error(locate_, position, last_token, e.id, e.what());
    return false;
  }

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

  detail::Locate locate_;
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

}  // namespace

std::ifstream open_input_file(const std::filesystem::path& path, std::string_view what) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(path.string(), "", "is a folder, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path.string(), "",
                     std::filesystem::exists(path, error) ? "cannot open the " + std::string(what)
                                                          : "no such file");
  }
  return in;
}

std::string read_text_file(const std::filesystem::path& path, std::string_view what) {
  std::ostringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
    if (std::cin.bad()) throw InputError("-", "", "cannot read standard input");
    return std::move(text).str();
  }
  std::ifstream in = open_input_file(path, what);
  std::error_code error;
  // A regular file is read into a string of its size: a stream's growing buffer would
  // hold up to twice a large database at once.
  std::string whole;
  if (std::filesystem::is_regular_file(path, error)) {
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error) {
      whole.resize(static_cast<std::size_t>(size));
      in.read(whole.data(), static_cast<std::streamsize>(size));
      whole.resize(static_cast<std::size_t>(in.gcount()));  // shorter if it shrank meanwhile
      if (in.bad()) throw InputError(path.string(), "", "cannot read the " + std::string(what));
      in.clear();
    }
  }
  text << in.rdbuf();  // the rest: all of a file that is not regular, what a file grew by
  if (in.bad()) throw InputError(path.string(), "", "cannot read the " + std::string(what));
  if (whole.empty()) return std::move(text).str();
  whole += std::move(text).str();
  return whole;
}

std::string document_format(const std::string& json_text, const std::filesystem::path& path) {
  FormatScanner scanner([&json_text](std::size_t offset) {
    return detail::line_column(std::string_view(json_text), offset);
  });
  Json::sax_parse(json_text, &scanner);
  if (!scanner.format) throw InputError(path.string(), "", scanner.problem);
  return *scanner.format;
}

std::string file_format(const std::filesystem::path& path) {
  std::ifstream in = open_input_file(path);
  FormatScanner scanner([&in](std::size_t offset) { return detail::line_column(in, offset); });
  Json::sax_parse(in, &scanner);
  if (!scanner.format) throw InputError(path.string(), "", scanner.problem);
  return *scanner.format;
}

Document read_document(const std::filesystem::path& path) {
  Document document;
  document.path = path;
  document.text = read_text_file(path);
  document.format = document_format(document.text, path);
  return document;
}

}  // namespace shadowgen
