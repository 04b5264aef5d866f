#pragma once

// Small EnergyPlus models written for the tests from the Input Output Reference and the
// IDD's field lists, and the helpers that look at what the reader makes of them.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "hsr/area.h"
#include "shadowgen/energyplus/energyplus_reader.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::energyplus::testing {

inline SourceModel read_idf(std::string_view text, const SourceOptions& options = {}) {
  return parse_energyplus(text, "model.idf", options);
}

inline const SourceFace& face_named(const SourceModel& model, std::string_view id) {
  const auto it = std::find_if(model.faces.begin(), model.faces.end(),
                               [&](const SourceFace& f) { return f.id == id; });
  if (it == model.faces.end()) {
    ADD_FAILURE() << "no face '" << id << "'";
    static const SourceFace none;
    return none;
  }
  return *it;
}

// Each vertex within `tolerance` of the one expected, in order.
inline void expect_loop(const hsr::Loop3& loop, const std::vector<glm::dvec3>& expected,
                        double tolerance = 1e-12) {
  ASSERT_EQ(loop.size(), expected.size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    EXPECT_NEAR(loop[i].x, expected[i].x, tolerance) << "vertex " << i;
    EXPECT_NEAR(loop[i].y, expected[i].y, tolerance) << "vertex " << i;
    EXPECT_NEAR(loop[i].z, expected[i].z, tolerance) << "vertex " << i;
  }
}

// The area of a face's region: its outer loop's less its holes'.
inline double net_area(const SourceFace& face) { return hsr::area(face.polygon); }

// The message of the InputError reading `text` throws.
inline std::string error_of(std::string_view text, std::string_view file = "model.idf") {
  try {
    (void)parse_energyplus(text, std::string(file), {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace shadowgen::energyplus::testing
