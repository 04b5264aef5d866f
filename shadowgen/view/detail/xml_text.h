#pragma once

// Text as XML character data, in an attribute value or an element, for the SVG files the
// view room writes: &, <, >, " and ' escaped, tab, line feed and carriage return as
// character references (attribute normalisation would make them spaces), and bytes that
// are not valid UTF-8 or not allowed in XML 1.0 replaced by U+FFFD.

#include <string>
#include <string_view>

namespace shadowgen::view::detail {

void append_xml_text(std::string& out, std::string_view text);
std::string xml_text(std::string_view text);

}  // namespace shadowgen::view::detail
