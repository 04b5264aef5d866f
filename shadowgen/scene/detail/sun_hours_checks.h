#pragma once

// The checks of a database's sums over a sun path on one face (docs/scene-format.md, "Sun
// hours"), once the face and every path are read: each gives the problem, worded for the
// message that names the face and its faces[i].sun_hours.<path>, or nothing. Lit polygons
// are checked by detail/lit_checks.h, which these build on; the rounding allowed is its
// LitChecker::area_tolerance. A check whose clip does not settle its snapping throws the
// clipper's SnapRoundingError.

#include <cstddef>
#include <optional>
#include <string>

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::scene::detail {

// A whole database's path on face f: its regions (where kept) on the face's planes, inside
// it and not overlapping, their areas summing to the face's and Σ hours × area to the lit
// areas' Σ × step; then lit_areas_problem's checks.
std::optional<std::string> sun_hours_problem(const Face& face, const SunPathHours& path,
                                             std::size_t f);

// A shard's nodes on face f, each checked as a face's regions are.
std::optional<std::string> nodes_problem(const Face& face, const SunPathHours& path, std::size_t f);

// Lit areas alone: none above the face's area, nor a part's above the part's, the parts'
// summing to the face's.
std::optional<std::string> lit_areas_problem(const Face& face, const SunPathHours& path,
                                             std::size_t f);

// On a face of several parts, the parts' lit areas against the parts and the face's lit
// area, up to `tolerance`.
std::optional<std::string> part_lit_area_problem(const Face& face, const SunPathHours& path,
                                                 std::size_t f, double tolerance);

}  // namespace shadowgen::scene::detail
