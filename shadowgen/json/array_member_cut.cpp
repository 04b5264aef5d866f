#include "shadowgen/json/array_member_cut.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "hsr/parallel.h"

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

// The array's text is scanned in chunks of this many bytes, in parallel: far above a
// task's cost, and a 25 MB scene still makes about a hundred.
constexpr std::size_t kChunkBytes = std::size_t{1} << 18;

// The characters a chunk's scan stops at: the quote, brackets and the comma.
constexpr std::array<bool, 256> kChunkStops = [] {
  std::array<bool, 256> stops{};
  for (const unsigned char c : {'"', '{', '[', '}', ']', ','}) stops[c] = true;
  return stops;
}();

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

// What a chunk holds at one depth below its start, relative to it (level k: k brackets
// more closed than opened): the commas at that depth while it is the lowest yet, and the
// bracket that first closed it, if one did. At the level where the array's own elements
// lie, these are the commas between them and the array's end.
struct Level {
  std::vector<std::size_t> commas;
  std::size_t close = kNone;
};

// A chunk scanned on one guess of whether it starts within a string.
struct Guess {
  std::ptrdiff_t depth = 0;            // brackets opened less closed
  std::vector<Level> levels{Level{}};  // levels[k]: depth -k; one more than the lowest reached
};

struct ChunkScan {
  bool odd_quotes = false;  // the chunk's quotes flip whether what follows is in a string
  Guess guess[2];           // [0]: the chunk starts outside a string; [1]: within one
};

// A quote at `at` ends or opens a string unless an odd run of backslashes precedes it,
// which in valid JSON happens within strings only: the scan of a chunk need not know
// where it starts. (Text that is not JSON may be cut otherwise than the parse would; its
// pieces then fail to parse, or the cut is refused.)
bool is_real_quote(std::string_view text, std::size_t at) {
  std::size_t backslashes = 0;
  while (at > backslashes && text[at - 1 - backslashes] == '\\') ++backslashes;
  return backslashes % 2 == 0;
}

// One pass over text[first, last) for both guesses at once: what follows an even number
// of quotes is outside a string on guess 0 and within one on guess 1, and the other way
// round after an odd number.
ChunkScan scan_chunk(std::string_view text, std::size_t first, std::size_t last) {
  ChunkScan scan;
  int parity = 0;
  for (std::size_t i = first; i < last; ++i) {
    if (!kChunkStops[static_cast<unsigned char>(text[i])]) continue;
    const char c = text[i];
    if (c == '"') {
      if (is_real_quote(text, i)) parity ^= 1;
      continue;
    }
    Guess& guess = scan.guess[parity];  // the guess that is outside a string here
    const std::size_t lowest = guess.levels.size() - 1;
    if (c == ',') {
      if (guess.depth == -static_cast<std::ptrdiff_t>(lowest)) {
        guess.levels.back().commas.push_back(i);
      }
    } else if (c == '{' || c == '[') {
      ++guess.depth;
    } else if (--guess.depth < -static_cast<std::ptrdiff_t>(lowest)) {
      guess.levels.back().close = i;
      guess.levels.emplace_back();
    }
  }
  scan.odd_quotes = parity == 1;
  return scan;
}

// The elements of the array whose '[' is at `open`, and the position of its ']'; nullopt
// where the array does not close with ']', or a comma stands next to another or to a
// bracket. The chunks are scanned in parallel, then followed in order: each starts where
// the one before left the string state and the depth, and that picks its guess and level.
std::optional<std::size_t> scan_elements(std::string_view text, std::size_t open,
                                         std::vector<std::string_view>& out) {
  const std::size_t body = open + 1;
  const std::size_t chunks =
      std::max<std::size_t>(1, (text.size() - body + kChunkBytes - 1) / kChunkBytes);
  std::vector<ChunkScan> scans(chunks);
  hsr::for_each_in_parallel(chunks, [&](std::size_t c) {
    const std::size_t first = body + c * kChunkBytes;
    scans[c] = scan_chunk(text, first, std::min(text.size(), first + kChunkBytes));
  });
  std::vector<std::size_t> commas;
  std::size_t close = kNone;
  bool in_string = false;
  std::size_t depth = 0;  // within the array: 0 where its elements lie
  for (const ChunkScan& scan : scans) {
    const Guess& guess = scan.guess[in_string ? 1 : 0];
    if (depth < guess.levels.size()) {
      const Level& level = guess.levels[depth];
      commas.insert(commas.end(), level.commas.begin(), level.commas.end());
      if (level.close != kNone) {
        close = level.close;
        break;
      }
    }
    depth = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(depth) + guess.depth);
    in_string = in_string != scan.odd_quotes;
  }
  if (close == kNone || text[close] != ']') return std::nullopt;
  // Each element between its separators, JSON's whitespace trimmed; none may be empty,
  // but for the whole of an empty array.
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  out.reserve(commas.size() + 1);
  for (std::size_t k = 0; k <= commas.size(); ++k) {
    std::size_t first = k == 0 ? body : commas[k - 1] + 1;
    std::size_t last = k == commas.size() ? close : commas[k];
    while (first < last && is_space(text[first])) ++first;
    while (last > first && is_space(text[last - 1])) --last;
    if (first == last) {
      if (commas.empty()) return close;  // [] or [ ]
      return std::nullopt;
    }
    out.push_back(text.substr(first, last - first));
  }
  return close;
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
      const std::optional<std::size_t> close = scan_elements(text, first, cut.elements);
      if (!close) return std::nullopt;
      cut.rest.reserve(text.size() - (*close + 1 - first) + 2);
      cut.rest.append(text.substr(0, first)).append("[]").append(text.substr(*close + 1));
      return cut;
    }
    if (!scan.skip_value()) return std::nullopt;
    scan.skip_space();
    if (!scan.take(',')) return std::nullopt;
    scan.skip_space();
  }
}

}  // namespace shadowgen
