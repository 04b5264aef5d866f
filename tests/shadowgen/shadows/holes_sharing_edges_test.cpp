// Faces whose holes share edges with their outer loop or with each other, end to end: the
// scene reader makes their region (outer loop less holes) their parts; the lit areas of
// the walls so read agree with the exact oracle on the walls as written (the oracle takes
// the holes as they are, independently of the face builder and the clipper), and with the
// same regions written as plain polygons without holes.

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

#include "shadowgen/output/report.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/shadows/shadow_check.h"
#include "tests/shadowgen/shadows/shadow_scenes.h"

namespace shadowgen::test {
namespace {

constexpr double kTolerance = 1e-9;

// Lit area by (face id, light id).
std::map<std::pair<std::string, std::string>, double> lit_areas(const ShadowedScene& shadowed) {
  std::map<std::pair<std::string, std::string>, double> out;
  for (const ReportRow& row : report_rows(shadowed)) {
    out[{shadowed.scene().faces[row.face].id, shadowed.scene().lights[row.light].id}] =
        row.lit_area;
  }
  return out;
}

TEST(HolesSharingEdges, LitAreasAgreeWithTheOracleOnTheWallsAsWritten) {
  const Scene written = walls_sharing_edges_as_written();
  const Scene read = as_read(written);
  ASSERT_EQ(read.faces[1].parts.size(), 1u);  // the front wall: one piece
  ASSERT_EQ(read.faces[2].parts.size(), 2u);  // the back wall: below and above its window
  const GenerateResult result = generate_shadows(read);
  const OracleCheck check = check_against_oracle(written, result.shadowed, kTolerance);
  EXPECT_EQ(check.failures, 0u) << check.report;
  EXPECT_EQ(check.invalid, 0u) << check.invalid_report;
  EXPECT_EQ(check.pairs, 10u) << summary(check);
  const auto lit = lit_areas(result.shadowed);
  // Light through the front wall's openings reaches the back wall: neither all nor nothing.
  EXPECT_GT(lit.at({"back", "sun"}), 0.0);
  EXPECT_LT(lit.at({"back", "sun"}), 12.0);
}

// The front wall of walls_sharing_edges_as_written with its door alone, and the back
// wall, each as holes and as plain polygons drawn around the openings.
Scene door_and_ribbon(bool as_holes) {
  Scene scene = walls_sharing_edges_as_written();
  scene.faces.resize(1);  // the ground
  if (as_holes) {
    add_face(scene, "front",
             polygon({{0, 0, 0}, {10, 0, 0}, {10, 0, 3}, {0, 0, 3}},
                     {{{4, 0, 0}, {5, 0, 0}, {5, 0, 2}, {4, 0, 2}}}));
    add_face(scene, "back",
             polygon({{0, 1.5, 0}, {10, 1.5, 0}, {10, 1.5, 3}, {0, 1.5, 3}},
                     {{{0, 1.5, 1}, {10, 1.5, 1}, {10, 1.5, 2}, {0, 1.5, 2}}}));
  } else {
    add_face(scene, "front",
             polygon({{0, 0, 0},
                      {4, 0, 0},
                      {4, 0, 2},
                      {5, 0, 2},
                      {5, 0, 0},
                      {10, 0, 0},
                      {10, 0, 3},
                      {0, 0, 3}}));
    add_face(scene, "back.low", polygon({{0, 1.5, 0}, {10, 1.5, 0}, {10, 1.5, 1}, {0, 1.5, 1}}));
    add_face(scene, "back.high", polygon({{0, 1.5, 2}, {10, 1.5, 2}, {10, 1.5, 3}, {0, 1.5, 3}}));
  }
  const Scene written = walls_sharing_edges_as_written();
  for (std::size_t f = 3; f < written.faces.size(); ++f) scene.faces.push_back(written.faces[f]);
  return as_read(scene);
}

TEST(HolesSharingEdges, LitAreasAreThoseOfTheSameRegionsWrittenWithoutHoles) {
  const auto holes = lit_areas(generate_shadows(door_and_ribbon(true)).shadowed);
  const auto plain = lit_areas(generate_shadows(door_and_ribbon(false)).shadowed);
  for (const std::string light : {"sun", "lamp"}) {
    EXPECT_NEAR(holes.at({"front", light}), plain.at({"front", light}), kTolerance * 28.0) << light;
    EXPECT_NEAR(holes.at({"back", light}),
                plain.at({"back.low", light}) + plain.at({"back.high", light}), kTolerance * 20.0)
        << light;
    EXPECT_GT(holes.at({"front", light}), 0.0) << light;
  }
}

}  // namespace
}  // namespace shadowgen::test
