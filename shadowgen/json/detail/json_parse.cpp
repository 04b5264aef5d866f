#include "detail/json_parse.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "detail/nul_watching_input.h"

namespace shadowgen::json::detail {
namespace {

using Json = nlohmann::json;

// Counts lines and columns over the bytes it is shown, in order.
class LineCounter {
 public:
  void add(std::string_view bytes) {
    for (const char c : bytes) {
      if (c == '\n') {
        ++place_.first;
        place_.second = 1;
      } else {
        ++place_.second;
      }
    }
  }
  LineColumn place() const { return place_; }

 private:
  LineColumn place_{1, 1};
};

// Reads `in` from its start in chunks, showing each to `look` until it returns false.
template <class Look>
void read_through(std::istream& in, Look&& look) {
  in.clear();
  in.seekg(0);
  std::string chunk(std::size_t{1} << 20, '\0');
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got == 0 || !look(std::string_view(chunk.data(), got))) break;
  }
  in.clear();
  in.seekg(0);
}

std::string nul_problem_at(LineColumn at) {
  return "line " + std::to_string(at.first) + ", column " + std::to_string(at.second) +
         ": invalid JSON: a NUL byte (JSON text has none; is this a binary file?)";
}

// Builds the tree as nlohmann's own DOM parser does. Every open container sits on a stack
// with the step that leads to it from its parent ("[2]" or ".key"), so that a repeated
// key can be named by its path. Pointers into the tree stay valid while a container is
// open: nothing is appended to an array while one of its elements is being built, and
// object members (std::map nodes) never move.
class DomBuilder {
 public:
  DomBuilder(Locate locate, Json& root, const ElementStream* stream, std::size_t depth = 0)
      : locate_(std::move(locate)), root_(root), stream_(stream), depth_(depth) {}

  std::optional<std::string> problem;

  bool null() { return scalar(nullptr); }
  bool boolean(bool value) { return scalar(value); }
  bool number_integer(Json::number_integer_t value) { return scalar(value); }
  bool number_unsigned(Json::number_unsigned_t value) { return scalar(value); }
  bool number_float(Json::number_float_t value, const Json::string_t&) { return scalar(value); }
  bool string(Json::string_t& value) { return scalar(std::move(value)); }
  bool binary(Json::binary_t& value) { return scalar(Json::binary(std::move(value))); }

  bool start_object(std::size_t) { return open(Json::object()); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(Json::string_t& key) {
    Json& object = *open_.back().container;
    const auto [it, fresh] = object.emplace(key, nullptr);
    if (!fresh) {
      const std::string where = path();
      problem = (where.empty() ? std::string() : where + ": ") + "the key '" + key +
                "' is given twice (a key may appear once in an object)";
      return false;
    }
    member_ = &it.value();
    member_key_ = key;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& error) {
    problem = describe_parse_error(locate_, position, last_token, error.id, error.what());
    return false;
  }

 private:
  struct Open {
    Json* container;
    std::string step;  // from the parent: "[i]" or "key"
  };

  bool scalar(Json value) {
    Json* placed = put(std::move(value));
    if (open_.size() == 2 && streamed(open_[1])) hand_over(*placed);
    return true;
  }

  // Whether `level` is the array whose elements go to the stream: the member `key` of
  // the root object.
  bool streamed(const Open& level) const {
    return stream_ != nullptr && level.step == stream_->key && level.container->is_array() &&
           open_.front().container->is_object();
  }

  // A complete element of the streamed array, the last one so far.
  void hand_over(Json& element) {
    const std::size_t index = open_[1].container->size() - 1;
    if (stream_->take(element, index)) element = Json();
  }

  // Places a value where the parser is: the root, the next element of the open array,
  // or the member whose key was just read.
  Json* put(Json value) {
    if (open_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Json& parent = *open_.back().container;
    if (parent.is_array()) {
      parent.push_back(std::move(value));
      return &parent.back();
    }
    *member_ = std::move(value);
    return member_;
  }

  bool open(Json container) {
    if (depth_ + open_.size() >= kMaxJsonDepth) {
      const std::string where = path();
      problem = (where.empty() ? std::string() : where + ": ") + "arrays and objects nested " +
                "deeper than " + std::to_string(kMaxJsonDepth) + " levels (the limit)";
      return false;
    }
    std::string step;
    if (!open_.empty()) {
      const Json& parent = *open_.back().container;
      if (parent.is_array()) {
        step += '[';  // appended piece by piece: g++ 12 warns falsely on "[" + std::string
        step += std::to_string(parent.size());
        step += ']';
      } else {
        step = member_key_;
      }
    }
    Json* placed = put(std::move(container));
    open_.push_back({placed, std::move(step)});
    return true;
  }

  bool close() {
    Json* closed = open_.back().container;
    open_.pop_back();
    if (open_.size() == 2 && streamed(open_[1])) hand_over(*closed);
    return true;
  }

  // The path of the innermost open container, an object with a string "id" (read so far)
  // labelled by it: `lights[1] ('lamp')`.
  std::string path() const {
    std::string out;
    for (const Open& level : open_) {
      if (!level.step.empty()) {
        if (level.step.front() != '[' && !out.empty()) out += '.';
        out += level.step;
      }
      const Json& container = *level.container;
      if (container.is_object() && !out.empty()) {
        const auto id = container.find("id");
        if (id != container.end() && id->is_string()) {
          out += " ('" + id->get<std::string>() + "')";
        }
      }
    }
    return out;
  }

  Locate locate_;
  Json& root_;
  std::vector<Open> open_;
  Json* member_ = nullptr;
  std::string member_key_;
  const ElementStream* stream_;
  std::size_t depth_;  // of the root in the document it stands in
};

}  // namespace

std::string describe_parse_error(std::string_view text, std::size_t position,
                                 const std::string& last_token, int id, const std::string& what) {
  return describe_parse_error([text](std::size_t offset) { return line_column(text, offset); },
                              position, last_token, id, what);
}

LineColumn line_column(std::string_view text, std::size_t offset) {
  LineCounter counter;
  counter.add(text.substr(0, std::min(offset, text.size())));
  return counter.place();
}

LineColumn line_column(std::istream& in, std::size_t offset) {
  LineCounter counter;
  std::size_t left = offset;
  read_through(in, [&](std::string_view chunk) {
    counter.add(chunk.substr(0, std::min(left, chunk.size())));
    left -= std::min(left, chunk.size());
    return left > 0;
  });
  return counter.place();
}

std::string describe_parse_error(const Locate& locate, std::size_t position,
                                 const std::string& last_token, int id, const std::string& what) {
  std::size_t offset = position > 0 ? position - 1 : 0;  // position counts bytes read
  std::string problem;
  if (id == 406) {  // number overflow: point at the number's start
    offset = position >= last_token.size() ? position - last_token.size() : 0;
    problem = "the number " + last_token + " is out of the range of a double";
  } else {
    // nlohmann's text: "[json.exception.parse_error.101] parse error at line 2, column 4:
    // syntax error while parsing ..."; keep what follows the position.
    problem = what;
    const std::size_t column = problem.find(", column ");
    const std::size_t colon = column == std::string::npos ? column : problem.find(": ", column);
    if (colon != std::string::npos) {
      problem = problem.substr(colon + 2);
    } else if (const std::size_t bracket = problem.find("] "); bracket != std::string::npos) {
      problem = problem.substr(bracket + 2);
    }
  }
  const auto [line, column] = locate(offset);
  return "line " + std::to_string(line) + ", column " + std::to_string(column) +
         ": invalid JSON: " + problem;
}

std::optional<std::string> nul_problem(std::string_view text, std::size_t end) {
  const std::size_t nul = text.substr(0, std::min(end, text.size())).find('\0');
  if (nul == std::string_view::npos) return std::nullopt;
  return nul_problem_at(line_column(text, nul));
}

std::optional<std::string> nul_problem(std::istream& in, std::size_t end) {
  LineCounter counter;
  bool nul = false;
  std::size_t left = end;
  read_through(in, [&](std::string_view chunk) {
    chunk = chunk.substr(0, std::min(left, chunk.size()));
    left -= chunk.size();
    const std::size_t at = chunk.find('\0');
    counter.add(chunk.substr(0, at));
    nul = at != std::string_view::npos;
    return !nul && left > 0;
  });
  if (!nul) return std::nullopt;
  return nul_problem_at(counter.place());
}

namespace {

ParseOutcome parse_text(std::string_view text, Json& root, const ElementStream* stream,
                        std::size_t depth) {
  // nlohmann's parser takes a NUL byte for the end of the text and would accept whatever
  // came before it, ignoring the rest; JSON text has no NUL byte anywhere.
  if (std::optional<std::string> nul = nul_problem(text)) {
    root = Json();
    return {std::move(nul)};
  }
  DomBuilder builder([text](std::size_t offset) { return line_column(text, offset); }, root, stream,
                     depth);
  Json::sax_parse(text, &builder);
  ParseOutcome outcome;
  outcome.problem = std::move(builder.problem);
  if (outcome.problem) root = Json();
  return outcome;
}

}  // namespace

ParseOutcome parse_json(std::string_view text, Json& root, const ElementStream* stream) {
  return parse_text(text, root, stream, 0);
}

ParseOutcome parse_json_at_depth(std::string_view text, Json& root, std::size_t depth) {
  return parse_text(text, root, nullptr, depth);
}

ParseOutcome parse_json(std::istream& in, Json& root, const ElementStream* stream) {
  // As for text: the parser would take a NUL byte for the end. It is looked for as the
  // parse reads, in one pass (a gzip file is inflated once): a parse that reaches the end
  // without one has seen every byte. Only where the parse stops early or a NUL came by is
  // the stream read again from its start, to say where the first NUL is, if anywhere: as
  // before any parse, the NUL is the problem wherever it stands.
  in.clear();
  in.seekg(0);
  NulWatchingInput watched(in);
  DomBuilder builder([&in](std::size_t offset) { return line_column(in, offset); }, root, stream);
  const bool parsed = Json::sax_parse(watched, &builder);
  if (!parsed || builder.problem || watched.saw_nul()) {
    if (std::optional<std::string> nul = nul_problem(in)) {
      root = Json();
      return {std::move(nul)};
    }
  }
  ParseOutcome outcome;
  outcome.problem = std::move(builder.problem);
  if (outcome.problem) root = Json();
  return outcome;
}

}  // namespace shadowgen::json::detail
