#include "snap_contacts.h"

#include <algorithm>
#include <cmath>

#include "clipper/predicates.h"
#include "crossing.h"
#include "snap.h"

namespace shadowgen::clipper::detail {
namespace {

double distance(const Point2& p, const Point2& q) { return std::hypot(q.x - p.x, q.y - p.y); }

// Whether v lies strictly between the ends of a0-a1 by projection and within d of it.
bool within_distance(const Point2& v, const Point2& a0, const Point2& a1, double d) {
  if (!projects_inside(v, a0, a1)) return false;
  const double dx = a1.x - a0.x, dy = a1.y - a0.y;
  return std::fabs(orient2d_value(a0, a1, v)) <= d * std::sqrt(dx * dx + dy * dy);
}

bool in_box(const Point2& p, const Piece& e) {
  return p.x >= std::min(e.from.x, e.to.x) - e.margin &&
         p.x <= std::max(e.from.x, e.to.x) + e.margin &&
         p.y >= std::min(e.from.y, e.to.y) - e.margin &&
         p.y <= std::max(e.from.y, e.to.y) + e.margin;
}

}  // namespace

bool properly_cross(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1) {
  const Orientation oa0 = orient2d(b0, b1, a0);
  const Orientation oa1 = orient2d(b0, b1, a1);
  if (oa0 == Orientation::kCollinear || oa1 == Orientation::kCollinear || oa0 == oa1) return false;
  const Orientation ob0 = orient2d(a0, a1, b0);
  const Orientation ob1 = orient2d(a0, a1, b1);
  return ob0 != Orientation::kCollinear && ob1 != Orientation::kCollinear && ob0 != ob1;
}

void ContactFinder::find(std::size_t i, std::size_t j) {
  const Piece& a = pieces_[i];
  const Piece& b = pieces_[j];
  // Vertices in each other's pixels become one: first, as the other contacts of the
  // two pieces change with it. (Each asked, none skipped: every merge is recorded.)
  const bool m0 = merge(a.from, b.from), m1 = merge(a.from, b.to);
  const bool m2 = merge(a.to, b.from), m3 = merge(a.to, b.to);
  if (m0 || m1 || m2 || m3) return;
  // A vertex of one in the other's way: the other's segment is routed through it. The
  // two then share that vertex and cannot cross: no crossing is made, which would only
  // be rounded a hair from it (two nearly parallel edges, crossed again and again by
  // the rounding of each new crossing, would never settle).
  const bool s0 = snap(a.from, j), s1 = snap(a.to, j), s2 = snap(b.from, i), s3 = snap(b.to, i);
  if (s0 || s1 || s2 || s3) return;
  if (a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to) return;
  if (properly_cross(a.from, a.to, b.from, b.to)) cross(i, j);
}

bool ContactFinder::merge(const Point2& p, const Point2& q) {
  if (!within_snap_distance(p, q)) return false;
  found_.merges.emplace_back(p, q);
  return true;
}

// Whether v lies in piece e's way: e passes through v's pixel (exactly through v
// included), or v lies between e and its segment's line, nearer e than e moved from it
// (e moved when routed through a vertex off its segment, by up to that vertex's pixel,
// which far from the origin is wider than the pixels of vertices it passes nearer the
// origin; such a vertex would otherwise end on the wrong side of e, and a needle of
// the input turn over there).
bool ContactFinder::snap(const Point2& v, std::size_t piece) {
  const Piece& e = pieces_[piece];
  if (!in_box(v, e)) return false;
  const Segment& s = segments_[e.segment];
  const bool in_way = within_snap_distance(v, e.from, e.to) ||
                      (e.deviation > 0.0 && within_distance(v, e.from, e.to, e.deviation) &&
                       between_piece_and_line(v, e, s));
  if (!in_way) return false;
  found_.through.push_back({static_cast<std::uint32_t>(piece), v});
  return true;
}

// Whether v lies off the segment's line on the side the piece moved to, and on the
// line's side of the piece: where the piece's move could have carried it across v.
// Vertices beyond the piece are not routed in, or each round would carry the piece a
// pixel further out.
bool ContactFinder::between_piece_and_line(const Point2& v, const Piece& e, const Segment& s) {
  const Orientation moved = orient2d(s.from, s.to, e.from) != Orientation::kCollinear
                                ? orient2d(s.from, s.to, e.from)
                                : orient2d(s.from, s.to, e.to);
  const Orientation side = orient2d(s.from, s.to, v);
  if (side == Orientation::kCollinear || side != moved) return false;
  // Beside the piece, the line lies on the side the piece moved away from, as seen
  // along the line: for a piece running the segment's way, on its side opposite to
  // `moved`; for one running against it, on that side. Not where the segment's ends lie:
  // a piece tilted by its move (a hair off the line over a length far shorter than the
  // segment's) has a line of its own that can cross the segment's between the ends,
  // putting an end on the far side of the piece; taken from that end, the side was the
  // wrong one, and vertices beyond the piece were routed in round after round (and
  // vertices between it and the line were not). A piece square to the line has the line
  // beside it only where it meets it.
  const int along = dot_sign(s.from, s.to, e.from, e.to);
  if (along == 0) return true;
  const Orientation line = along > 0 ? static_cast<Orientation>(-static_cast<int>(moved)) : moved;
  const Orientation of_v = orient2d(e.from, e.to, v);
  return of_v == Orientation::kCollinear || of_v == line;
}

// The rounded crossing of two properly crossing pieces routes both segments through
// it. Where the segments themselves cross, near the pieces, their crossing is taken: it
// lies within rounding of both input lines, which the pieces' crossing need not. A
// crossing in the pixel of an endpoint of the pieces is that endpoint (the nearest,
// then the least): rounded there, nothing tells the two apart.
void ContactFinder::cross(std::size_t i, std::size_t j) {
  const Piece& a = pieces_[i];
  const Piece& b = pieces_[j];
  const Segment& sa = segments_[a.segment];
  const Segment& sb = segments_[b.segment];
  Point2 p = crossing_point(a.from, a.to, b.from, b.to);
  if (a.deviation > 0.0 || b.deviation > 0.0) {
    if (properly_cross(sa.from, sa.to, sb.from, sb.to)) {
      // Unless both segments already pass through it: then the pieces cross somewhere
      // else, where a piece moved across the other, and that crossing is the one to make.
      const Point2 q = crossing_point(sa.from, sa.to, sb.from, sb.to);
      if (in_box(q, a) && in_box(q, b) && !(passes_through(sa, q) && passes_through(sb, q))) {
        p = q;
      }
    }
  }
  const Point2* nearest = nullptr;
  double nearest_distance = INFINITY;
  for (const Point2* end : {&a.from, &a.to, &b.from, &b.to}) {
    if (*end != p && !within_snap_distance(p, *end)) continue;
    const double d = distance(p, *end);
    if (d < nearest_distance || (d == nearest_distance && *end < *nearest)) {
      nearest = end;
      nearest_distance = d;
    }
  }
  if (nearest != nullptr) {
    p = *nearest;
  } else {
    ++found_.crossings;
  }
  // Whole input edges on both sides: the exact crossing is known by its two edges.
  const bool whole = a.from == sa.from && a.to == sa.to && b.from == sb.from && b.to == sb.to;
  found_.through.push_back({static_cast<std::uint32_t>(i), p, whole, b.from, b.to});
  found_.through.push_back({static_cast<std::uint32_t>(j), p, whole, a.from, a.to});
}

// Whether p is an end of the segment or on its route (as the route is before merging).
bool ContactFinder::passes_through(const Segment& s, const Point2& p) {
  return p == s.from || p == s.to || std::find(s.route.begin(), s.route.end(), p) != s.route.end();
}

}  // namespace shadowgen::clipper::detail
