#pragma once

// Whole-scene comparison of shadowgen::generate_shadows with the exact shadow oracle,
// and the lit fractions the metamorphic tests compare.

#include <cstddef>
#include <map>
#include <string>
#include <utility>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::test {

// Worst errors over every (face, light) with area, each relative to the face's area.
struct OracleCheck {
  double worst_area_error = 0.0;    // |our lit area (report) − exact lit area| / area
  double worst_region_error = 0.0;  // area(ours Δ exact) / area
  double worst_overlap = 0.0;       // (sum of our pieces − their union) / area
  double worst_outside = 0.0;       // area(ours − face) / area
  double worst_bound_ratio = 0.0;   // the largest error over its pair's bound
  std::size_t pairs = 0;            // (face, light) pairs compared
  std::size_t failures = 0;         // pairs beyond the tolerance, or unreadable
  std::string report;               // the first few failing pairs, in full
  std::size_t invalid = 0;          // pairs with a lit loop that is not simple
  std::string invalid_report;       // the first few of them
};

// Generates (or takes `shadowed`) and compares every (face, light) with the oracle;
// a pair fails when any error above exceeds its bound or our polygons cannot be read.
// The bound of a pair is `tolerance` + vertex_error × (the length of our lit polygons'
// boundary) / (the face's area): what moving every lit vertex by vertex_error can
// change, for scenes whose coordinates cannot hold 1e-9 of a face's area.
// Loops that are not simple are counted apart (`invalid`): they are measured all the same.
OracleCheck check_against_oracle(const Scene& scene, const ShadowedScene& shadowed,
                                 double tolerance, double vertex_error = 0.0);
OracleCheck check_against_oracle(const Scene& scene, double tolerance, double vertex_error = 0.0);

// "worst area 1.2e-15, region 3.4e-15, overlap 0, outside 0 over 40 pairs".
std::string summary(const OracleCheck& check);

// Lit fraction by (face id, light id), from the report rows of a generation.
std::map<std::pair<std::string, std::string>, double> lit_fractions(const ShadowedScene& shadowed);

}  // namespace shadowgen::test
