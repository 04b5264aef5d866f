#pragma once

// Snap rounding on a grid (Greene and Yao 1986; Hobby 1999; Guibas and Marimont 1998):
// the snapping's last resort (snap_rounding.h), for inputs on which its iterated rounds
// cycle without reaching edges that meet only at vertices.
//
// The plane is cut into square cells of width g, each the half-open square
// [c − g/2, c + g/2) around its centre c, a multiple of g in both coordinates. A cell that
// holds a vertex or a proper crossing of two edges is hot, and every edge is replaced by
// the centres of the hot cells it meets, in order along it. One pass, no rounds: edges
// routed so cannot cross (the theorem of snap rounding; edges may come to share a
// fragment, or a centre land exactly on another edge's fragment, which is made a vertex
// of it), so what the overlay needs is reached by construction. The noded check
// (snap_convergence.h) still judges the result.
//
// Exact throughout: g is a power of two, so centres and cell sides are doubles; which
// cells an edge meets is decided with orient2d on the corners, the upper and right sides
// taken a hair inside the cell, which makes the closed square the half-open cell (an
// edge through a corner or along a side meets the cells that hold its points, and no
// other); a crossing, whose rounded point lies within 5u of the exact one, marks every
// cell within that of it hot (extra hot cells cost a detour through their centres, never
// a crossing).
//
// The price is a coarser tolerance than the rounds' pixels: every vertex moves to its
// cell's centre, up to g/√2, and g is the smallest power of two of at least 8u·M
// (u = 2^-53), M the largest coordinate magnitude of the loops it is snapped with: a
// vertex moves less than 12u·M, the half-width of the rounds' pixel at that magnitude.
// Loops are snapped together only with those whose boxes, grown by the grid of all
// loops, meet theirs (directly or along a chain), each such group on its own grid, so a
// small feature near the origin is not rounded to the grid of coordinates elsewhere
// unless a loop joins them.

#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

// The loops of both operands (as snap_round takes them), snapped in place on grids. A
// loop may come back with spikes or edges run both ways, and a loop snapped to a single
// point comes back empty, as from snap_round.
void snap_round_on_grid(std::vector<Loop2> (&loops)[2]);

}  // namespace shadowgen::clipper::detail
