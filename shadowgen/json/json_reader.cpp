#include "shadowgen/json/json_reader.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "detail/json_parse.h"
#include "detail/key_suggestion.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen {

using Json = nlohmann::json;

// ---- JsonValue -------------------------------------------------------------------------

JsonValue JsonValue::child(const Json* node, std::string path) const {
  JsonValue value(node, source_, std::move(path));
  value.face_ = face_;
  value.subject_ = subject_;
  return value;
}

JsonValue JsonValue::for_face(std::string id) const {
  JsonValue value = *this;
  value.face_ = std::move(id);
  return value;
}

JsonValue JsonValue::named(std::string subject, std::string_view id) const {
  JsonValue value = *this;
  value.subject_ = std::move(subject);
  value.path_ += " ('";
  value.path_ += id;
  value.path_ += "')";
  return value;
}

bool JsonValue::is_null() const { return node_->is_null(); }
bool JsonValue::is_object() const { return node_->is_object(); }
bool JsonValue::is_array() const { return node_->is_array(); }

std::string JsonValue::describe() const {
  switch (node_->type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::object:
      return "an object";
    default:
      return node_->is_number() ? "a number" : node_->type_name();
  }
}

JsonPlace JsonValue::place() const { return JsonPlace(source_, path_, face_, subject_); }

std::string JsonValue::message(const std::string& problem) const {
  return place().message(problem);
}

void JsonValue::fail(const std::string& problem) const { place().fail(problem); }

void JsonValue::warn(const std::string& problem) const {
  if (source_->warnings != nullptr) source_->warnings->push_back(message(problem));
}

void JsonValue::fail_expected(const char* expected) const {
  fail(std::string("expected ") + expected + ", found " + describe());
}

JsonObject JsonValue::object() const {
  if (!node_->is_object()) fail_expected("an object");
  return JsonObject(*this);
}

JsonArray JsonValue::array() const {
  if (!node_->is_array()) fail_expected("an array");
  return JsonArray(*this);
}

std::string JsonValue::string() const {
  if (!node_->is_string()) fail_expected("a string");
  return node_->get<std::string>();
}

double JsonValue::number() const {
  if (!node_->is_number()) fail_expected("a number");
  const double value = node_->get<double>();
  if (!std::isfinite(value)) fail("the number is not finite");
  return value;
}

std::size_t JsonValue::index() const {
  if (node_->is_number_unsigned()) return node_->get<std::size_t>();
  if (node_->is_number_integer() && node_->get<std::int64_t>() >= 0) {
    return static_cast<std::size_t>(node_->get<std::int64_t>());
  }
  fail_expected("a non-negative integer");
}

glm::dvec3 JsonValue::vec3() const {
  if (!node_->is_array() || node_->size() != 3) {
    fail("expected an array of 3 numbers, found " +
         (node_->is_array() ? "an array of " + std::to_string(node_->size()) : describe()));
  }
  glm::dvec3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    out[static_cast<int>(i)] = child(&(*node_)[i], path_ + "[" + std::to_string(i) + "]").number();
  }
  return out;
}

std::vector<glm::dvec3> JsonValue::vec3_list() const {
  if (!node_->is_array()) fail_expected("an array");
  std::vector<glm::dvec3> out;
  out.reserve(node_->size());
  for (std::size_t i = 0; i < node_->size(); ++i) {
    const Json& point = (*node_)[i];
    // The common case without building a path; anything else is read again to be named.
    if (point.is_array() && point.size() == 3 && point[0].is_number() && point[1].is_number() &&
        point[2].is_number()) {
      const glm::dvec3 p(point[0].get<double>(), point[1].get<double>(), point[2].get<double>());
      if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
        out.push_back(p);
        continue;
      }
    }
    out.push_back(child(&point, path_ + "[" + std::to_string(i) + "]").vec3());
  }
  return out;
}

// ---- JsonObject ------------------------------------------------------------------------

std::size_t JsonObject::size() const { return self_.node_->size(); }

std::optional<JsonValue> JsonObject::find(std::string_view key) {
  if (std::find(asked_.begin(), asked_.end(), key) == asked_.end()) asked_.emplace_back(key);
  const Json& object = *self_.node_;
  const auto it = object.find(key);
  if (it == object.end()) return std::nullopt;
  const std::string& path = self_.path_;
  return self_.child(&*it, path.empty() ? std::string(key) : path + "." + std::string(key));
}

JsonValue JsonObject::get(std::string_view key) {
  std::optional<JsonValue> value = find(key);
  if (!value) self_.fail("missing '" + std::string(key) + "'");
  return std::move(*value);
}

bool JsonObject::has(std::string_view key) { return find(key).has_value(); }

std::vector<std::pair<std::string, JsonValue>> JsonObject::entries() {
  all_known_ = true;
  std::vector<std::pair<std::string, JsonValue>> out;
  out.reserve(size());
  for (const auto& [key, value] : self_.node_->items()) {
    out.emplace_back(key, self_.child(&value, self_.path_ + "['" + key + "']"));
  }
  return out;
}

std::vector<std::string> JsonObject::unknown_keys() const {
  std::vector<std::string> unknown;
  if (all_known_) return unknown;
  for (const auto& [key, value] : self_.node_->items()) {
    if (std::find(asked_.begin(), asked_.end(), key) == asked_.end()) unknown.push_back(key);
  }
  return unknown;
}

std::string JsonObject::unknown_key_problem(const std::string& key) const {
  std::string problem = "unknown key '" + key + "'";
  if (const std::optional<std::string> meant = json::detail::closest_key(key, asked_)) {
    problem += " (did you mean '" + *meant + "'?)";
  }
  return problem;
}

void JsonObject::finish() {
  for (const std::string& key : unknown_keys()) {
    if (self_.source_->strict) self_.fail(unknown_key_problem(key));
    self_.warn(unknown_key_problem(key));
  }
}

// ---- JsonPlace -------------------------------------------------------------------------

JsonPlace JsonPlace::element(std::size_t index) const {
  return JsonPlace(source_, path_ + "[" + std::to_string(index) + "]", face_, subject_);
}

std::string JsonPlace::located(const std::string& problem) const {
  std::string what;
  if (!subject_.empty()) what += subject_ + ": ";
  if (!path_.empty()) what += path_ + ": ";
  return what + problem;
}

std::string JsonPlace::message(const std::string& problem) const {
  return InputError(source_->file, face_, located(problem)).what();
}

void JsonPlace::fail(const std::string& problem) const {
  throw InputError(source_->file, face_, located(problem));
}

// ---- JsonArray, JsonDocument -----------------------------------------------------------

std::size_t JsonArray::size() const { return self_.node_->size(); }

JsonValue JsonArray::at(std::size_t index) const {
  return self_.child(&(*self_.node_)[index], self_.path_ + "[" + std::to_string(index) + "]");
}

JsonDocument::JsonDocument(std::string_view text, JsonSource source)
    : root_(std::make_unique<Json>()), source_(std::make_unique<JsonSource>(std::move(source))) {
  const json::detail::ParseOutcome outcome = json::detail::parse_json(text, *root_);
  if (outcome.problem) throw InputError(source_->file, "", *outcome.problem);
}

JsonDocument::JsonDocument(std::string_view text, JsonSource source, std::string_view streamed_key,
                           const ElementTaker& take)
    : root_(std::make_unique<Json>()), source_(std::make_unique<JsonSource>(std::move(source))) {
  const json::detail::ElementStream stream = element_stream(streamed_key, take);
  const json::detail::ParseOutcome outcome = json::detail::parse_json(text, *root_, &stream);
  if (outcome.problem) throw InputError(source_->file, "", *outcome.problem);
}

JsonDocument::JsonDocument(std::istream& in, JsonSource source, std::string_view streamed_key,
                           const ElementTaker& take)
    : root_(std::make_unique<Json>()), source_(std::make_unique<JsonSource>(std::move(source))) {
  const json::detail::ElementStream stream = element_stream(streamed_key, take);
  const json::detail::ParseOutcome outcome = json::detail::parse_json(in, *root_, &stream);
  if (outcome.problem) throw InputError(source_->file, "", *outcome.problem);
}

JsonDocument::JsonDocument(std::string_view text, JsonSource source, std::string path,
                           std::size_t depth)
    : root_(std::make_unique<Json>()),
      source_(std::make_unique<JsonSource>(std::move(source))),
      root_path_(std::move(path)) {
  const json::detail::ParseOutcome outcome = json::detail::parse_json_at_depth(text, *root_, depth);
  if (outcome.problem) throw InputError(source_->file, "", *outcome.problem);
}

JsonDocument::~JsonDocument() = default;

json::detail::ElementStream JsonDocument::element_stream(std::string_view key,
                                                         const ElementTaker& take) const {
  return {key, [this, key, &take](Json& element, std::size_t index) {
            const JsonValue value(&element, source_.get(),
                                  std::string(key) + "[" + std::to_string(index) + "]");
            return take(root(), value);
          }};
}

JsonValue JsonDocument::root() const { return JsonValue(root_.get(), source_.get(), root_path_); }

}  // namespace shadowgen
