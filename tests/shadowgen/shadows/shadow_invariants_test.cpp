// Invariants of shadow generation on every test scene: area is conserved (lit + shadowed
// = area, with lit inside the face and pieces disjoint), nothing is lost (every face id in
// the report and the database), and the answer does not depend on the order of faces or
// lights, on a rigid motion or on a uniform scale. And the database round trip: the
// report from a written and re-read database is the report from generation, byte for
// byte.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "shadowgen/output/database.h"
#include "shadowgen/output/report.h"
#include "shadowgen/scene/database_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/shadows/shadow_check.h"
#include "tests/shadowgen/shadows/shadow_oracle.h"
#include "tests/shadowgen/shadows/shadow_scenes.h"

namespace shadowgen::test {
namespace {

constexpr double kTolerance = 1e-9;

class Invariants : public ::testing::TestWithParam<NamedScene> {};

TEST_P(Invariants, LitPlusShadowedIsTheFaceArea) {
  // The shadowed region is face − ours, measured exactly by the oracle; with the
  // report's lit area it must make up the face: so our pieces lie in the face and do not
  // overlap.
  const Scene& scene = GetParam().scene;
  const GenerateResult result = generate_shadows(scene);
  const ShadowOracle oracle(scene);
  for (const ReportRow& row : report_rows(result.shadowed)) {
    const std::string where = scene.faces[row.face].id + " / " + scene.lights[row.light].id;
    EXPECT_GE(row.lit_area, 0.0) << where;
    EXPECT_LE(row.lit_area, row.area * (1.0 + kTolerance)) << where;
    if (row.area == 0.0) continue;
    const LitComparison c = oracle.compare(row.face, row.light,
                                           polygons_of(result.shadowed.lit()[row.face][row.light]));
    ASSERT_EQ(c.problem, "") << where;
    const double shadowed = c.face_area - (c.our_union_area - c.outside_face_area);
    EXPECT_LE(c.outside_face_area, kTolerance * c.face_area) << where << ": lit outside the face";
    EXPECT_LE(c.our_pieces_area - c.our_union_area, kTolerance * c.face_area)
        << where << ": lit pieces overlap";
    EXPECT_NEAR(row.lit_area + shadowed, row.area, kTolerance * row.area) << where;
  }
}

TEST_P(Invariants, EveryFaceIdIsInTheReportAndTheDatabase) {
  const Scene& scene = GetParam().scene;
  const GenerateResult result = generate_shadows(scene);
  ASSERT_EQ(result.shadowed.lit().size(), scene.faces.size());
  const std::vector<ReportRow> rows = report_rows(result.shadowed);
  ASSERT_EQ(rows.size(), scene.faces.size() * scene.lights.size());
  std::set<std::pair<std::size_t, std::size_t>> seen;
  for (const ReportRow& row : rows) seen.insert({row.face, row.light});
  EXPECT_EQ(seen.size(), rows.size());

  const std::string csv = report_csv(result.shadowed);
  std::set<std::string> csv_faces;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "face_id,light_id,area,lit_area,lit_fraction");
  std::size_t count = 0;
  while (std::getline(lines, line)) {
    csv_faces.insert(line.substr(0, line.find(',')));
    ++count;
  }
  EXPECT_EQ(count, rows.size());

  const ShadowedScene read = parse_database(database_json(result.shadowed), "round.json");
  ASSERT_EQ(read.scene().faces.size(), scene.faces.size());
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    EXPECT_TRUE(csv_faces.count(scene.faces[f].id)) << scene.faces[f].id;
    EXPECT_EQ(read.scene().faces[f].id, scene.faces[f].id);
  }
}

TEST_P(Invariants, DatabaseRoundTripGivesTheSameReport) {
  const Scene& scene = GetParam().scene;
  const GenerateResult result = generate_shadows(scene);
  const std::string direct = report_csv(result.shadowed);
  const ShadowedScene read = parse_database(database_json(result.shadowed), "round.json");
  EXPECT_EQ(report_csv(read), direct);
  EXPECT_EQ(report_json(read), report_json(result.shadowed));
  EXPECT_EQ(database_json(read), database_json(result.shadowed));
}

// Lit fractions of `changed` agree with those of `scene` by (face id, light id).
void ExpectSameFractions(const Scene& scene, const Scene& changed, const std::string& what) {
  const auto before = lit_fractions(generate_shadows(scene).shadowed);
  const auto after = lit_fractions(generate_shadows(changed).shadowed);
  ASSERT_EQ(before.size(), after.size());
  double worst = 0.0;
  for (const auto& [key, fraction] : before) {
    const auto it = after.find(key);
    ASSERT_NE(it, after.end()) << key.first << " / " << key.second;
    worst = std::max(worst, std::fabs(it->second - fraction));
    EXPECT_NEAR(it->second, fraction, kTolerance)
        << what << ": " << key.first << " / " << key.second;
  }
  std::printf("[ %-12s ] worst lit fraction change %.3g\n", what.c_str(), worst);
}

TEST_P(Invariants, ShufflingFacesAndLightsChangesNothing) {
  const Scene& scene = GetParam().scene;
  for (std::uint64_t seed : {1u, 2u, 3u})
    ExpectSameFractions(scene, shuffled(scene, seed), "shuffle");
}

TEST_P(Invariants, RigidMotionChangesNothing) {
  const Scene& scene = GetParam().scene;
  const glm::dvec3 axis = glm::dvec3(0.36, -0.48, 0.8);  // unit length
  ExpectSameFractions(scene, moved(scene, rotation(axis, 0.7), {3.25, -1.5, 0.75}), "rigid");
  ExpectSameFractions(scene, moved(scene, rotation({0, 0, 1}, 2.1), {-10.0, 20.0, 5.0}), "rigid_z");
}

TEST_P(Invariants, UniformScaleChangesNothing) {
  const Scene& scene = GetParam().scene;
  ExpectSameFractions(scene, scaled(scene, 3.0), "scale_3");
  ExpectSameFractions(scene, scaled(scene, 0.001), "scale_1em3");
  ExpectSameFractions(scene, scaled(scene, 1024.0), "scale_1024");
}

// Each light's image cut into regions settled apart (hsr/image_regions.h), on 1, 2 or 3
// threads: the database is the same byte for byte whatever the thread count, and the
// lit regions agree with the oracle as the uncut ones do.
TEST_P(Invariants, ImageRegionsOnAnyThreadCountGiveOneDatabase) {
  const Scene& scene = GetParam().scene;
  GenerateOptions options;
  options.image_regions = 6;
  options.threads = 1;
  const GenerateResult one = generate_shadows(scene, options);
  const std::string database = database_json(one.shadowed);
  for (unsigned threads : {2u, 3u}) {
    options.threads = threads;
    EXPECT_EQ(database_json(generate_shadows(scene, options).shadowed), database)
        << threads << " threads";
  }
  const OracleCheck check = check_against_oracle(scene, one.shadowed, kTolerance);
  std::printf("[ 6 regions ] %s\n", summary(check).c_str());
  EXPECT_EQ(check.failures, 0u) << check.report;
}

INSTANTIATE_TEST_SUITE_P(Scenes, Invariants, ::testing::ValuesIn(oracle_scenes()),
                         [](const auto& p) { return p.param.name; });

}  // namespace
}  // namespace shadowgen::test
