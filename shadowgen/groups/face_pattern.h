#pragma once

// Face patterns: which faces a group holds (docs/scene-format.md, "Groups"). The one home
// of the rule, for a scene's `groups` and for `report --group-by` alike.
//
//   FacePattern garden("garden*");
//   garden.matches("garden-bed");   // true
//   garden.matches("garden/0");     // false: '*' stops at '/'
//   FacePattern("lawn/**").matches("lawn/edge/3");  // true
//
// A pattern matches a face id whole, byte for byte, but for:
//   *    any run of characters (none included) without '/';
//   **   (two or more stars) any run of characters, '/' included;
//   ?    one character (a UTF-8 code point) other than '/';
//   \c   the character c itself ("\*" a star, "\\" a backslash, "\?" a question mark).
// Mesh and model face ids are "<entry>/<k>" or "<entry>/<object>/<k>", so '*' picks faces
// of one level ("lawn/*": every face of mesh 'lawn') and '**' of every level below
// ("district/**": every face of a CityJSON entry).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowgen::groups {

class FacePattern {
 public:
  // What is wrong with `text` as a pattern (empty, or ending in a lone '\'); nullopt when
  // it is one.
  static std::optional<std::string> problem(std::string_view text);

  // Throws std::invalid_argument where problem(text) says something.
  explicit FacePattern(std::string text);

  const std::string& text() const { return text_; }

  // Whether the pattern matches `id` whole. Time: O(pattern length × id length).
  bool matches(std::string_view id) const;

 private:
  enum class Kind { kCharacter, kStar, kAnyStar, kOne };
  struct Token {
    Kind kind = Kind::kCharacter;
    char character = '\0';  // kCharacter
  };

  std::string text_;
  std::vector<Token> tokens_;
};

}  // namespace shadowgen::groups
