#pragma once

// How strictly an input (a scene, its meshes, a shadowed database) is read.

namespace shadowgen {

struct ReadOptions {
  // What is otherwise a warning is an error: a non-planar polygon (instead of being split
  // into triangles), a key the format does not define.
  bool strict = false;
};

}  // namespace shadowgen
