#include "shadowgen/shadows/detail/coplanar_groups.h"

#include <gtest/gtest.h>

#include <vector>

namespace shadowgen::shadows::detail {
namespace {

hsr::Polygon3 square_at_height(double x, double z) {
  return {{{x, 0.0, z}, {x + 1.0, 0.0, z}, {x + 1.0, 1.0, z}, {x, 1.0, z}}, {}};
}

// Groups are numbered in the order of their planes' offsets, each polygon that starts a
// plane taking a number whether or not another joins it, as one pass over the sorted
// planes numbers them; the runs of offsets settled apart (more than the window between
// them) keep that numbering. Exactly coplanar polygons share a group; a plane 1e-3 off
// is another; a polygon without area has none.
TEST(CoplanarGroups, GroupsAreNumberedInTheOrderOfTheirPlanes) {
  std::vector<hsr::Polygon3> polygons = {
      square_at_height(0.0, 5.0),                                 // third plane, with polygon 3
      square_at_height(0.0, 0.0),                                 // first plane, with polygon 2
      square_at_height(4.0, 0.0),                                 //
      square_at_height(4.0, 5.0),                                 //
      square_at_height(2.0, 2.0),                                 // second plane, alone
      square_at_height(2.0, 5.001),                               // fourth plane, alone
      {{{0.0, 0.0, 1.0}, {1.0, 1.0, 1.0}, {2.0, 2.0, 1.0}}, {}},  // no area
  };
  std::vector<hsr::Plane3> planes;
  for (const hsr::Polygon3& p : polygons) planes.push_back(hsr::plane_of(p));
  EXPECT_EQ(coplanar_groups(polygons, planes), (std::vector<int>{2, 0, 0, 2, -1, -1, -1}));
}

}  // namespace
}  // namespace shadowgen::shadows::detail
