#pragma once

// Snap rounding's shortcut held against its rounds (clipper/detail/snap_rounding.h), on
// the boundaries clip() snaps for a subject and a clip region: where the shortcut
// decides, it must give the very loops and statistics the rounds give.

#include <string>

#include "clipper/polygon.h"

namespace shadowgen::test {

// "" when the two agree or the shortcut does not decide (*taken tells which); otherwise
// what differs.
std::string shortcut_disagreement(const clipper::PolygonSet2& subject,
                                  const clipper::PolygonSet2& clip, bool* taken = nullptr);

}  // namespace shadowgen::test
