#pragma once

// Writing JSON for generated output (the shadowed database, the JSON report) with a
// layout chosen per container: inline, `{"id":"sun","direction":[0.0,0.0,-1.0]}`, or
// one member or element per line, indented two spaces a level, keys followed by ": ":
//
//   {
//     "format": "shadowgen-shadowed/1",
//     "lights": [
//       {"id":"sun","type":"directional",...}
//     ]
//   }
//
// An empty container is `[]` or `{}` either way. Numbers are the shortest form that reads
// back to the same double (std::to_chars), always with a '.' or an exponent ("28.0",
// "-0.0", "1e-300") so that they read as floating point; JSON has no NaN or infinity, and
// a non-finite number is refused (std::invalid_argument) rather than written. Strings are
// escaped as JSON requires; bytes that are not UTF-8 become U+FFFD.
//
// The text is kept whole for take(), or, given a sink, passed on in pieces of about a
// mebibyte as it is written and ended by finish(): a database of hundreds of megabytes
// then never stands in memory as one string.

#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace shadowgen {

class JsonWriter {
 public:
  enum class Layout { kInline, kLines };
  using Sink = std::function<void(std::string_view)>;

  JsonWriter() = default;
  explicit JsonWriter(Sink sink) : sink_(std::move(sink)) {}

  JsonWriter& begin_object(Layout layout = Layout::kInline);
  JsonWriter& end_object();
  JsonWriter& begin_array(Layout layout = Layout::kInline);
  JsonWriter& end_array();

  // The key of the next member of the open object.
  JsonWriter& key(std::string_view key);

  JsonWriter& value(double number);
  JsonWriter& value(std::uint64_t integer);
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  // [x, y, z].
  JsonWriter& value(const glm::dvec3& v);

  // The document, ended by a line break. Every container must be closed. Without a sink.
  std::string take();
  // Passes the rest of the document, ended by a line break, to the sink. Every container
  // must be closed.
  void finish();

 private:
  struct Open {
    Layout layout;
    bool empty = true;
  };

  // What goes before a value or a key: a comma, and in a container of lines a line break
  // and the indent.
  void separate();
  void newline(std::size_t depth);
  // Ends the innermost open object or array with `bracket`.
  JsonWriter& close(char bracket);

  // Hands the text so far to the sink once it has grown past a piece's size.
  void spill();

  Sink sink_;
  std::string out_;
  std::vector<Open> open_;
  bool after_key_ = false;
};

}  // namespace shadowgen
