#pragma once

// The triangles a mesh primitive draws, as positions in its vertex sequence (the indices'
// order, or the vertices' where it has none), by the glTF 2.0 specification, 3.7.2.1
// "Overview" of mesh primitives, topology types:
//   TRIANGLES (4, the default): p_i = {v_3i, v_3i+1, v_3i+2};
//   TRIANGLE_STRIP (5):         p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)}, keeping every
//                               triangle's winding that of the first;
//   TRIANGLE_FAN (6):           p_i = {v_i+1, v_i+2, v_0}.
// POINTS, LINES, LINE_LOOP and LINE_STRIP (0 to 3) draw no faces and are refused by the
// reader; so is a TRIANGLES sequence whose length is not a multiple of 3.

#include <array>
#include <cstddef>
#include <optional>

namespace shadowgen::gltf::detail {

enum class Topology { kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6 };

// The topology of glTF mode `mode` (-1, absent, is TRIANGLES); nullopt for another mode.
std::optional<Topology> triangle_topology(int mode);

// "POINTS", "LINES", ..., or the number.
const char* mode_name(int mode);

// How many triangles a sequence of `vertices` draws (0 for fewer than 3 in a strip or a
// fan); for TRIANGLES the caller has checked `vertices` is a multiple of 3.
std::size_t triangle_count(Topology topology, std::size_t vertices);

// The positions in the sequence of triangle `i`'s corners, in its winding.
std::array<std::size_t, 3> triangle_corners(Topology topology, std::size_t i);

}  // namespace shadowgen::gltf::detail
