#pragma once

// Text for one line of a message or a table. Ids and paths come from the user's files and
// may hold a line break, a tab or another control character; printed as they are, one
// message would split over lines (and could pass for another). Here each of them becomes
// an escape: "\n", "\r", "\t", or "\xHH" (lower-case hex) for the others, DEL included.
// Everything else, UTF-8 included, is kept as it is.

#include <string>
#include <string_view>

namespace shadowgen {

std::string one_line(std::string_view text);

}  // namespace shadowgen
