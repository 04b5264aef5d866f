#pragma once

// JSON text pieces for the writer (json_writer.h): numbers in the shortest decimal form
// that reads back to the same double, so every value survives a write and a read bit for
// bit, and strings escaped as JSON requires.

#include <string>
#include <string_view>

namespace shadowgen::json::detail {

// Shortest round-trip form (std::to_chars), always with a '.' or an exponent so that JSON
// readers take it for a floating-point number: 28 is written "28.0" and -0 as "-0.0",
// which keeps its sign. Precondition: `value` is finite (JSON has no NaN or infinity).
void append_json_number(std::string& out, double value);

// A quoted JSON string. Bytes that are not valid UTF-8 become U+FFFD, so the output is
// always valid JSON; valid UTF-8 is kept as it is.
void append_json_string(std::string& out, std::string_view text);

}  // namespace shadowgen::json::detail
