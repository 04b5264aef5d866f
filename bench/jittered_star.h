#pragma once

// Benchmark workload: jittered star-shaped polygons with star-shaped holes, and the
// standard overlapping pair that every clipper of bench/ is timed on.
//
// Shape. Each loop is star-shaped about its own centre: its vertices are visited at
// strictly increasing angles and lie at positive radii, so it is simple by
// construction. The radius follows a star profile (arms alternating between an outer
// and an inner radius) multiplied by a random factor 1 ± j, j = min(0.1, 0.6·2π / loop
// size), and each angle is jittered by up to ±0.35 of the angular step. The jitter thus
// scales with the spacing of the vertices: the boundary is locally irregular at every
// size, while the number of crossings between two such polygons grows with the number
// of arms, not quadratically with the number of vertices.
//
// Holes are centred 0.28·radius from the centre and reach at most 0.22·radius from
// their own centre, so they lie inside the outer loop (no closer than 0.6·radius·(1 − j)
// to the centre at a vertex, and above 0.53·radius along the chords) and, for at most 3
// holes, apart from each other (centres 0.48·radius apart).
//
// Determinism. The random numbers come from std::mt19937_64 (whose sequence the
// standard fixes) turned into doubles by hand, not by a <random> distribution (whose
// algorithm it does not fix); only std::sin/std::cos depend on the C library.

#include <cstddef>
#include <cstdint>

#include "clipper/polygon.h"

namespace shadowgen::bench {

struct JitteredStarSpec {
  clipper::Point2 centre;
  double radius = 1.0;
  int arms = 9;
  double rotation = 0.0;  // radians, of the first arm tip
  // Total over the outer loop and the holes; each hole takes an eighth of it (at
  // least 4) and the outer loop the rest.
  std::size_t vertex_count = 64;
  int hole_count = 3;
  std::uint64_t seed = 1;
};

// Outer loop counter-clockwise, holes clockwise, exactly spec.vertex_count vertices in
// all. Precondition: vertex_count >= 8 * (hole_count + 1) and hole_count <= 3.
clipper::PolygonWithHoles2 jittered_star_with_holes(const JitteredStarSpec& spec);

struct StarPair {
  clipper::PolygonWithHoles2 subject;
  clipper::PolygonWithHoles2 clip;
};

// Two different jittered stars (9 and 11 arms, different seeds and rotations) of
// vertex_count vertices each, with centres 0.54 radius apart: each covers roughly
// half of the other, and each one's holes cross the other's boundary and holes.
StarPair overlapping_star_pair(std::size_t vertex_count);

}  // namespace shadowgen::bench
