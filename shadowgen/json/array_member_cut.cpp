#include "shadowgen/json/array_member_cut.h"

#include <array>

namespace shadowgen {
namespace {

// The characters a scan stops at: 1 for the quote and the backslash (within a string), 2
// for brackets and the quote (within an object or array). Runs of anything else (digits,
// commas, spaces: most of a scene) are passed over a table look-up a character.
constexpr std::array<unsigned char, 256> kStops = [] {
  std::array<unsigned char, 256> stops{};
  stops['"'] = 1 | 2;
  stops['\\'] = 1;
  for (const unsigned char c : {'{', '[', '}', ']'}) stops[c] = 2;
  return stops;
}();

// A cursor over the text; every step returns false where the structure does not scan.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  std::size_t at() const { return at_; }
  bool done() const { return at_ >= text_.size(); }
  char peek() const { return done() ? '\0' : text_[at_]; }

  // JSON's whitespace only: space, tab, line feed, carriage return.
  void skip_space() {
    while (!done() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) {
      ++at_;
    }
  }

  bool take(char c) {
    if (peek() != c) return false;
    ++at_;
    return true;
  }

  // A string from its opening quote; `raw` gets its characters as written, escapes kept.
  bool skip_string(std::string_view* raw = nullptr) {
    if (!take('"')) return false;
    const std::size_t first = at_;
    while (!done()) {
      skip_to(1);
      if (done()) return false;
      const char c = text_[at_++];
      if (c == '\\') {
        if (done()) return false;
        ++at_;
      } else if (c == '"') {
        if (raw != nullptr) *raw = text_.substr(first, at_ - 1 - first);
        return true;
      }
    }
    return false;
  }

  // One value: a string, an object or array up to its matching bracket (strings skipped,
  // brackets of either kind counted), or a scalar up to the next delimiter. Whether the
  // value is valid is for its parse to say.
  bool skip_value() {
    const char c = peek();
    if (c == '"') return skip_string();
    if (c == '{' || c == '[') {
      std::size_t depth = 0;
      while (!done()) {
        skip_to(2);
        if (done()) return false;
        const char d = peek();
        if (d == '"') {
          if (!skip_string()) return false;
          continue;
        }
        ++at_;
        if (d == '{' || d == '[') {
          ++depth;
        } else if (d == '}' || d == ']') {
          if (--depth == 0) return true;
        }
      }
      return false;
    }
    const std::size_t first = at_;
    while (!done()) {
      const char d = peek();
      if (d == ',' || d == ']' || d == '}' || d == ' ' || d == '\t' || d == '\n' || d == '\r') {
        break;
      }
      ++at_;
    }
    return at_ > first;
  }

 private:
  // Past every character that is not a stop of `kind` (kStops).
  void skip_to(unsigned char kind) {
    while (at_ < text_.size() && (kStops[static_cast<unsigned char>(text_[at_])] & kind) == 0) {
      ++at_;
    }
  }

  std::string_view text_;
  std::size_t at_ = 0;
};

// The elements of the array whose '[' is at the scanner, up to and past its ']'.
bool scan_elements(Scanner& scan, std::string_view text, std::vector<std::string_view>& out) {
  if (!scan.take('[')) return false;
  scan.skip_space();
  if (scan.take(']')) return true;
  while (true) {
    const std::size_t first = scan.at();
    if (!scan.skip_value()) return false;
    out.push_back(text.substr(first, scan.at() - first));
    scan.skip_space();
    if (scan.take(']')) return true;
    if (!scan.take(',')) return false;
    scan.skip_space();
  }
}

}  // namespace

std::optional<ArrayMemberCut> cut_array_member(std::string_view text, std::string_view key) {
  Scanner scan(text);
  scan.skip_space();
  if (!scan.take('{')) return std::nullopt;
  scan.skip_space();
  if (scan.peek() == '}') return std::nullopt;
  while (true) {
    std::string_view name;
    if (!scan.skip_string(&name)) return std::nullopt;
    scan.skip_space();
    if (!scan.take(':')) return std::nullopt;
    scan.skip_space();
    if (name == key && scan.peek() == '[') {
      const std::size_t first = scan.at();
      ArrayMemberCut cut;
      if (!scan_elements(scan, text, cut.elements)) return std::nullopt;
      cut.rest.reserve(text.size() - (scan.at() - first) + 2);
      cut.rest.append(text.substr(0, first)).append("[]").append(text.substr(scan.at()));
      return cut;
    }
    if (!scan.skip_value()) return std::nullopt;
    scan.skip_space();
    if (!scan.take(',')) return std::nullopt;
    scan.skip_space();
  }
}

}  // namespace shadowgen
