#pragma once

// A JSON document cut at one array member of its top-level object, so that the array's
// elements can be parsed apart, in parallel, and the rest on its own: a scan of the text's
// structure (strings skipped, brackets counted), not a parse. The array's text is scanned
// in chunks on the calling task arena's threads, each chunk on both guesses of whether it
// starts within a string, then the guesses are chained in order. The cut is exact for
// valid JSON; for text that is not, each piece fails to parse on its own or the cut is
// refused, so a caller that falls back to parsing the whole text whenever a piece fails
// gives the whole text's verdict (the pieces are valid JSON exactly when the whole is:
// the separators between the elements, commas and JSON's whitespace, are checked here;
// the rest, and what lies between two commas, is parsed).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowgen {

struct ArrayMemberCut {
  // The document with the array emptied (`"key": []`), everything else as written.
  std::string rest;
  // Each element's text, in order: views into the text that was cut.
  std::vector<std::string_view> elements;
};

// Cuts the first member `key` of the top-level object of `text`, when the key is written
// as plain characters (no escapes) and its value is an array; nullopt otherwise (the text
// is not an object, has no such member, or its structure does not scan: a caller then
// parses the whole text). O(size of the text), spread over the threads, and no
// allocation per element.
std::optional<ArrayMemberCut> cut_array_member(std::string_view text, std::string_view key);

}  // namespace shadowgen
