#pragma once

// The key probably meant by an unknown one: "rnage" -> "range", "tranform" -> "transform",
// "hole" -> "holes".

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace shadowgen::json::detail {

// Edit distance counting an insertion, a deletion, a substitution or a swap of two
// neighbouring characters as one edit (optimal string alignment), letters compared
// without regard to case.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The known key nearest to `unknown`, when it is close: at most one edit for keys of up to
// four characters, two for longer ones (closer than that, a typo is likelier than a
// different word). The first of equals, in the order given; none when nothing is close.
std::optional<std::string> closest_key(std::string_view unknown,
                                       std::span<const std::string> known);

}  // namespace shadowgen::json::detail
