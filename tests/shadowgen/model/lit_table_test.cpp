#include "shadowgen/model/lit_table.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>
#include <vector>

namespace shadowgen {
namespace {

hsr::Polygon3 triangle(double x) { return {{{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}}, {}}; }

TEST(LitTable, LightsNotKeptHoldNothingAndTakeNoRoom) {
  LitTable table(3, 4, {true, false, true, false});
  EXPECT_EQ(table.size(), 3u);
  EXPECT_EQ(table.lights(), 4u);
  EXPECT_TRUE(table.kept(0));
  EXPECT_FALSE(table.kept(1));
  table.at(2, 2).push_back({0, triangle(2)});
  EXPECT_TRUE(std::as_const(table).at(2, 1).empty());
  EXPECT_THROW(table.at(2, 1), std::logic_error);
  EXPECT_THROW(table[0][3], std::logic_error);
  EXPECT_EQ(std::as_const(table)[2][2].size(), 1u);
  // Every light's list, kept or not, in light order.
  std::vector<std::size_t> sizes;
  for (const LitTable::Polygons& polygons : std::as_const(table)[2])
    sizes.push_back(polygons.size());
  EXPECT_EQ(sizes, (std::vector<std::size_t>{0, 0, 1, 0}));
  EXPECT_THROW(std::as_const(table).at(3, 0), std::out_of_range);
  EXPECT_THROW(std::as_const(table).at(0, 4), std::out_of_range);
}

TEST(LitTable, RowsMustBeAlike) {
  const LitTable table({{{}, {{0, triangle(0)}}}, {{{1, triangle(1)}}, {}}});
  EXPECT_EQ(table.size(), 2u);
  EXPECT_EQ(table.lights(), 2u);
  EXPECT_EQ(table[1][0].front().part, 1u);
  EXPECT_THROW(LitTable({{{}, {}}, {{}}}), std::invalid_argument);
  EXPECT_THROW(LitTable(1, 2, {true}), std::invalid_argument);
}

TEST(LitTable, AddedFacesAreEmpty) {
  LitTable table(0, 2, {false, true});
  table.add_face();
  table.at(0, 1).push_back({0, triangle(0)});
  table.add_face();
  EXPECT_EQ(table.size(), 2u);
  EXPECT_EQ(table[0][1].size(), 1u);
  EXPECT_TRUE(std::as_const(table)[1][1].empty());
}

TEST(LitTable, KeepLightsRenumbersAndKeepsWhatIsNotKept) {
  LitTable table(2, 4, {true, false, true, true});
  for (std::size_t f = 0; f < 2; ++f) {
    const double x = f == 0 ? 0.0 : 10.0;
    table.at(f, 0).push_back({0, triangle(x)});
    table.at(f, 3).push_back({0, triangle(x + 3)});
  }
  table.keep_lights({false, true, false, true});
  EXPECT_EQ(table.lights(), 2u);
  EXPECT_FALSE(table.kept(0));  // old light 1
  EXPECT_TRUE(table.kept(1));   // old light 3
  EXPECT_EQ(table[1][1].front().polygon.outer[0].x, 13.0);
  EXPECT_THROW(table.keep_lights({true}), std::invalid_argument);
}

}  // namespace
}  // namespace shadowgen
