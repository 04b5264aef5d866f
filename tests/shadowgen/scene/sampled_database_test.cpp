// A database made by a sampled method (docs/scene-format.md, "Methods"): it names its method
// and holds lit areas, not lit polygons; it reads back as written, and a tampered one is
// refused naming the file, the face and the JSON path.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/output/report.h"
#include "shadowgen/scene/database_reader.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

// Face "g" (4 × 1) and face "h" (2 × 1) under lights "sun" and "lamp", and path "p" of
// four instants (hand_scenes.h), as a rays run of 64 samples (or `method`) would leave them.
ShadowedScene sampled_by_hand(const Method& method = {MethodKind::kRays, 64}) {
  const ShadowedScene by_hand = test::sun_path_by_hand();
  Scene scene = by_hand.scene();
  scene.faces.push_back({"h", {test::unit_strip(5, 7)}, "test.json"});
  Light sun, lamp;
  sun.id = "sun";
  lamp.id = "lamp";
  lamp.type = LightType::kPoint;
  lamp.position = {1, 1, 3};
  scene.lights.push_back(sun);
  scene.lights.push_back(lamp);
  ShadowedScene shadowed(std::move(scene), LitTable(2, 6, std::vector<bool>(6, false)),
                         Estimate{method, {{}, {}, {}, {}, {3.25, 2.0}, {0.0, 1.5}}});
  shadowed.sun_paths = by_hand.sun_paths;
  SunPathHours& path = shadowed.sun_paths.front();
  path.lit_area.push_back({2, 2, 0.5, 0});
  path.part_lit_area.push_back({});
  path.regions_kept = false;
  path.regions.clear();
  return shadowed;
}

InputError refusal(const std::string& text) {
  try {
    (void)parse_database(text, "db.json");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "read without an error:\n" << text;
  return InputError("", "", "");
}

// `text` with the first `from` replaced by `to`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(SampledDatabase, ReadsBackAsWritten) {
  const ShadowedScene written = sampled_by_hand();
  const std::string text = database_json(written);
  EXPECT_NE(text.find(R"("method": {"name":"rays","samples":64})"), std::string::npos) << text;
  EXPECT_EQ(text.find(R"("lit":)"), std::string::npos);
  const ShadowedScene read = parse_database(text, "db.json");
  ASSERT_TRUE(read.estimate());
  EXPECT_EQ(read.estimate()->method, written.estimate()->method);
  EXPECT_EQ(read.estimate()->lit_area, written.estimate()->lit_area);
  EXPECT_EQ(read.sun_paths.front().lit_area, written.sun_paths.front().lit_area);
  EXPECT_EQ(database_json(read), text);
  const LitAreas areas(read);
  EXPECT_EQ(areas(0, 4), 3.25);
  EXPECT_EQ(areas(1, 5), 1.5);
  EXPECT_EQ(areas(1, 2), 0.5);  // instant p@2, from the path
}

TEST(SampledDatabase, ShadowMapNamesItsResolution) {
  const Method shadow_map{MethodKind::kShadowMap, 16, 512};
  const ShadowedScene shadowed = sampled_by_hand(shadow_map);
  const std::string text = database_json(shadowed);
  EXPECT_NE(text.find(R"({"name":"shadow-map","samples":16,"resolution":512})"), std::string::npos);
  const ShadowedScene read = parse_database(text, "db.json");
  ASSERT_TRUE(read.estimate());
  EXPECT_EQ(read.estimate()->method, shadow_map);
}

TEST(SampledDatabase, ReportsNameTheMethod) {
  const ShadowedScene shadowed = sampled_by_hand();
  EXPECT_NE(report_json(shadowed).find(R"("method": {"name":"rays","samples":64})"),
            std::string::npos);
  EXPECT_EQ(report_table(shadowed, 0)
                .rfind("lit areas estimated by the rays method, 64 samples "
                       "per face\n",
                       0),
            0u);
  EXPECT_NE(report_csv(shadowed, CsvIds::kExact).find("h,lamp,2,1.5,0.75"), std::string::npos);
}

TEST(SampledDatabase, RefusesTamperedAreas) {
  const std::string text = database_json(sampled_by_hand());
  const InputError above = refusal(edited(text, R"({"sun":2.0)", R"({"sun":2.5)"));
  EXPECT_EQ(above.face_id(), "h");
  EXPECT_NE(above.problem().find("faces[1].lit_area['sun']"), std::string::npos) << above.what();
  EXPECT_NE(above.problem().find("not between 0 and the face's area of 2"), std::string::npos)
      << above.what();
  EXPECT_NE(
      refusal(edited(text, R"("lamp":0.0)", R"("lamp":-1e-300)")).problem().find("not between"),
      std::string::npos);
  const InputError missing = refusal(edited(text, R"(,"lamp":1.5)", ""));
  EXPECT_NE(missing.problem().find("no lit area for light 'lamp'"), std::string::npos)
      << missing.what();
  EXPECT_NE(refusal(edited(text, R"("lamp":0.0)", R"("lamp":0,"moon":0)"))
                .problem()
                .find("no light has this id"),
            std::string::npos);
  EXPECT_NE(refusal(edited(text, R"("lamp":0.0)", R"("lamp":0,"p@1":0)"))
                .problem()
                .find("an instant of sun path 'p'"),
            std::string::npos);
}

TEST(SampledDatabase, RefusesLitPolygonsAndRegions) {
  const std::string text = database_json(sampled_by_hand());
  const InputError polygons =
      refusal(edited(text, R"("lit_area": {)", R"("lit": {}, "lit_area": {)"));
  EXPECT_NE(polygons.problem().find("made by the rays method holds lit areas"), std::string::npos)
      << polygons.what();
  const InputError unknown =
      refusal(edited(text, R"({"name":"rays")", R"({"name":"shadow-volumes")"));
  EXPECT_NE(unknown.problem().find("unknown method 'shadow-volumes'"), std::string::npos);
  EXPECT_NE(refusal(edited(text, R"("samples":64)", R"("samples":0)"))
                .problem()
                .find("sample points per face from 1"),
            std::string::npos);
  const InputError map = refusal(edited(text, R"({"name":"rays")", R"({"name":"shadow-map")"));
  EXPECT_NE(map.problem().find("resolution"), std::string::npos) << map.what();
}

TEST(SampledDatabase, AnExactDatabaseIsWrittenAsBefore) {
  ShadowedScene exact = test::sun_path_by_hand();
  const std::string text = database_json(exact);
  EXPECT_EQ(text.find("method"), std::string::npos);
  EXPECT_EQ(text.find("lit_area\": {"), std::string::npos);
  EXPECT_TRUE(parse_database(text, "db.json").is_exact());
}

}  // namespace
}  // namespace shadowgen
