#pragma once

// Snap rounding of the two operands' boundaries together, in floating point: the step
// that makes every later decision of the clipper exact.
//
// Every point where two edges meet is made a vertex of both: a proper crossing, rounded
// (crossing.h), and a vertex lying on an edge or in its way (snap.h: the edge passes
// through the vertex's hot pixel). A rounded crossing or a vertex brought onto an edge
// moves that edge by a hair, and the moved pieces may then meet others, so the step
// repeats on the new pieces until none meets another except at a common endpoint or as
// the very same segment: iterated snap rounding (Hobby 1999; Halperin and Packer 2002),
// with doubles for the grid and hot pixels of six ulps of each point's own
// magnitude. Each input edge keeps its route, the points it passes through in order; a
// point found in the way of a piece goes into that piece, and into a route at most once,
// so no two points can take turns splitting each other. A route found passing a point a
// second time has the stretch between cut out (a sliver loop narrower than the pixels
// it passes). Put back, the points cut out can make the same cut again, round after
// round, where dozens of rounded crossings crowd within a few pixels (the shadow edges
// of a sun path fanning out from one corner), so the rounds first keep them out of that
// route; where that leaves edges crossing, the rounds run again putting them back, and
// such cycles pass through states whose edges meet only at vertices (snap_convergence.h).
// Each way settled inputs the other did not. Where neither does, the operands are snap
// rounded on a grid (grid_snap.h), which moves their vertices further but needs no
// rounds.
//
// Vertices in each other's pixels are merged (the one with the wider pixel stays), never
// along a chain. A piece routed through a vertex off its input edge may lie that far from
// the input line, which far from the origin is more than the pixels of the vertices it
// passes nearer the origin; a vertex between the piece and its input line is routed in
// too, or it would end on the wrong side and a thin needle of the input turn over.
// Where two moved pieces cross and their input edges cross as well, the crossing of the
// input edges is taken (within rounding of both input lines). Crossings on a whole input
// edge that lie within their rounding of each other along it are put in the order of
// their exact points (orient2d_crossing, predicates.h): a long edge's coordinate can
// round by more than the thickness of what it crosses.
//
// Afterwards the boundaries form a plane graph whose vertices are doubles: which side of
// the other operand an edge lies on, whether two edges are the same, where a loop turns,
// all are exact predicates on those doubles, with no rounded point left to disagree with
// them. The clipper's pieces are the Boolean combination of the snapped operands.
//
// How far the boundaries move: a crossing by its rounding (5u of each coordinate's
// magnitude), a vertex by a merge (within its pixel), an edge by the pixels of the
// points it is routed through. Features narrower than a pixel can close up: a needle of
// the input becomes a spike, which the clipper cancels.

#include <cstddef>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

struct SnapRoundingStats {
  int rounds = 0;             // rounds that changed a route or merged vertices
  std::size_t crossings = 0;  // rounded crossing points made
  std::size_t splits = 0;     // points put into routes
  bool converged = true;      // false when the round limit stopped it, or it ended
                              // with points held out of routes they were cut from
  bool separated = false;     // decided by the shortcut, without rounds
  bool on_grid = false;       // neither way of the rounds ended noded: snapped on a grid
};

// Whether snap_round may take its shortcut (operands of a few edges, well clear of each
// other but where edges cross properly or a vertex lies in an edge's way: the edges
// routed through those points, no rounds) or must run the rounds, which give the same
// loops there (for tests that hold the two side by side).
enum class SnapPath { kShortcutWhereShown, kRoundsOnly };

// The loops of both operands (loops[0] the subject's, loops[1] the clip's, each running
// with its region on the left), snapped in place. A loop may come back with spikes,
// repeated vertices or edges run both ways (a needle of its region closed by the
// snapping); a loop snapped to a single point comes back empty, in its place.
//
// Whatever way the rounds end (settled, stopped by the round limit, or with points held
// out of routes: stats->converged false), the snapped edges are checked exactly: meeting
// only at common vertices or as the very same segment, they are a plane graph, and the
// loops come back snapped as far as the rounds went. Otherwise they are snapped on a
// grid (stats->on_grid), whose result is checked the same way; where that fails too (no
// input is known to), it throws
// SnapRoundingError (clipper/clip.h), after filling `stats`, and the loops are left as
// they came: a graph that is not noded would give every caller pieces whose areas could
// be wrong, so none gets one.
void snap_round(std::vector<Loop2> (&loops)[2], SnapRoundingStats* stats = nullptr,
                SnapPath path = SnapPath::kShortcutWhereShown);

}  // namespace shadowgen::clipper::detail
