#pragma once

// Contact finding for snap rounding (snap_rounding.h): given the pieces the input edges
// are currently routed through, which pairs of them meet other than at a common endpoint,
// and what that asks of the routes. The snapping rounds (snap_rounds.cpp) own the routes
// and apply what is found; this is the per-pair decision, kept apart because it is the
// geometric core of the step and reads nothing but the two pieces and their segments.
//
// For each close pair of pieces, in this order (the first that applies decides):
//   - endpoints in each other's pixels are to be merged;
//   - an endpoint of one in the other's way routes the other's segment through it;
//   - pieces that properly cross route both segments through their rounded crossing.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

// Whether a0-a1 and b0-b1 cross at a point interior to both (exact).
bool properly_cross(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1);

// An input edge, and the points it is routed through.
struct Segment {
  Point2 from, to;
  Loop2 route;  // interior points, in order from `from` to `to`
};

// A piece of a route: the edge between two consecutive points of it.
struct Piece {
  Point2 from, to;
  std::uint32_t segment;
  std::uint32_t position;  // it ends at route[position], or at the segment's end
  double margin;           // how far a point meeting it can lie from its box
  double deviation;        // how far it may lie from its segment's line (at its ends, at most)
  bool fresh;              // made or moved in the last round
};

// A point some piece must pass through. A crossing of two pieces that are whole input
// edges keeps the other one, which orders it exactly among others on the same edge.
struct Through {
  std::uint32_t piece;
  Point2 at;
  bool crossing = false;
  Point2 f0{}, f1{};
};

// What one round finds: points each segment must be routed through, and vertices to
// merge.
struct Contacts {
  std::vector<Through> through;
  std::vector<std::pair<Point2, Point2>> merges;
  std::size_t crossings = 0;
};

// Finds the contacts of pairs of pieces, adding them to `found`. The pieces and segments
// are read, never changed: every round finds all its contacts against one state of the
// routes, and applies them together afterwards.
class ContactFinder {
 public:
  ContactFinder(const std::vector<Piece>& pieces, const std::vector<Segment>& segments,
                Contacts& found)
      : pieces_(pieces), segments_(segments), found_(found) {}

  // Records what pieces i and j (indices into the pieces) ask of the routes, if anything.
  void find(std::size_t i, std::size_t j);

 private:
  bool merge(const Point2& p, const Point2& q);
  bool snap(const Point2& v, std::size_t piece);
  static bool between_piece_and_line(const Point2& v, const Piece& e, const Segment& s);
  void cross(std::size_t i, std::size_t j);
  static bool passes_through(const Segment& s, const Point2& p);

  const std::vector<Piece>& pieces_;
  const std::vector<Segment>& segments_;
  Contacts& found_;
};

}  // namespace shadowgen::clipper::detail
