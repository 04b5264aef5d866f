#pragma once

// How strictly an input (a scene, its meshes, a shadowed database) is read.

namespace shadowgen {

struct ReadOptions {
  // What is otherwise a warning is an error: a non-planar polygon (instead of being split
  // into triangles), a key the format does not define.
  bool strict = false;
  // Every warning on a line of its own. Otherwise a kind of warning that more than
  // kWarningsListed faces of one mesh, or of a scene's polygons, draw is one line: how
  // many, the kind, the first faces' ids ("56 faces of mesh 'spider': zero area:
  // spider/924, spider/927, spider/931, ... (--verbose lists all)"; "1000 polygons: not
  // planar: p0, p1, p2, ... (--verbose lists all)"). detail/warning_summary.h.
  bool verbose = false;
};

inline constexpr int kWarningsListed = 3;

}  // namespace shadowgen
