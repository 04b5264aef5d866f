#pragma once

// The checks of a shadowed database once every face is read, faces in parallel: its lit
// polygons (lit_checks.h) and its sums over sun paths (sun_hours_checks.h), the costly
// part of reading a database (a clip per part and light). The problem reported is the
// first in the file's order, an InputError at its place; a check whose clip did not settle
// its snapping (docs/clipper.md, Limit) is not the input's fault, and not known to be right
// either: it throws the clipper's SnapRoundingError, naming the file, the face and where in
// it (the command line's exit code 3).

#include <cstddef>
#include <vector>

#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::scene::detail {

// One face's list of lit polygons for one light, and where it stands in the file.
struct LitList {
  std::size_t light;
  JsonPlace place;
};

// Each face's lists of lit polygons: lists_of_face[f] is where face f's lists start in
// `lists`. Each list on the face's planes, inside it, not overlapping.
void check_lit_lists(const ShadowedScene& shadowed, const std::vector<std::size_t>& lists_of_face,
                     const std::vector<LitList>& lists);

// Each face's sun-hours regions over a path, checked as one face's lit polygons are,
// all regions together: on the face's planes, inside it, not overlapping. They must
// also tile it: their areas sum to the face's, and Σ hours × area to the lit areas'
// Σ × step, up to the rounding along the regions' boundaries (LitChecker::
// area_tolerance; times the path's hours for the second sum, each instant's lit
// boundary lying along them), and no instant's lit area exceeds the face's by more.
// In a shard, the nodes' sums get the same checks (nodes_problem). places[p][f] is where
// face f's sum over path p stands.
void check_sun_hours_sums(const ShadowedScene& shadowed,
                          const std::vector<std::vector<JsonPlace>>& places);

}  // namespace shadowgen::scene::detail
