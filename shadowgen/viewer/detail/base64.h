#pragma once

// Base64 (RFC 4648, section 4: the standard alphabet, '=' padding, no line breaks), which
// a browser's atob() reads.

#include <string>
#include <string_view>

namespace shadowgen::viewer::detail {

std::string base64(std::string_view bytes);

}  // namespace shadowgen::viewer::detail
