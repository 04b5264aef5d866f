#pragma once

// Numbers as text, written the same way wherever shadowgen writes one (the database,
// reports, OBJ, SVG, messages), independent of the C locale, never truncated; and read
// from the text files shadowgen reads (mesh files, weather files) the same way.

#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace shadowgen {

// The shortest decimal form that reads back to the same double (std::to_chars): "0.1",
// "28", "1e+101". Non-finite values come out as "inf", "-inf" or "nan"; writers that
// must never hold them check before writing.
void append_shortest(std::string& out, double value);
std::string shortest(double value);

// `precision` significant digits (general) or decimals (fixed): "1.24e-07", "0.8367".
// Whatever the length: a fixed form of 1e300 has over 300 digits, and is given whole.
std::string number_text(double value, std::chars_format format, int precision);

// The whole token as a double (a leading '+' allowed); nullopt when it is not a number or
// is out of a double's range. Infinities and NaNs spelled out come back as such: callers
// that need finite numbers check. Independent of the C locale (std::from_chars).
std::optional<double> parse_number(std::string_view token);

// The whole token as an integer (a leading '+' allowed); nullopt otherwise.
std::optional<std::int64_t> parse_integer(std::string_view token);

}  // namespace shadowgen
