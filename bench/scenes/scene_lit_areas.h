#pragma once

// Lit area per face and light of a generate_shadows result, checked: every lit area must
// lie in [0, face area] (up to 1e-9 relative rounding); a result outside that range
// throws, so a broken run cannot produce a figure.

#include <vector>

#include "shadowgen/shadows/generate.h"

namespace shadowgen::bench {

struct LitAreas {
  std::vector<double> face_area;         // per face
  std::vector<std::vector<double>> lit;  // lit[light][face]
  double total_area = 0.0;
};

LitAreas checked_lit_areas(const ShadowedScene& shadowed);

}  // namespace shadowgen::bench
