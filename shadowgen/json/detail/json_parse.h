#pragma once

// JSON text to a document, in one pass of nlohmann's SAX parser that builds the tree as
// json::parse does and also refuses what json::parse lets through: a key given twice in
// one object (json::parse keeps the last value and silently drops the first, so a second
// "polygons": [] would empty a scene). Syntax errors, and numbers beyond a double's range,
// are located by line and column.

#include <cstddef>
#include <functional>
#include <istream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace shadowgen::json::detail {

// How deeply arrays and objects may nest. The formats need 6 levels at most (a hole's
// vertex in a lit polygon of a database face); a file nested deeper is refused as soon as
// the parser reaches the limit, before it has built more than that much of the tree (a
// file of 20 million '[' once took 2.4 GB to build and then reject).
inline constexpr std::size_t kMaxJsonDepth = 64;

struct ParseOutcome {
  // What is wrong, worded for the file's reader ("line 3, column 18: invalid JSON: ...",
  // "lights[1] ('lamp'): the key 'range' is given twice"); empty when the text is valid.
  std::optional<std::string> problem;
};

// The elements of one top-level array member (`key`, the root being an object), handed to
// `take` each as soon as it is complete, with its index: one that `take` returns true for
// is dropped from the tree (a null keeps its place), so a reader that converts elements
// as they come never holds more than one element's tree of that array. The members
// before it in the text are complete by then. What `take` throws passes through.
struct ElementStream {
  std::string_view key;
  std::function<bool(nlohmann::json& element, std::size_t index)> take;
};

ParseOutcome parse_json(std::string_view text, nlohmann::json& root,
                        const ElementStream* stream = nullptr);

// The same for a value that sits `depth` levels deep in a larger document (an element of
// a top-level array: 2), refused where that document would be for its nesting.
ParseOutcome parse_json_at_depth(std::string_view text, nlohmann::json& root, std::size_t depth);

// The same from a stream that can seek (a file), read as it is parsed: the text is
// never held whole. It is looked through once for a NUL byte first, and read again up to
// a syntax error to place it by line and column.
ParseOutcome parse_json(std::istream& in, nlohmann::json& root,
                        const ElementStream* stream = nullptr);

// Line and column (1-based, columns in bytes) of the byte at `offset` (0-based).
using LineColumn = std::pair<std::size_t, std::size_t>;
using Locate = std::function<LineColumn(std::size_t offset)>;

// "line L, column C: invalid JSON: a NUL byte (JSON text has none; is this a binary
// file?)" for the first NUL byte among the first `end` bytes of `text`, or of what `in`
// reads from its start (the stream is left at its start); nullopt where there is none.
// nlohmann's parser takes a NUL byte for the end of the text ("unexpected end of input"),
// so where it stops, this says what it found.
std::optional<std::string> nul_problem(std::string_view text,
                                       std::size_t end = std::string_view::npos);
std::optional<std::string> nul_problem(std::istream& in, std::size_t end = std::string_view::npos);

// "line L, column C: invalid JSON: what", for a SAX parse error at `position` (bytes read,
// as nlohmann counts them). `last_token` is the token being read, `id` nlohmann's error
// id, `what` its message.
std::string describe_parse_error(std::string_view text, std::size_t position,
                                 const std::string& last_token, int id, const std::string& what);
// The same where `locate` places an offset.
std::string describe_parse_error(const Locate& locate, std::size_t position,
                                 const std::string& last_token, int id, const std::string& what);

// Where `offset` is in `text`, or in what `in` reads from its start (the stream is left
// at its start).
LineColumn line_column(std::string_view text, std::size_t offset);
LineColumn line_column(std::istream& in, std::size_t offset);

}  // namespace shadowgen::json::detail
