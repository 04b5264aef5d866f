#pragma once

// Exact plane predicates over the loops of a face in its chart, shared by the loop
// checks (loop_validation.h) and the analysis of pinched and bridged loops
// (loop_pieces.h). Everything is decided with clipper::orient2d, never with a tolerance.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::scene::detail {

// No edge: a bridge partner or next edge that does not exist.
inline constexpr std::uint32_t kNoEdge = std::numeric_limits<std::uint32_t>::max();

// A loop with consecutive repeated vertices removed, remembering where each kept vertex
// was in the given loop (for messages).
struct CleanLoop {
  std::vector<clipper::Point2> points;
  std::vector<std::size_t> original;
};

CleanLoop clean(const clipper::Loop2& loop);

// The index in the given loop of the vertex at `clean_index` (taken round the loop), as
// messages name it.
std::string vertex_name(const CleanLoop& loop, std::size_t clean_index);

// Where a loop passes through a point: the points before and after it along the loop.
struct Corner {
  clipper::Point2 prev, at, next;
};

// Strictly to the left of the path prev -> at -> next, near `at`.
bool left_of(const Corner& c, const clipper::Point2& w);

// Whether two passages through one point cross there: the directions in and out of one
// lie on both sides of the other's path. Their directions must all differ.
bool cross(const Corner& a, const Corner& b);

// Crossing-number test, exact; `p` must not lie on the loop.
bool inside_loop(const std::vector<clipper::Point2>& loop, const clipper::Point2& p);

// What the directed edge a -> b adds to the winding number around x, which is not on it.
int winding(const clipper::Point2& a, const clipper::Point2& b, const clipper::Point2& x);

// Directions from p, counter-clockwise from +x, exactly; q1 and q2 must not lie in the
// same direction.
bool angle_less(const clipper::Point2& p, const clipper::Point2& q1, const clipper::Point2& q2);

// A direction from a point along a loop: to the vertex before (into the point) or after.
struct Ray {
  clipper::Point2 to;
  bool out;
};

}  // namespace shadowgen::scene::detail
