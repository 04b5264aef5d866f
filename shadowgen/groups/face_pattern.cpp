#include "shadowgen/groups/face_pattern.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace shadowgen::groups {
namespace {

// Whether byte `c` continues a UTF-8 sequence (10xxxxxx) rather than starting a character.
bool continues_character(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

}  // namespace

std::optional<std::string> FacePattern::problem(std::string_view text) {
  if (text.empty()) return "a face pattern must not be empty";
  std::size_t backslashes = 0;  // the run of them at the end
  for (auto it = text.rbegin(); it != text.rend() && *it == '\\'; ++it) ++backslashes;
  if (backslashes % 2 == 1) {
    return "a face pattern must not end in a lone '\\' (\"\\\\\" stands for a backslash)";
  }
  return std::nullopt;
}

FacePattern::FacePattern(std::string text) : text_(std::move(text)) {
  if (const std::optional<std::string> why = problem(text_)) throw std::invalid_argument(*why);
  for (std::size_t i = 0; i < text_.size(); ++i) {
    const char c = text_[i];
    if (c == '\\') {
      tokens_.push_back({Kind::kCharacter, text_[++i]});
    } else if (c == '*') {
      Kind kind = Kind::kStar;
      while (i + 1 < text_.size() && text_[i + 1] == '*') {
        kind = Kind::kAnyStar;
        ++i;
      }
      tokens_.push_back({kind, '\0'});
    } else if (c == '?') {
      tokens_.push_back({Kind::kOne, '\0'});
    } else {
      tokens_.push_back({Kind::kCharacter, c});
    }
  }
}

bool FacePattern::matches(std::string_view id) const {
  // reach[j]: the tokens so far can match id's first j bytes. Each token moves it on.
  const std::size_t n = id.size();
  std::vector<char> reach(n + 1, 0), next(n + 1, 0);
  reach[0] = 1;
  for (const Token& token : tokens_) {
    std::fill(next.begin(), next.end(), 0);
    for (std::size_t j = 0; j <= n; ++j) {
      switch (token.kind) {
        case Kind::kCharacter:
          if (reach[j] && j < n && id[j] == token.character) next[j + 1] = 1;
          break;
        case Kind::kOne:
          if (reach[j] && j < n && id[j] != '/' && !continues_character(id[j])) {
            std::size_t end = j + 1;
            while (end < n && continues_character(id[end])) ++end;
            next[end] = 1;
          }
          break;
        case Kind::kStar:  // from a reached place on, over any run without '/'
          next[j] = reach[j] || (j > 0 && next[j - 1] && id[j - 1] != '/');
          break;
        case Kind::kAnyStar:
          next[j] = reach[j] || (j > 0 && next[j - 1]);
          break;
      }
    }
    std::swap(reach, next);
  }
  return reach[n] != 0;
}

}  // namespace shadowgen::groups
