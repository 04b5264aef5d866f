#include "shadowgen/json/json_writer.h"

#include <cassert>
#include <cmath>
#include <stdexcept>

#include "shadowgen/json/json_text.h"

namespace shadowgen {
namespace {

constexpr std::size_t kPieceBytes = std::size_t{1} << 20;

}  // namespace

void JsonWriter::spill() {
  if (sink_ && out_.size() >= kPieceBytes) {
    sink_(out_);
    out_.clear();
  }
}

void JsonWriter::newline(std::size_t depth) {
  out_ += '\n';
  out_.append(2 * depth, ' ');
}

void JsonWriter::separate() {
  spill();
  if (after_key_) {  // the value of a member: right after its key
    after_key_ = false;
    return;
  }
  if (open_.empty()) return;
  Open& open = open_.back();
  if (!open.empty) out_ += ',';
  if (open.layout == Layout::kLines) newline(open_.size());
  open.empty = false;
}

JsonWriter& JsonWriter::begin_object(Layout layout) {
  separate();
  out_ += '{';
  open_.push_back({layout});
  return *this;
}

JsonWriter& JsonWriter::begin_array(Layout layout) {
  separate();
  out_ += '[';
  open_.push_back({layout});
  return *this;
}

JsonWriter& JsonWriter::close(char bracket) {
  assert(!open_.empty() && !after_key_);
  const Open open = open_.back();
  open_.pop_back();
  if (open.layout == Layout::kLines && !open.empty) newline(open_.size());
  out_ += bracket;
  return *this;
}

JsonWriter& JsonWriter::end_object() { return close('}'); }

JsonWriter& JsonWriter::end_array() { return close(']'); }

JsonWriter& JsonWriter::key(std::string_view key) {
  assert(!open_.empty() && !after_key_);
  separate();
  json::detail::append_json_string(out_, key);
  out_ += open_.back().layout == Layout::kLines ? ": " : ":";
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(double number) {
  if (!std::isfinite(number)) {
    throw std::invalid_argument("JSON output: a number is not finite (JSON has no " +
                                std::string(std::isnan(number) ? "NaN" : "infinity") + ")");
  }
  separate();
  json::detail::append_json_number(out_, number);
  return *this;
}

JsonWriter& JsonWriter::value(std::uint64_t integer) {
  separate();
  out_ += std::to_string(integer);
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) {
  separate();
  json::detail::append_json_string(out_, text);
  return *this;
}

JsonWriter& JsonWriter::value(const glm::dvec3& v) {
  begin_array();
  value(v.x).value(v.y).value(v.z);
  return end_array();
}

std::string JsonWriter::take() {
  assert(open_.empty() && !after_key_ && !sink_);
  out_ += '\n';
  return std::move(out_);
}

void JsonWriter::finish() {
  assert(open_.empty() && !after_key_ && sink_);
  out_ += '\n';
  sink_(out_);
  out_.clear();
}

}  // namespace shadowgen
