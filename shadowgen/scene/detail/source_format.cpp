#include "detail/source_format.h"

#include <cctype>
#include <fstream>
#include <string>

namespace shadowgen::scene::detail {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool ends_with(std::string_view text, std::string_view tail) {
  return text.size() >= tail.size() && text.substr(text.size() - tail.size()) == tail;
}

std::size_t first_non_blank(std::string_view head) {
  std::size_t i = 0;
  // A UTF-8 byte order mark, which some Windows tools write, is not content.
  if (head.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  return i;
}

// `text` in double quotes, built piece by piece (g++ 12 warns falsely on "\"" + text).
std::string quoted(std::string_view text) {
  std::string out(1, '"');
  out += text;
  out += '"';
  return out;
}

// The JSON key `"key"`, with blanks allowed between it and its colon.
bool has_key(std::string_view head, std::string_view key) {
  const std::string quoted = detail::quoted(key);
  for (std::size_t at = head.find(quoted); at != std::string_view::npos;
       at = head.find(quoted, at + 1)) {
    std::size_t i = at + quoted.size();
    while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
    if (i < head.size() && head[i] == ':') return true;
  }
  return false;
}

bool has_string(std::string_view head, std::string_view value) {
  return head.find(quoted(value)) != std::string_view::npos;
}

// An IDF's Version object: a line whose first word, before blanks and a ',' or ';', is
// "version", any case; lines of comments (from '!') and blank lines may come first.
bool starts_idf(std::string_view head) {
  std::size_t line_start = 0;
  while (line_start < head.size()) {
    std::size_t line_end = head.find('\n', line_start);
    if (line_end == std::string_view::npos) line_end = head.size();
    std::string_view line = head.substr(line_start, line_end - line_start);
    const std::size_t bang = line.find('!');
    if (bang != std::string_view::npos) line = line.substr(0, bang);
    std::size_t i = 0;
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i < line.size()) {
      std::size_t j = i;
      while (j < line.size() && std::isalpha(static_cast<unsigned char>(line[j]))) ++j;
      if (lower(line.substr(i, j - i)) != "version") return false;
      while (j < line.size() && std::isspace(static_cast<unsigned char>(line[j]))) ++j;
      return j < line.size() && (line[j] == ',' || line[j] == ';');
    }
    line_start = line_end + 1;
  }
  return false;
}

SourceFormat by_extension(const std::filesystem::path& file) {
  const std::string name = lower(file.filename().string());
  for (std::string_view ext : {".idf", ".epjson"}) {
    if (ends_with(name, ext)) return SourceFormat::kEnergyPlus;
  }
  for (std::string_view ext : {".gltf", ".glb"}) {
    if (ends_with(name, ext)) return SourceFormat::kGltf;
  }
  for (std::string_view ext : {".json", ".jsonl"}) {
    if (ends_with(name, ext)) return SourceFormat::kCityJson;
  }
  return SourceFormat::kMesh;
}

}  // namespace

SourceFormat format_of(std::string_view head, const std::filesystem::path& file) {
  if (head.substr(0, 4) == "glTF") return SourceFormat::kGltf;
  const std::size_t start = first_non_blank(head);
  if (start < head.size() && head[start] == '{') {
    if (has_string(head, "CityJSON") || has_string(head, "CityJSONFeature")) {
      return SourceFormat::kCityJson;
    }
    if (has_key(head, "version_identifier")) return SourceFormat::kEnergyPlus;
    if (has_key(head, "asset")) return SourceFormat::kGltf;
  } else if (starts_idf(head)) {
    return SourceFormat::kEnergyPlus;
  }
  return by_extension(file);
}

SourceFormat format_of_file(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return by_extension(file);
  std::ifstream in(file, std::ios::binary);
  std::string head(kSniffBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return format_of(head, file);
}

std::string_view format_name(SourceFormat format) {
  switch (format) {
    case SourceFormat::kMesh:
      return "a mesh file";
    case SourceFormat::kEnergyPlus:
      return "an EnergyPlus model (IDF or epJSON)";
    case SourceFormat::kCityJson:
      return "a CityJSON file";
    case SourceFormat::kGltf:
      return "a glTF file";
  }
  return "a file";
}

}  // namespace shadowgen::scene::detail
