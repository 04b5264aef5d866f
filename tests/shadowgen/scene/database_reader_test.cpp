// A shadowed database is checked as strictly as a scene (shadowgen/scene/
// database_reader.h): tampered lit polygons, broken faces, lights and views that a scene
// would refuse, repeated keys. Each is an InputError naming the file, the face where one
// is to blame, and the JSON path.

#include "shadowgen/scene/database_reader.h"

#include <gtest/gtest.h>

#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "clipper/clip.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

// A database with one face, "wall": the unit square in z = 0 with a hole, and one light,
// "sun", whose lit polygons on it are `lit` (the inside of a JSON array).
std::string database(const std::string& lit,
                     const std::string& parts = R"({"outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]],
                                                     "holes": [[[1,1,0],[1,2,0],[2,2,0],[2,1,0]]]})",
                     const std::string& views = "") {
  return R"({"format": "shadowgen-shadowed/1",
    "lights": [{"id": "sun", "type": "directional", "direction": [0.0, 0.0, -1.0],
                "intensity": [1.0, 1.0, 1.0]}],
    "views": [)" +
         views + R"(],
    "faces": [{"id": "wall", "source_file": "scene.json", "parts": [)" +
         parts + R"(], "lit": {"sun": [)" + lit + "]}}]}";
}

std::string square(double x0, double y0, double size, double z = 0.0) {
  auto point = [](double px, double py, double pz) {
    std::ostringstream s;
    s.precision(17);
    s << "[" << px << "," << py << "," << pz << "]";
    return s.str();
  };
  return R"({"outer": [)" + point(x0, y0, z) + "," + point(x0 + size, y0, z) + "," +
         point(x0 + size, y0 + size, z) + "," + point(x0, y0 + size, z) + R"(], "holes": []})";
}

struct Refusal {
  std::string file, face, problem;
};

Refusal refusal(const std::string& text) {
  try {
    (void)parse_database(text, "db.json");
  } catch (const InputError& e) {
    return {e.file(), e.face_id(), e.problem()};
  }
  return {"", "", "(no error)"};
}

// The problem, checked to name db.json and the face.
std::string wall_problem(const std::string& text) {
  const Refusal r = refusal(text);
  EXPECT_EQ(r.file, "db.json") << r.problem;
  EXPECT_EQ(r.face, "wall") << r.problem;
  return r.problem;
}

bool starts_with(const std::string& text, const std::string& start) {
  return text.rfind(start, 0) == 0;
}

TEST(DatabaseReader, GoodLitPolygonsAreRead) {
  const ShadowedScene s =
      parse_database(database(square(0, 0, 1) + "," + square(2.5, 2.5, 1)), "db.json");
  ASSERT_EQ(s.lit()[0][0].size(), 2u);
  // Touching the face's boundary and touching each other is fine.
  EXPECT_NO_THROW(parse_database(
      database(square(0, 0, 1) + "," + square(1, 0, 1) + "," + square(3, 3, 1)), "db.json"));
  // The face lit whole, hole and all.
  EXPECT_NO_THROW(parse_database(database(R"({"outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]],
                                               "holes": [[[1,1,0],[1,2,0],[2,2,0],[2,1,0]]]})"),
                                 "db.json"));
}

TEST(DatabaseReader, LitPolygonsWithoutPartGoOnTheCoplanarPartThatHoldsThem) {
  // A face of two coplanar parts (a square whose hole across it cut it apart), its lit
  // polygons written without "part": each is read on the part that holds it.
  const std::string parts = square(0, 0, 4) + "," + square(0, 6, 4);
  const ShadowedScene s =
      parse_database(database(square(1, 7, 1) + "," + square(1, 1, 2), parts), "db.json");
  ASSERT_EQ(s.lit()[0][0].size(), 2u);
  EXPECT_EQ(s.lit()[0][0][0].part, 1u);
  EXPECT_EQ(s.lit()[0][0][1].part, 0u);
}

TEST(DatabaseReader, LitAreaAboveTheFacesIsAnError) {
  // Three times the face's area (15), and 2500 times.
  const std::string big = R"({"outer": [[-2,-2,0],[7,-2,0],[7,3,0],[-2,3,0]], "holes": []})";
  EXPECT_TRUE(starts_with(wall_problem(database(big)),
                          "faces[0].lit['sun']: the lit polygons cover an area of 45, more than "
                          "the face's area of 15 (a lit fraction of 3)"))
      << wall_problem(database(big));
  EXPECT_NE(wall_problem(database(square(-100, -100, 193.6492))).find("a lit fraction of 2500"),
            std::string::npos);
}

TEST(DatabaseReader, ALitPolygonOffTheFacesPlaneIsAnError) {
  const std::string problem = wall_problem(database(square(0, 0, 1) + "," + square(3, 3, 1, 0.5)));
  EXPECT_TRUE(starts_with(problem,
                          "faces[0].lit['sun'][1]: lies off its face's plane: a vertex "
                          "is 0.5 from it"))
      << problem;
  // A hair off, within rounding, is the generator's rounding and passes.
  EXPECT_NO_THROW(parse_database(database(square(0, 0, 1, 1e-15)), "db.json"));
}

TEST(DatabaseReader, ALitPolygonOutsideTheFaceIsAnError) {
  const std::string outside = wall_problem(database(square(0, 0, 1) + "," + square(5, 5, 1)));
  EXPECT_TRUE(starts_with(outside,
                          "faces[0].lit['sun'][1]: lies outside its face: an area of 1 "
                          "of its 1 is beyond the face's boundary"))
      << outside;
  // Over the face's hole.
  const std::string in_hole = wall_problem(database(square(1.25, 1.25, 0.5)));
  EXPECT_TRUE(starts_with(in_hole, "faces[0].lit['sun'][0]: lies outside its face")) << in_hole;
  // Half across the edge.
  const std::string across = wall_problem(database(square(3.5, 0, 1)));
  EXPECT_TRUE(starts_with(across,
                          "faces[0].lit['sun'][0]: lies outside its face: an area of 0.5 "
                          "of its 1"))
      << across;
}

TEST(DatabaseReader, ARepeatedOrOverlappingLitPolygonIsAnError) {
  const std::string repeated =
      wall_problem(database(square(0, 0, 1) + "," + square(3, 3, 1) + "," + square(0, 0, 1)));
  EXPECT_EQ(repeated, "faces[0].lit['sun'][2]: repeats lit polygon 0 of this light");
  const std::string overlapping = wall_problem(database(square(0, 0, 1) + "," + square(0.5, 0, 1)));
  EXPECT_TRUE(starts_with(overlapping, "faces[0].lit['sun']: the lit polygons overlap"))
      << overlapping;
}

TEST(DatabaseReader, FacePartsGetTheScenesFaceChecks) {
  EXPECT_TRUE(
      starts_with(wall_problem(database("", R"({"outer": [[0,0,0],[1,1,0],[1,0,0],[0,1,0]]})")),
                  "faces[0].parts[0]: the outer loop intersects itself"));
  EXPECT_TRUE(
      starts_with(wall_problem(database("", R"({"outer": [[0,0,0],[1,0,0],[1,1,0.5],[0,1,0]]})")),
                  "faces[0].parts[0]: not planar"));
  EXPECT_TRUE(starts_with(wall_problem(database("", R"({"outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]],
                                    "holes": [[[5,5,0],[6,5,0],[6,6,0]]]})")),
                          "faces[0].parts[0]: hole 0 is not inside the outer loop"));
  // A part without area is kept, as a scene's degenerate face is, and nothing on it is lit.
  const std::string line = R"({"outer": [[0,0,0],[1,1,1],[2,2,2]]})";
  EXPECT_NO_THROW(parse_database(database("", line), "db.json"));
  EXPECT_TRUE(starts_with(wall_problem(database(square(0, 0, 1), line)),
                          "faces[0].lit['sun']: the lit polygons cover an area of 1, more than "
                          "the face's area of 0"));
}

// A model's face is planar within twice its vertex rounding (a CityJSON roof stored to
// the millimetre, one corner a step above the others' plane: 0.25 mm from the best-fit
// plane, far beyond the relative tolerance). Its database keeps the rounding, so the part
// reads back planar, and so does what is lit on it; without it, or with a rounding too
// small for it, it is refused.
TEST(DatabaseReader, AModelFacePlanarWithinItsVertexRoundingReadsBack) {
  const std::string roof = R"({"outer": [[0,0,9],[10,0,9],[10,10,9.001],[0,10,9]]})";
  // Lit whole: the lit polygon is the roof itself, as far off the plane as its corner.
  nlohmann::ordered_json db = nlohmann::ordered_json::parse(database(roof, roof));
  EXPECT_TRUE(starts_with(wall_problem(db.dump()), "faces[0].parts[0]: not planar"));
  db["faces"][0]["vertex_rounding"] = 0.000866;
  const ShadowedScene read = parse_database(db.dump(), "db.json");
  ASSERT_EQ(read.scene().faces.size(), 1u);
  EXPECT_EQ(read.scene().faces[0].vertex_rounding, 0.000866);
  const std::string written = database_json(read);
  EXPECT_NE(written.find("\"vertex_rounding\": 0.000866,"), std::string::npos) << written;
  EXPECT_EQ(database_json(parse_database(written, "again.json")), written);
  db["faces"][0]["vertex_rounding"] = 0.0001;  // twice it is 0.2 mm: not enough
  EXPECT_TRUE(starts_with(wall_problem(db.dump()), "faces[0].parts[0]: not planar"));
  db["faces"][0]["vertex_rounding"] = -1;
  EXPECT_EQ(wall_problem(db.dump()),
            "faces[0].vertex_rounding: a vertex rounding cannot be negative");
}

TEST(DatabaseReader, LightsAndViewsGetTheScenesChecks) {
  std::string zero = database("");
  zero.replace(zero.find("[0.0, 0.0, -1.0]"), 16, "[0, 0, 0]");
  EXPECT_EQ(refusal(zero).problem, "light 'sun': lights[0] ('sun').direction: must not be zero");
  const std::string view = R"({"id": "v", "eye": [1,2,3], "target": [1,2,3], "up": [0,0,1],
                               "fov_deg": 45.0})";
  EXPECT_EQ(refusal(database("", square(0, 0, 4), view)).problem,
            "view 'v': views[0] ('v'): 'eye' and 'target' must differ");
}

TEST(DatabaseReader, AKeyGivenTwiceIsAnError) {
  const std::string twice = database(square(0, 0, 1));
  const std::string text = twice.substr(0, twice.size() - 1) + R"(, "faces": []})";
  EXPECT_EQ(refusal(text).problem,
            "the key 'faces' is given twice (a key may appear once in an object)");
  EXPECT_EQ(refusal(database(R"({"outer": [[0,0,0],[1,0,0],[0,1,0]], "holes": [], "holes": []})"))
                .problem,
            "faces[0] ('wall').lit.sun[0]: the key 'holes' is given twice (a key may appear once "
            "in an object)");
}

TEST(DatabaseReader, UnknownKeysWarnAndAreErrorsWhenStrict) {
  const std::string text =
      database(R"({"outer": [[0,0,0],[1,0,0],[0,1,0]], "hole": [], "part": 0})");
  std::vector<std::string> warnings;
  (void)parse_database(text, "db.json", {}, warnings);
  EXPECT_EQ(warnings, std::vector<std::string>{"db.json: face 'wall': faces[0].lit['sun'][0]: "
                                               "unknown key 'hole' (did you mean 'holes'?)"});
  std::vector<std::string> ignored;
  EXPECT_THROW((void)parse_database(text, "db.json", {.strict = true}, ignored), InputError);
}

// What shadowgen writes reads back, bit for bit, through every check.
TEST(DatabaseReader, WrittenDatabasesReadBack) {
  const std::string text = database(square(0, 0, 1) + "," + square(2.5, 2.5, 1));
  const std::string written = database_json(parse_database(text, "db.json"));
  EXPECT_EQ(database_json(parse_database(written, "again.json")), written);
}

// The scene's site is kept (every key written) and read back, before or after the faces;
// one without its latitude, longitude or offset, or with a key out of range, is refused.
TEST(DatabaseReader, TheSiteIsWrittenAndReadBack) {
  nlohmann::ordered_json db = nlohmann::ordered_json::parse(database(square(0, 0, 1)));
  db["site"] = {{"latitude_deg", 51.5}, {"longitude_deg", -0.1}, {"utc_offset_h", 1}};
  const ShadowedScene read = parse_database(db.dump(), "db.json");
  ASSERT_TRUE(read.scene().site.has_value());
  EXPECT_EQ(read.scene().site->latitude_deg, 51.5);
  EXPECT_EQ(read.scene().site->longitude_deg, -0.1);
  EXPECT_EQ(read.scene().site->utc_offset_h, 1.0);
  EXPECT_EQ(read.scene().site->elevation_m, 0.0);
  EXPECT_EQ(read.scene().site->north_axis_deg, 0.0);
  const std::string written = database_json(read);
  EXPECT_NE(written.find("\"site\": {\"latitude_deg\":51.5,\"longitude_deg\":-0.1,"
                         "\"elevation_m\":0.0,\"utc_offset_h\":1.0,\"north_axis_deg\":0.0},\n"
                         "  \"lights\""),
            std::string::npos)
      << written;
  EXPECT_EQ(database_json(parse_database(written, "again.json")), written);
  // After the faces: read in the second pass.
  nlohmann::ordered_json late = db;
  late.erase("site");
  late["site"] = db["site"];
  late["site"]["north_axis_deg"] = 30;
  EXPECT_EQ(parse_database(late.dump(), "db.json").scene().site->north_axis_deg, 30.0);
  // No site: none written.
  EXPECT_EQ(database_json(parse_database(database(square(0, 0, 1)), "db.json")).find("\"site\""),
            std::string::npos);
  db["site"].erase("utc_offset_h");
  EXPECT_EQ(refusal(db.dump()).problem, "site: missing 'utc_offset_h'");
  db["site"]["utc_offset_h"] = 0;
  db["site"]["north_axis_deg"] = 400;
  EXPECT_EQ(refusal(db.dump()).problem.rfind("site.north_axis_deg: ", 0), 0u)
      << refusal(db.dump()).problem;
}

// The members of a database in any order: as written (the faces last, each read as the
// parser reaches it), the faces first (kept until the rest is read), or a member the faces
// need after them (the streamed faces read too early: the text is read again whole).
// Each reads as written, its warnings given once.
TEST(DatabaseReader, ReadsTheSameWhateverTheOrderOfItsMembers) {
  nlohmann::ordered_json db =
      nlohmann::ordered_json::parse(database_json(test::sun_path_by_hand()));
  db["faces"][0]["colour"] = "red";  // unknown: one warning
  const std::string written = db.dump();
  const auto in_order = [&db](std::vector<std::string> keys) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const std::string& key : keys) out[key] = db[key];
    EXPECT_EQ(out.size(), db.size());
    return out.dump();
  };
  const std::vector<std::string> texts = {
      written, in_order({"faces", "format", "lights", "sun_paths", "views"}),
      in_order({"format", "lights", "views", "faces", "sun_paths"}),
      in_order({"lights", "faces", "views", "sun_paths", "format"})};
  std::vector<std::string> warnings;
  const std::string expected = database_json(parse_database(written, "db.json", {}, warnings));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("faces[0]: unknown key 'colour'"), std::string::npos) << warnings[0];
  for (std::size_t i = 0; i < texts.size(); ++i) {
    std::vector<std::string> again;
    EXPECT_EQ(database_json(parse_database(texts[i], "db.json", {}, again)), expected) << i;
    EXPECT_EQ(again, warnings) << i;
  }
  // A face's error names the face and its path in every order.
  db["faces"][0]["parts"] = nlohmann::ordered_json::array();
  for (const std::vector<std::string>& keys :
       {std::vector<std::string>{"format", "lights", "views", "sun_paths", "faces"},
        std::vector<std::string>{"faces", "format", "lights", "sun_paths", "views"}}) {
    const Refusal r = refusal(in_order(keys));
    EXPECT_EQ(r.problem, "faces[0].parts: a face needs at least one polygon");
    EXPECT_EQ(r.face, "g");
  }
}

// A database read from its file, as it is parsed, reads as its text does: the same
// scene, the same warnings, the same errors with the same lines and columns (a syntax
// error, a NUL byte, a face's problem, members arranged by hand).
TEST(DatabaseReader, AFileReadsAsItsText) {
  const test::TempFolder folder("database_reader");
  nlohmann::ordered_json db =
      nlohmann::ordered_json::parse(database_json(test::sun_path_by_hand()));
  db["faces"][0]["colour"] = "red";
  const std::string written = db.dump(1);
  nlohmann::ordered_json faces_first = nlohmann::ordered_json::object();
  faces_first["faces"] = db["faces"];
  for (const auto& [key, value] : db.items()) faces_first[key] = value;
  std::string with_nul = written;
  with_nul[written.size() / 2] = '\0';
  const std::vector<std::string> texts = {written, faces_first.dump(),
                                          written.substr(0, written.size() - 40), with_nul,
                                          database(square(0, 0, 1) + "," + square(0.5, 0.5, 1))};
  for (std::size_t i = 0; i < texts.size(); ++i) {
    const std::filesystem::path file = folder.write("db" + std::to_string(i) + ".json", texts[i]);
    std::string from_text, from_file;
    std::vector<std::string> text_warnings, file_warnings;
    try {
      from_text = database_json(parse_database(texts[i], file, {}, text_warnings));
    } catch (const InputError& e) {
      from_text = e.what();
    }
    try {
      from_file = database_json(read_database(file, {}, file_warnings));
    } catch (const InputError& e) {
      from_file = e.what();
    }
    EXPECT_EQ(from_file, from_text) << i;
    EXPECT_EQ(file_warnings, text_warnings) << i;
    const std::vector<std::string> expected = {"", "", ": line ", "a NUL byte",
                                               "faces[0].lit['sun'][1]: lies outside its face"};
    EXPECT_NE(from_file.find(expected[i]), std::string::npos) << from_file;
    EXPECT_EQ(file_warnings.size(), i < 2 ? 1u : 0u) << i;
  }
}

// A check whose clip does not settle its snapping is the clipper's error (exit code 3 on
// the command line), naming the file, the face and where in it: the database may be
// right, but cannot be shown to be. The limit is lowered until an ordinary T-junction
// between two lit polygons runs into it.
TEST(DatabaseReader, ACheckWhoseClipDoesNotSettleNamesTheFileAndTheFace) {
  const std::string text = database(square(0, 2.5, 1) + "," + square(1, 3, 1));
  EXPECT_NO_THROW((void)parse_database(text, "db.json"));
  const clipper::SnapRoundLimitForTesting limit(0, 0);
  try {
    (void)parse_database(text, "db.json");
    ADD_FAILURE() << "no error";
  } catch (const clipper::SnapRoundingError& e) {
    EXPECT_TRUE(starts_with(e.what(),
                            "db.json: face 'wall': faces[0].lit['sun']: the lit polygons could "
                            "not be checked: snap rounding of "))
        << e.what();
  }
}

// A sliver triangle lit whole: its one lit polygon is the triangle itself, corner for
// corner, yet its corners seemed 2.2e-5 off the plane of its rounded normal (tolerance
// 1.8e-9) and the database did not read back (a reader fuzzer finding). The plane of a
// sliver is known only to the tilt its normal's rounding allows.
TEST(DatabaseReader, ASliverTriangleLitWholeReadsBack) {
  const std::string triangle = R"({"outer": [[-0.8664763412811685,-2.0078308440393733,0.0],)"
                               R"([0.1956559480312316,-0.24372513135791332,1.0],)"
                               R"([0.1956559480312316,-0.2437251313573806,1.0]], "holes": []})";
  EXPECT_EQ(refusal(database(triangle, triangle)).problem, "(no error)");
  // A vertex a whole unit off the sliver's plane is still refused.
  const std::string off = R"({"outer": [[-0.8664763412811685,-2.0078308440393733,0.0],)"
                          R"([0.1956559480312316,-0.24372513135791332,1.0],)"
                          R"([0.1956559480312316,-1.2437251313573806,1.0]], "holes": []})";
  EXPECT_NE(refusal(database(off, triangle)).problem, "(no error)");
}

// The sun path made by hand, written, changed by `change`, and read back: its problem.
std::string sun_path_problem(const std::function<void(nlohmann::json&)>& change) {
  nlohmann::json db = nlohmann::json::parse(database_json(test::sun_path_by_hand()));
  change(db);
  const Refusal r = refusal(db.dump());
  EXPECT_EQ(r.file, "db.json") << r.problem;
  return r.problem;
}

TEST(DatabaseReaderSunHours, SumsReadBackAsWritten) {
  const std::string text = database_json(test::sun_path_by_hand());
  const ShadowedScene read = parse_database(text, "db.json");
  ASSERT_EQ(read.sun_paths.size(), 1u);
  EXPECT_EQ(read.sun_paths[0].instants, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(read.scene().lights[2].sun->time, "2026-03-21T12:00");
  EXPECT_EQ(database_json(read), text);
}

TEST(DatabaseReaderSunHours, SumsThatDoNotTileTheFaceOrMatchTheLitAreasAreErrors) {
  const auto regions = [](nlohmann::json& db) -> nlohmann::json& {
    return db["faces"][0]["sun_hours"]["p"]["regions"];
  };
  EXPECT_EQ(sun_path_problem([&](nlohmann::json& db) { regions(db).erase(0); }),
            "faces[0].sun_hours.p: the regions cover an area of 3, not the face's 4");
  EXPECT_EQ(sun_path_problem([&](nlohmann::json& db) { regions(db)[1]["hours"] = 1.0; }),
            "faces[0].sun_hours.p: the regions' hours times areas sum to 4, the lit areas' to 5");
  EXPECT_EQ(sun_path_problem([&](nlohmann::json& db) { regions(db)[1]["hours"] = 1.25; }),
            "faces[0].sun_hours.p.regions[1].hours: expected a whole number of the path's "
            "30-minute instants, from 0 to 4");
  EXPECT_EQ(sun_path_problem([&](nlohmann::json& db) { regions(db)[2]["hours"] = 1.5; }),
            "faces[0].sun_hours.p.regions[2].hours: regions must come in increasing hours");
  EXPECT_EQ(sun_path_problem([&](nlohmann::json& db) {
              regions(db)[0]["polygons"].push_back(regions(db)[2]["polygons"][0]);
            }).rfind("faces[0].sun_hours.p: regions: ", 0),
            0u);
  EXPECT_EQ(sun_path_problem(
                [](nlohmann::json& db) { db["faces"][0]["sun_hours"]["p"]["lit_area"].erase(3); }),
            "faces[0].sun_hours.p.lit_area: expected one lit area per instant of the path (4), "
            "found 3");
  EXPECT_EQ(sun_path_problem(
                [](nlohmann::json& db) { db["faces"][0]["sun_hours"]["p"]["lit_area"][0] = 5.0; }),
            "faces[0].sun_hours.p: a lit area of 5, more than the face's area of 4");
  EXPECT_EQ(sun_path_problem([](nlohmann::json& db) { db["faces"][0].erase("sun_hours"); }),
            "faces[0]: missing 'sun_hours'");
  // A path no light names has no instant; the faces' sums are then of a path they lack.
  EXPECT_EQ(sun_path_problem([](nlohmann::json& db) { db["sun_paths"][0]["id"] = "q"; }),
            "faces[0].sun_hours: missing 'q'");
}

// A path whose instant polygons were dropped keeps only its instants' lit areas: a face
// listing lit polygons for one of them is tampered with, not a database to trust.
TEST(DatabaseReaderSunHours, LitPolygonsOfAnInstantWhosePolygonsWereDroppedAreAnError) {
  EXPECT_EQ(sun_path_problem([](nlohmann::json& db) {
              ASSERT_EQ(db["sun_paths"][0]["instant_polygons"], "dropped");
              db["faces"][0]["lit"]["p@2"] = nlohmann::json::parse(
                  R"([{"outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "holes": []}])");
            }),
            "faces[0].lit['p@2']: the light is an instant of sun path 'p', whose instant "
            "polygons are \"dropped\": only its lit areas are kept");
}

// A shard (generate --instants 1/1) of the courtyard over 21 March, its sums in nodes.
std::string court_shard_text() {
  GenerateOptions options;
  options.threads = 1;
  options.shard = ShardPlace{0, 1};
  const Scene scene =
      parse_scene(test::site_scene(test::kCourtyard, test::kMarch21), "court.json").scene;
  return database_json(generate_shadows(scene, options).shadowed);
}

nlohmann::json court_shard() { return nlohmann::json::parse(court_shard_text()); }

// JSON objects are unordered: a sampled method's database with "method" after "faces",
// and a shard with "shard" after them (its faces hold "lit_area" in place of "lit", and
// "nodes" in place of "regions"), read as written, from the text and from the file; so
// does a face's error, which names the face.
TEST(DatabaseReader, AMethodOrAShardAfterTheFacesReadsAsWritten) {
  const test::TempFolder folder("database_reader_order");
  const ShadowedScene by_hand = test::sun_path_by_hand();
  const std::size_t lights = by_hand.scene().lights.size();
  ShadowedScene sampled(
      by_hand.scene(), by_hand.lit(),
      Estimate{{MethodKind::kRays, 64}, std::vector<std::vector<double>>(lights)});
  sampled.sun_paths = by_hand.sun_paths;
  sampled.sun_paths[0].regions_kept = false;
  sampled.sun_paths[0].regions.clear();
  const std::vector<std::string> written = {database_json(sampled), court_shard_text()};
  for (std::size_t i = 0; i < written.size(); ++i) {
    const nlohmann::ordered_json db = nlohmann::ordered_json::parse(written[i]);
    ASSERT_TRUE(db.contains(i == 0 ? "method" : "shard"));
    nlohmann::ordered_json late = nlohmann::ordered_json::object();
    for (const auto& [key, value] : db.items()) {
      if (key != "method" && key != "shard") late[key] = value;
    }
    for (const char* key : {"method", "shard"}) {
      if (db.contains(key)) late[key] = db[key];
    }
    const std::filesystem::path file = folder.write("late.json", late.dump());
    EXPECT_EQ(database_json(parse_database(late.dump(), "db.json")), written[i]) << i;
    EXPECT_EQ(database_json(read_database(file)), written[i]) << i;
    late["faces"][0]["parts"] = nlohmann::ordered_json::array();
    const Refusal r = refusal(late.dump());
    EXPECT_EQ(r.problem, "faces[0].parts: a face needs at least one polygon") << i;
    EXPECT_EQ(r.face, i == 0 ? "g" : "ground") << i;
  }
}

// That shard with the ground's nodes changed by `change`, read back: its problem.
std::string shard_problem(const std::function<void(nlohmann::json& ground_nodes)>& change) {
  nlohmann::json db = court_shard();
  EXPECT_EQ(db["faces"][0]["id"], "ground");
  change(db["faces"][0]["sun_hours"]["day"]["nodes"]);
  const Refusal r = refusal(db.dump());
  EXPECT_EQ(r.file, "db.json") << r.problem;
  EXPECT_EQ(r.face, "ground") << r.problem;
  return r.problem;
}

// The vertex of the first node's pieces at the ground's corner (-10, -10).
nlohmann::json& ground_corner(nlohmann::json& nodes) {
  for (nlohmann::json& count : nodes[0]["parts"][0]["counts"]) {
    for (nlohmann::json& piece : count["pieces"]) {
      for (nlohmann::json& point : piece["outer"]) {
        if (point[0] == -10.0 && point[1] == -10.0) return point;
      }
    }
  }
  throw std::logic_error("no piece has the ground's corner");
}

// A shard's sums are checked as a whole database's regions are, node by node: the pieces
// of all counts tile each part they list, and their counts agree with the lit areas.
TEST(DatabaseReaderSunHours, AShardsNodesMustTileTheFaceAndAgreeWithTheLitAreas) {
  EXPECT_EQ(refusal(court_shard().dump()).problem, "(no error)");
  // A corner moved in leaves a gap.
  const std::string gap =
      shard_problem([](nlohmann::json& nodes) { ground_corner(nodes)[0] = -9.75; });
  EXPECT_TRUE(starts_with(gap,
                          "faces[0].sun_hours.day: nodes[0]: the pieces on part 0 cover "
                          "an area of 399."))
      << gap;
  EXPECT_TRUE(gap.ends_with(", not the part's 400")) << gap;
  // Moved out: beyond the ground.
  const std::string outside =
      shard_problem([](nlohmann::json& nodes) { ground_corner(nodes)[0] = -10.25; });
  EXPECT_TRUE(starts_with(outside, "faces[0].sun_hours.day: nodes[0]: pieces: ")) << outside;
  // A piece given twice overlaps itself.
  const std::string twice = shard_problem([](nlohmann::json& nodes) {
    nlohmann::json& pieces = nodes[0]["parts"][0]["counts"].back()["pieces"];
    pieces.push_back(pieces[0]);
  });
  EXPECT_TRUE(starts_with(twice, "faces[0].sun_hours.day: nodes[0]: pieces: ")) << twice;
  // The same tiling with a piece counted once more no longer sums to the lit areas.
  const std::string counted = shard_problem([](nlohmann::json& nodes) {
    nlohmann::json& counts = nodes[0]["parts"][0]["counts"];
    ASSERT_GE(counts.size(), 2u);
    nlohmann::json& from = counts[counts.size() - 2]["pieces"];
    counts.back()["pieces"].push_back(from.back());
    from.erase(from.size() - 1);
  });
  EXPECT_TRUE(starts_with(counted,
                          "faces[0].sun_hours.day: nodes[0]: the counts times areas "
                          "sum to "))
      << counted;
  const std::string too_many = shard_problem(
      [](nlohmann::json& nodes) { nodes[0]["parts"][0]["counts"].back()["count"] = 25; });
  EXPECT_EQ(too_many, "faces[0].sun_hours.day: nodes[0]: a count of 25 instants in a node of 24");
}

TEST(DatabaseReaderSunHours, APathsSpanMustBeTimesInOrderHoldingItsInstants) {
  EXPECT_EQ(
      sun_path_problem([](nlohmann::json& db) { db["sun_paths"][0]["from"] = "noon"; }),
      "sun path 'p': sun_paths[0] ('p').from: expected a local time YYYY-MM-DDTHH:MM (seconds "
      "optional)");
  EXPECT_EQ(
      sun_path_problem([](nlohmann::json& db) { db["sun_paths"][0]["to"] = "2026-03-21T09:00"; }),
      "sun path 'p': sun_paths[0] ('p').to: must not be before 'from'");
  EXPECT_EQ(
      sun_path_problem([](nlohmann::json& db) { db["sun_paths"][0]["to"] = "2026-03-21T12:30"; }),
      "sun path 'p': sun_paths[0] ('p').to: light 'p@3' of this path is at 2026-03-21T13:00, "
      "outside its span from 2026-03-21T10:00 to 2026-03-21T12:30");
}

// A path's instants are its lights in the file's order: each on one of the path's steps
// from "from", after the one before it (the shading schedule puts each lit area on the
// step of its instant's time, the sun hours count one step per instant).
TEST(DatabaseReaderSunHours, APathsInstantsComeInTimeOrderOnItsSteps) {
  const auto at = [](int light, const char* time) {
    return [light, time](nlohmann::json& db) { db["lights"][light]["sun"]["time"] = time; };
  };
  EXPECT_EQ(sun_path_problem(at(2, "2026-03-21T11:00")),
            "sun path 'p': sun_paths[0] ('p'): light 'p@2' of this path is at 2026-03-21T11:00, "
            "the time of light 'p@1' before it (2026-03-21T11:00): a path's instants come in "
            "time order, one per step");
  EXPECT_EQ(sun_path_problem(at(1, "2026-03-21T12:30")),
            "sun path 'p': sun_paths[0] ('p'): light 'p@2' of this path is at 2026-03-21T12:00, "
            "before the time of light 'p@1' before it (2026-03-21T12:30): a path's instants "
            "come in time order, one per step");
  EXPECT_EQ(sun_path_problem(at(1, "2026-03-21T11:10")),
            "sun path 'p': sun_paths[0] ('p').step_min: light 'p@1' of this path is at "
            "2026-03-21T11:10, not on one of its 30-minute steps from 2026-03-21T10:00");
  EXPECT_EQ(sun_path_problem(at(0, "noon")),
            "sun path 'p': sun_paths[0] ('p'): light 'p@0' of this path is at 'noon', not a "
            "local time YYYY-MM-DDTHH:MM (seconds optional)");
}

// A path with the sun below the horizon at every step (21 December at Tromsø, 69.65° N) is
// a path all the same: no instant, every face's one region of 0 hours, read back as
// written.
TEST(DatabaseReaderSunHours, APathWithoutAnInstantReadsBackAsWritten) {
  const std::string scene =
      R"({"format": "shadowgen-scene/1",
          "polygons": [{"id": "g", "outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]]}],
          "site": {"latitude_deg": 69.65, "longitude_deg": 18.96, "utc_offset_h": 1},
          "lights": [{"id": "dec21", "type": "sun", "from": "2026-12-21T00:00",
                      "to": "2026-12-21T23:00", "step_min": 60}]})";
  const std::string text = database_json(test::generated(scene));
  const ShadowedScene read = parse_database(text, "db.json");
  ASSERT_EQ(read.sun_paths.size(), 1u);
  const SunPathHours& night = read.sun_paths[0];
  EXPECT_EQ(night.id, "dec21");
  EXPECT_EQ(night.from, "2026-12-21T00:00");
  EXPECT_EQ(night.to, "2026-12-21T23:00");
  EXPECT_TRUE(night.instants.empty());
  EXPECT_TRUE(read.scene().lights.empty());
  ASSERT_EQ(night.regions.size(), 1u);
  ASSERT_EQ(night.regions[0].size(), 1u);
  EXPECT_EQ(night.regions[0][0].hours, 0.0);
  EXPECT_EQ(lit_area(night.regions[0][0].polygons), 16.0);
  EXPECT_EQ(database_json(read), text);
}

// The dart of kDartUnderRoof, a face of two parts, over a morning: each part's lit areas.
TEST(DatabaseReaderSunHours, APartsLitAreasMustFitThePartAndSumToTheFaces) {
  std::string scene = test::kDartUnderRoof;
  const std::string light = R"({"id": "sun", "type": "directional", "direction": [0,0,-1]})";
  scene.replace(scene.find(light), light.size(),
                R"({"id": "am", "type": "sun", "from": "2026-03-21T09:00",
                    "to": "2026-03-21T11:00", "step_min": 60})");
  scene.replace(scene.find(R"("lights")"), 0,
                R"("site": {"latitude_deg": 51.5, "longitude_deg": 0, "utc_offset_h": 0}, )");
  const std::string text = database_json(test::generated(scene));
  EXPECT_EQ(database_json(parse_database(text, "db.json")), text);
  const auto problem = [&](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json db = nlohmann::json::parse(text);
    change(db);
    return refusal(db.dump()).problem;
  };
  const auto parts = [](nlohmann::json& db) -> nlohmann::json& {
    return db["faces"][0]["sun_hours"]["am"]["part_lit_area"];
  };
  EXPECT_EQ(problem([&](nlohmann::json& db) { parts(db)[1][0] = 4.0; }),
            "faces[0].sun_hours.am: part 1's lit area of 4 at instant 0, more than the part's "
            "area of 3.7416573867739413");
  EXPECT_EQ(problem([&](nlohmann::json& db) {
              parts(db)[1][0] = 0.0;
            }).rfind("faces[0].sun_hours.am: the parts' lit areas at instant 0 sum to ", 0),
            0u);
  EXPECT_EQ(problem([&](nlohmann::json& db) { parts(db).erase(1); }),
            "faces[0].sun_hours.am.part_lit_area: expected one list of lit areas per part of the "
            "face (2), found 1");
  EXPECT_EQ(problem([&](nlohmann::json& db) {
              db["faces"][0]["sun_hours"]["am"].erase("part_lit_area");
            }),
            "faces[0].sun_hours.am: missing 'part_lit_area'");
}

}  // namespace
}  // namespace shadowgen
