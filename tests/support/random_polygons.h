#pragma once

// Seeded generators of test polygons. Every generator draws only from the given
// std::mt19937_64, so a seed names the same case on every run of one build (another
// standard library may map a seed to other cases: its distributions and std::sin and
// std::cos are its own).
//
// Loops come out with random orientation and random starting vertex (the clipper
// normalises on entry, so tests should exercise that too).

#include <random>

#include "clipper/polygon.h"

namespace shadowgen::test {

using clipper::Loop2;
using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

// A concave polygon with 1 to 3 holes in generic double coordinates (all 53 bits used):
// a star-shaped outer loop of 5 to 16 vertices with jittered radii around a centre in
// [-0.5, 0.5]², radius at most 1.2; each hole a star-shaped loop of 3 to 8 vertices
// inside a disk that lies strictly inside the outer loop and apart from the other holes.
// Two such polygons overlap partially most of the time.
PolygonWithHoles2 random_polygon_with_holes(std::mt19937_64& rng);

// Side of the coarse grid of random_grid_polygon: coordinates are integers in
// [0, kGridSize], so two grid polygons share vertices and collinear overlapping edges
// very often.
inline constexpr int kGridSize = 12;

// A valid polygon (checked by the CGAL oracle, regenerated until valid) on the integer
// grid: either a polyomino (a 4-connected set of unit cells without pinch points,
// sometimes with holes carved out; its unit edges are merged into long ones except in
// one case out of four, which keeps collinear vertices), or a star-shaped polygon snapped
// to the grid (diagonal edges, so intersection points fall off the grid) with up to two
// snapped holes.
PolygonWithHoles2 random_grid_polygon(std::mt19937_64& rng);

// A triangle with height / base = aspect (e.g. 1e-7), base length in [1, 2], random
// direction, its base's midpoint in [-0.2, 0.2]², so two slivers usually cross.
PolygonWithHoles2 sliver_triangle(std::mt19937_64& rng, double aspect);

// A self-crossing loop of `lines` chords through (1000, 1000), each of length 1 to 3 in
// a random direction, visited end by end, every end moved by a hair of up to 1e-13:
// almost concurrent lines, whose rounded crossings crowd around the centre and lie off
// their lines by more than at the origin. Not normalised.
Loop2 almost_concurrent_star(std::mt19937_64& rng, int lines);

// Reverses each loop with probability 1/2 and starts it at a random vertex.
void randomize_loops(PolygonWithHoles2& polygon, std::mt19937_64& rng);

}  // namespace shadowgen::test
