#pragma once

// JSON text: writing it by hand, for outputs whose layout we choose line by line (the
// shadowed database, the JSON report), and reading errors worded for people. Numbers are
// the shortest decimal form that reads back to the same double, so every value survives
// a write and a read bit for bit.

#include <exception>
#include <string>
#include <string_view>

namespace shadowgen::detail {

// Shortest round-trip form (std::to_chars), always with a '.' or an exponent so that JSON
// readers take it for a floating-point number: 28 is written "28.0" and -0 as "-0.0",
// which keeps its sign. Precondition: `value` is finite (JSON has no NaN or infinity).
void append_json_number(std::string& out, double value);

// A quoted JSON string. Bytes that are not valid UTF-8 become U+FFFD, so the output is
// always valid JSON; valid UTF-8 is kept as it is.
void append_json_string(std::string& out, std::string_view text);

// nlohmann's message without its "[json.exception.parse_error.101] " tag: "parse error at
// line 3, column 5: syntax error while parsing ...".
std::string json_error_message(const std::exception& error);

}  // namespace shadowgen::detail
