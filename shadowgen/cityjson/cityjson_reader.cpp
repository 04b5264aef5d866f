#include "shadowgen/cityjson/cityjson_reader.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include "detail/cityjson_file.h"
#include "detail/cityjson_seq.h"
#include "shadowgen/json/document.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::cityjson {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

bool ends_with_jsonl(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return extension == ".jsonl";
}

// Whether anything but white space follows in `in`, which is left before it; the white
// space passed over is appended to `skipped`.
bool more_follows(std::istream& in, std::string& skipped) {
  while (true) {
    const int c = in.peek();
    if (c == std::char_traits<char>::eof()) return false;
    if (c != ' ' && c != '\t' && c != '\r' && c != '\n') return true;
    skipped += static_cast<char>(in.get());
  }
}

bool is_json_object(const std::string& line, const std::string& file) {
  try {
    const JsonDocument document(line, {file, false, nullptr});
    return document.root().is_object();
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

SourceModel read_cityjson(const std::filesystem::path& file, const SourceOptions& options) {
  const std::string name = file.string();
  std::ifstream in = open_input_file(file, "CityJSON file");
  std::string raw_first;
  std::getline(in, raw_first);
  const bool line_ended = !in.eof();
  std::string first = raw_first;
  if (std::string_view(first).starts_with(kByteOrderMark)) first.erase(0, kByteOrderMark.size());
  if (!first.empty() && first.back() == '\r') first.pop_back();

  std::string skipped;
  const bool more = line_ended && more_follows(in, skipped);
  if (ends_with_jsonl(file) || (more && is_json_object(first, name))) {
    const auto blank_lines =
        static_cast<std::size_t>(std::count(skipped.begin(), skipped.end(), '\n'));
    return detail::read_cityjson_seq(first, 2 + blank_lines, in, name, options);
  }
  std::string text = std::move(raw_first);
  if (line_ended) text += '\n';
  text += skipped;
  text.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(name, "", "could not be read to its end");
  if (std::string_view(text).starts_with(kByteOrderMark)) text.erase(0, kByteOrderMark.size());
  return detail::read_cityjson_text(text, name, options);
}

}  // namespace shadowgen::cityjson
