#pragma once

// Reading a JSON input (a scene or a shadowed database) with every value knowing where it
// is: its path from the top (`lights[1] ('lamp').range.end`), and the face it belongs to
// once that is known. Every problem is an InputError naming the file, the face where there
// is one, the path and what is wrong; scenes and databases share these checks, so the
// same mistake reads the same in both.
//
//   JsonDocument document(text, {file, strict, &warnings});
//   JsonObject top = document.root().object();
//   JsonArray lights = top.get("lights").array();
//   ...
//   top.finish();  // keys the reader never asked for: a warning, or under strict an error
//
// The document is refused whole when it is not JSON, holds a number beyond a double's
// range, or gives one key twice in an object (docs/scene-format.md, "Reading rules").
// Values point into the document, which must outlive them.

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <istream>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace shadowgen {

namespace json::detail {
struct ElementStream;
}

// Where a document comes from and how strictly it is read.
struct JsonSource {
  std::string file;  // names the file in messages
  // Unknown keys are errors, not warnings.
  bool strict = false;
  // Receives the warnings ("file: path: what" lines); may be null, then they are dropped.
  std::vector<std::string>* warnings = nullptr;
};

class JsonObject;
class JsonArray;
class JsonPlace;

class JsonValue {
 public:
  const std::string& path() const { return path_; }

  // The same value, with messages naming face `id` (InputError's face) from here down.
  JsonValue for_face(std::string id) const;
  // The same value, its messages starting with `subject` ("light 'lamp'"), and its path
  // labelled by the entry's id: `lights[1] ('lamp')`.
  JsonValue named(std::string subject, std::string_view id) const;

  bool is_null() const;
  bool is_object() const;
  bool is_array() const;
  // "a number", "an array", "null"...
  std::string describe() const;

  // Typed reads: each fails ("expected an object, found a string") when the value is of
  // another type.
  JsonObject object() const;
  JsonArray array() const;
  std::string string() const;
  double number() const;  // finite
  // A non-negative integer ("expected a non-negative integer").
  std::size_t index() const;
  // [x, y, z], finite.
  glm::dvec3 vec3() const;
  // An array of [x, y, z] (a loop of points).
  std::vector<glm::dvec3> vec3_list() const;

  // Where the value stands, for messages after its tree is gone (JsonDocument's
  // streaming): kept apart from the value so that nothing reads a node no longer there.
  JsonPlace place() const;

  // InputError naming the file, the face (if known), the path and `problem`.
  [[noreturn]] void fail(const std::string& problem) const;
  // The same as a warning line.
  void warn(const std::string& problem) const;
  // What fail() would say, without throwing.
  std::string message(const std::string& problem) const;

 private:
  friend class JsonDocument;
  friend class JsonObject;
  friend class JsonArray;

  JsonValue(const nlohmann::json* node, const JsonSource* source, std::string path)
      : node_(node), source_(source), path_(std::move(path)) {}
  JsonValue child(const nlohmann::json* node, std::string path) const;
  [[noreturn]] void fail_expected(const char* expected) const;

  const nlohmann::json* node_;
  const JsonSource* source_;
  std::string path_;
  std::string face_;
  std::string subject_;
};

// Where a value stands in its document: the file, the face, the path. It fails and words
// messages as the value itself would.
class JsonPlace {
 public:
  // The place of element `index` of the array here: `...[index]`.
  JsonPlace element(std::size_t index) const;

  [[noreturn]] void fail(const std::string& problem) const;
  std::string message(const std::string& problem) const;

 private:
  friend class JsonValue;
  JsonPlace(const JsonSource* source, std::string path, std::string face, std::string subject)
      : source_(source),
        path_(std::move(path)),
        face_(std::move(face)),
        subject_(std::move(subject)) {}
  std::string located(const std::string& problem) const;  // "subject: path: problem"

  const JsonSource* source_;
  std::string path_;
  std::string face_;
  std::string subject_;
};

// An object being read. It records every key asked for, present or not, so that finish()
// can name the keys nobody asked for, with the asked-for key each was probably meant to be.
class JsonObject {
 public:
  const JsonValue& value() const { return self_; }
  std::size_t size() const;

  // From here on, messages about this object and its members name face `id`, or start
  // with `subject` with the object's path labelled by `id` (JsonValue::for_face, named).
  void for_face(std::string id) { self_ = self_.for_face(std::move(id)); }
  void name(std::string subject, std::string_view id) {
    self_ = self_.named(std::move(subject), id);
  }

  // A member the format requires: fails with "missing 'key'" when absent.
  JsonValue get(std::string_view key);
  // An optional member.
  std::optional<JsonValue> find(std::string_view key);
  // Whether the member is there; counts as asking for it.
  bool has(std::string_view key);
  // Every member, in key order, for objects keyed by data (a map from light ids): all of
  // them count as known. Paths are `lit['sun']`.
  std::vector<std::pair<std::string, JsonValue>> entries();

  // Keys present but never asked for: each a warning `path: unknown key 'rnage' (did you
  // mean 'range'?)`, or under JsonSource::strict an InputError saying the same.
  void finish();
  // The keys present that were never asked for, in key order.
  std::vector<std::string> unknown_keys() const;
  // "unknown key 'rnage' (did you mean 'range'?)".
  std::string unknown_key_problem(const std::string& key) const;

 private:
  friend class JsonValue;
  explicit JsonObject(JsonValue self) : self_(std::move(self)) {}

  JsonValue self_;
  std::vector<std::string> asked_;
  bool all_known_ = false;
};

class JsonArray {
 public:
  const JsonValue& value() const { return self_; }
  std::size_t size() const;
  bool empty() const { return size() == 0; }
  // Element `index` (< size()), its path `...[index]`.
  JsonValue at(std::size_t index) const;

 private:
  friend class JsonValue;
  explicit JsonArray(JsonValue self) : self_(std::move(self)) {}

  JsonValue self_;
};

class JsonDocument {
 public:
  // Parses `text`. InputError naming source.file: "line 3, column 18: invalid JSON: ...",
  // "line 2, column 9: invalid JSON: the number 1e999 is out of the range of a double",
  // "lights[1] ('lamp'): the key 'range' is given twice ...".
  JsonDocument(std::string_view text, JsonSource source);
  ~JsonDocument();
  JsonDocument(const JsonDocument&) = delete;
  JsonDocument& operator=(const JsonDocument&) = delete;

  // Parses `text` as above, handing each element of the top-level array member
  // `streamed_key` to `take` as soon as it is complete, with the root as read so far (the
  // members before that array in the text complete, the array itself open). An element
  // `take` returns true for is dropped from the document, a null left in its place: a
  // reader that converts elements as they come holds one element's tree at a time.
  // What `take` throws passes through.
  using ElementTaker = std::function<bool(const JsonValue& root, const JsonValue& element)>;
  JsonDocument(std::string_view text, JsonSource source, std::string_view streamed_key,
               const ElementTaker& take);
  // The same from a file, read once as it is parsed, NUL bytes looked for on the way (the
  // stream must rewind to its start: it is read again only to place a NUL or an error):
  // the text is never held whole.
  JsonDocument(std::istream& in, JsonSource source, std::string_view streamed_key,
               const ElementTaker& take);

  // Parses `text` as the element at `path` of a larger document (`polygons[12]`), nested
  // `depth` levels deep in it (an element of a top-level array: 2): its values' paths
  // start with `path`, and it is refused where that document would be for its nesting.
  // For the pieces cut_array_member (json/array_member_cut.h) cuts.
  JsonDocument(std::string_view text, JsonSource source, std::string path, std::size_t depth);

  JsonValue root() const;
  const JsonSource& source() const { return *source_; }

 private:
  // What the streaming constructors hand to the parser: each element of array `key` as
  // a value, with the root as read so far, to `take`.
  json::detail::ElementStream element_stream(std::string_view key, const ElementTaker& take) const;

  std::unique_ptr<nlohmann::json> root_;
  std::unique_ptr<JsonSource> source_;  // values point to it
  std::string root_path_;               // "" but for an element parsed on its own
};

}  // namespace shadowgen
