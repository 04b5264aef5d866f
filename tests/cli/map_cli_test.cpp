// End-to-end tests of `shadowgen render` as a map: pieces of one colour drawn as one path
// (their areas those of the database, before and after merging), no seams where colours
// meet (the SVG drawn by rsvg-convert), a north arrow and a scale bar, a legend of light
// sets, outlines, and the sun-hours map as PNG.
//
// The scene: a yard 24 × 24 with a hole where a flat-roofed block 8 × 8 × 6 stands, so
// that a top view sees every horizontal face whole (the walls edge-on), and its pixel areas
// are the faces' areas times the scale squared.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

std::string yard_scene(const std::string& lights, double north_axis_deg) {
  return R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    { "id": "yard", "outer": [[-12,-12,0],[12,-12,0],[12,12,0],[-12,12,0]],
      "holes": [[[-2,-2,0],[-2,6,0],[6,6,0],[6,-2,0]]] },
    { "id": "roof", "outer": [[-2,-2,6],[6,-2,6],[6,6,6],[-2,6,6]] },
    { "id": "south", "outer": [[-2,-2,0],[6,-2,0],[6,-2,6],[-2,-2,6]] },
    { "id": "east", "outer": [[6,-2,0],[6,6,0],[6,6,6],[6,-2,6]] },
    { "id": "north", "outer": [[6,6,0],[-2,6,0],[-2,6,6],[6,6,6]] },
    { "id": "west", "outer": [[-2,6,0],[-2,-2,0],[-2,-2,6],[-2,6,6]] },
    { "id": "fence", "outer": [[-10,4,0],[-10,10,0],[-10,10,2],[-10,4,2]] }
  ],
  "site": { "latitude_deg": 51.48, "longitude_deg": 0, "utc_offset_h": 0,
            "north_axis_deg": )" +
         std::to_string(north_axis_deg) + R"( },
  "lights": [)" +
         lights +
         R"(],
  "views": [ { "id": "main", "eye": [30, -30, 25], "target": [0, 0, 0], "up": [0, 0, 1] } ]
})";
}

const std::string kDay =
    R"({ "id": "day", "type": "sun", "from": "2026-03-21T08:00", "to": "2026-03-21T16:00",
         "step_min": 120 })";
const std::string kSun = R"({ "id": "sun", "type": "directional", "direction": [-0.3, 0.5, -1] })";

// The fill paths of a picture: their data, fill and what they say (data-lights or
// data-band), from the paths one per colour or one per piece (--pieces).
struct FillPath {
  std::string d, fill, label;
};
std::vector<FillPath> fill_paths(const std::string& svg, const std::string& attribute) {
  std::vector<FillPath> paths;
  const std::regex path(R"re(<path d="([^"]*)" fill="(#[0-9a-f]{6})"[^>]*? )re" + attribute +
                        R"re(="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator();
       ++it) {
    paths.push_back({(*it)[1], (*it)[2], (*it)[3]});
  }
  return paths;
}

// Area by label (light set or band), in scene units: pixels over the scale squared.
std::map<std::string, double> areas_by_label(const std::vector<FillPath>& paths, double scale) {
  std::map<std::string, double> areas;
  for (const FillPath& path : paths) areas[path.label] += svg_paths_area(path.d) / (scale * scale);
  return areas;
}

void ExpectAreasNear(const std::map<std::string, double>& drawn,
                     const std::map<std::string, double>& database) {
  ASSERT_EQ(drawn.size(), database.size());
  for (const auto& [label, area] : database) {
    ASSERT_EQ(drawn.count(label), 1u) << label;
    EXPECT_LE(relative_error(drawn.at(label), area), 1e-9)
        << label << ": drawn " << drawn.at(label) << ", database " << area;
  }
}

// How far a map's grid (1/1000 pixel, shadowgen/view/detail/path_data.h) may move each
// label's area, from the exact paths (render --full-precision): each vertex moves by at
// most δ = √2 / 2000 pixel, so a loop of n vertices and perimeter P by at most
// δ·P + n·δ²/2; in scene units, over the scale squared.
std::map<std::string, double> grid_bounds_by_label(const std::vector<FillPath>& exact,
                                                   double scale) {
  const double delta = std::sqrt(2.0) / 2000.0;
  std::map<std::string, double> bounds;
  for (const FillPath& path : exact) {
    for (const auto& loop : svg_path_loops(path.d)) {
      double perimeter = 0.0;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const auto& [x0, y0] = loop[i];
        const auto& [x1, y1] = loop[(i + 1) % loop.size()];
        perimeter += std::hypot(x1 - x0, y1 - y0);
      }
      bounds[path.label] +=
          (delta * perimeter + 0.5 * static_cast<double>(loop.size()) * delta * delta) /
          (scale * scale);
    }
  }
  return bounds;
}

// The map's areas on the grid against the database's: within the grid's bound (above) and
// the exact paths' 1e-9.
void ExpectAreasWithin(const std::map<std::string, double>& drawn,
                       const std::map<std::string, double>& database,
                       const std::map<std::string, double>& bounds) {
  ASSERT_EQ(drawn.size(), database.size());
  for (const auto& [label, area] : database) {
    ASSERT_EQ(drawn.count(label), 1u) << label;
    EXPECT_LE(std::abs(drawn.at(label) - area), bounds.at(label) + 1e-9 * area)
        << label << ": drawn " << drawn.at(label) << ", database " << area;
  }
}

// The first match of `pattern`'s group 1 in `text`, or "" where none.
std::string first_match(const std::string& text, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(text, m, std::regex(pattern)) ? std::string(m[1]) : std::string();
}

class MapCli : public CliFolderTest<> {
 protected:
  MapCli() : CliFolderTest("shadowgen-map") {}

  fs::path generate(const std::string& name, const std::string& lights, double north_axis = 0) {
    const fs::path scene = dir_ / (name + ".json");
    write_file(scene, yard_scene(lights, north_axis));
    const fs::path db = dir_ / (name + ".shadowed.json");
    const Outcome generated = run({"generate", scene.string(), "-o", db.string()});
    EXPECT_EQ(generated.code, 0) << generated.err;
    return db;
  }

  // A top view (north up where the north axis is 0) at `scale` pixels per unit.
  std::string top_view(const fs::path& db, const std::vector<std::string>& more,
                       const std::string& scale = "20") {
    const fs::path svg = dir_ / "top.svg";
    std::vector<std::string> args = {"render",   db.string(), "--eye",     "0,0,50",
                                     "--target", "0,0,0",     "--ortho",   "--scale",
                                     scale,      "--svg",     svg.string()};
    args.insert(args.end(), more.begin(), more.end());
    const Outcome rendered = run(args);
    EXPECT_EQ(rendered.code, 0) << rendered.err;
    return contents(svg);
  }
};

// The lit and shadowed areas of the horizontal faces, from the report: one light gives
// two light sets, "sun" (lit) and "shadow".
TEST_F(MapCli, PathsPerColourHoldTheDatabasesAreaOfEachLightSetBeforeAndAfterMerging) {
  const fs::path db = generate("yard", kSun);
  const Outcome report = run({"report", db.string()});
  ASSERT_EQ(report.code, 0) << report.err;
  std::map<std::string, double> database;
  for (const ReportRow& row : parse_report(report.out)) {
    if (row.face != "yard" && row.face != "roof") continue;
    database["sun"] += row.lit_area;
    database["shadow"] += row.area - row.lit_area;
  }
  // Exact coordinates: the database's areas to 1e-9; on the grid, within its bound.
  const std::vector<FillPath> exact = fill_paths(top_view(db, {"--full-precision"}), "data-lights");
  EXPECT_EQ(exact.size(), 2u);  // one path per colour: the horizontal faces are all alike
  ExpectAreasNear(areas_by_label(exact, 20), database);
  const std::string merged = top_view(db, {});
  const std::vector<FillPath> paths = fill_paths(merged, "data-lights");
  EXPECT_EQ(paths.size(), 2u);
  ExpectAreasWithin(areas_by_label(paths, 20), database, grid_bounds_by_label(exact, 20));
  const std::string pieces = top_view(db, {"--pieces"});
  const std::vector<FillPath> piece_paths = fill_paths(pieces, "data-lights");
  EXPECT_GT(piece_paths.size(), paths.size());
  ExpectAreasNear(areas_by_label(piece_paths, 20), database);

  // The legend names the sets drawn, in their colours.
  EXPECT_NE(merged.find("data-legend=\"light-sets\""), std::string::npos);
  for (const FillPath& path : paths) {
    const std::regex entry("fill=\"" + path.fill +
                           "\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n<text x=\"[0-9]+\" "
                           "y=\"[0-9]+\">" +
                           path.label + "</text>");
    EXPECT_TRUE(std::regex_search(merged, entry)) << path.label;
  }
  // Each face is outlined, named by its id.
  for (const char* face : {"yard", "roof"}) {
    EXPECT_NE(merged.find(std::string("data-face=\"") + face + "\"/>"), std::string::npos) << face;
  }
}

// The bands' areas of the horizontal faces, from the sun-hours report's areas at least
// each band's first hour.
TEST_F(MapCli, PathsPerColourHoldTheDatabasesAreaOfEachHourBandBeforeAndAfterMerging) {
  const fs::path db = generate("yard", kDay);
  const Outcome report =
      run({"report", db.string(), "--format", "sun-hours", "--threshold", "2,4,6,8,10"});
  ASSERT_EQ(report.code, 0) << report.err;
  const std::vector<std::string> labels = {"0\u20132 h", "2\u20134 h",  "4\u20136 h",
                                           "6\u20138 h", "8\u201310 h", "\u2265 10 h"};
  std::map<std::string, double> database;
  std::istringstream lines(report.out);
  std::string line;
  std::getline(lines, line);  // the header
  while (std::getline(lines, line)) {
    const std::vector<std::string> f = csv_fields(line);
    ASSERT_EQ(f.size(), 11u) << line;
    if (f[0] != "yard" && f[0] != "roof") continue;
    // area, then the area with at least 2, 4, 6, 8 and 10 h.
    std::vector<double> at_least = {std::stod(f[2])};
    for (std::size_t i = 6; i < 11; ++i) at_least.push_back(std::stod(f[i]));
    at_least.push_back(0.0);
    for (std::size_t b = 0; b < labels.size(); ++b) {
      if (at_least[b] - at_least[b + 1] > 0.0) database[labels[b]] += at_least[b] - at_least[b + 1];
    }
  }
  const std::vector<FillPath> exact =
      fill_paths(top_view(db, {"--sun-hours", "day", "--full-precision"}), "data-band");
  ExpectAreasNear(areas_by_label(exact, 20), database);
  const std::string merged = top_view(db, {"--sun-hours", "day"});
  const std::vector<FillPath> paths = fill_paths(merged, "data-band");
  ExpectAreasWithin(areas_by_label(paths, 20), database, grid_bounds_by_label(exact, 20));
  std::set<std::string> fills;
  for (const FillPath& path : paths) EXPECT_TRUE(fills.insert(path.fill).second) << path.fill;

  const std::string pieces = top_view(db, {"--sun-hours", "day", "--pieces"});
  std::map<std::string, double> by_piece;
  const std::regex piece(R"re(<path d="([^"]*)" fill="(#[0-9a-f]{6})"[^>]*data-hours="([^"]*)")re");
  std::size_t count = 0;
  for (auto it = std::sregex_iterator(pieces.begin(), pieces.end(), piece);
       it != std::sregex_iterator(); ++it, ++count) {
    const double hours = std::stod((*it)[3]);
    const std::size_t band = std::min<std::size_t>(5, static_cast<std::size_t>(hours / 2.0));
    by_piece[labels[band]] += svg_paths_area((*it)[1]) / 400.0;
  }
  EXPECT_GT(count, paths.size());
  ExpectAreasNear(by_piece, database);
}

// North: the scene's +y is north_axis_deg clockwise from true north, so true north is
// (−sin a, cos a, 0). Looking down with +y up, it shows at −a; with +x up, the picture's
// right is −y, and north shows at atan2(n·(−y), n·x).
TEST_F(MapCli, TheNorthArrowPointsToTrueNorthAsTheSitesNorthAxisAndTheViewTurnIt) {
  struct Case {
    double north_axis;
    std::string up;  // empty: the default (+y up)
    std::string angle;
  };
  for (const Case& c :
       {Case{0, "", "0"}, Case{30, "", "330"}, Case{0, "1,0,0", "270"}, Case{30, "1,0,0", "240"}}) {
    const fs::path db = generate("north", kSun, c.north_axis);
    std::vector<std::string> more;
    if (!c.up.empty()) more = {"--up", c.up};
    const std::string svg = top_view(db, more);
    const std::string angle = first_match(svg, R"re(data-north-arrow="([^"]*)")re");
    ASSERT_FALSE(angle.empty()) << c.north_axis << " " << c.up;
    EXPECT_NEAR(std::stod(angle), std::stod(c.angle), 1e-9) << c.north_axis << " " << c.up;
    EXPECT_NE(svg.find("transform=\"rotate(" + angle + " "), std::string::npos);
  }
  // A database without a site has no north to show.
  const fs::path plain = dir_ / "plain.json";
  write_file(plain, R"({"format": "shadowgen-scene/1",
    "polygons": [{"id": "floor", "outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]]}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]})");
  ASSERT_EQ(run({"generate", plain.string(), "-o", (dir_ / "plain.db.json").string()}).code, 0);
  const std::string svg = top_view(dir_ / "plain.db.json", {});
  EXPECT_EQ(svg.find("data-north-arrow"), std::string::npos);
  // Nor a picture in which north lies along the line of sight.
  const fs::path db = generate("along", kSun);
  const fs::path along = dir_ / "along.svg";
  ASSERT_EQ(run({"render", db.string(), "--eye", "0,-40,0.0", "--target", "0,0,0.0", "--ortho",
                 "--svg", along.string()})
                .code,
            0);
  EXPECT_EQ(contents(along).find("data-north-arrow"), std::string::npos);
}

// The longest round length whose bar is at most a quarter of the 800-pixel picture.
TEST_F(MapCli, TheScaleBarIsARoundLengthAtTheViewsScale) {
  const fs::path db = generate("scale", kSun);
  for (const auto& [scale, length, pixels] :
       std::vector<std::tuple<std::string, std::string, std::string>>{{"20", "10", "200"},
                                                                      {"7", "20", "140"},
                                                                      {"0.5", "200", "100"},
                                                                      {"1300", "0.1", "130"}}) {
    const std::string svg = top_view(db, {}, scale);
    EXPECT_NE(svg.find("<g data-scale-bar=\"" + length + "\" data-pixels=\"" + pixels + "\">"),
              std::string::npos)
        << scale;
    EXPECT_NE(svg.find("width=\"" + pixels + "\" height=\"6\""), std::string::npos) << scale;
    EXPECT_NE(svg.find(">" + length + " m</text>"), std::string::npos) << scale;  // a site: metres
  }
  // A perspective picture has no one scale.
  const fs::path svg = dir_ / "main.svg";
  ASSERT_EQ(run({"render", db.string(), "--view", "main", "--svg", svg.string()}).code, 0);
  EXPECT_EQ(contents(svg).find("data-scale-bar"), std::string::npos);
}

// Whether (x, y) lies inside the loops (even-odd), and its distance to their edges.
struct Inside {
  bool inside = false;
  double distance = INFINITY;
};
Inside inside_loops(const std::vector<std::vector<std::pair<double, double>>>& loops, double x,
                    double y) {
  Inside result;
  for (const auto& loop : loops) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const auto [x0, y0] = loop[i];
      const auto [x1, y1] = loop[(i + 1) % loop.size()];
      if ((y0 <= y) != (y1 <= y) && x < x0 + (y - y0) / (y1 - y0) * (x1 - x0)) {
        result.inside = !result.inside;
      }
      const double dx = x1 - x0, dy = y1 - y0;
      const double t = std::clamp(((x - x0) * dx + (y - y0) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      result.distance = std::min(result.distance, std::hypot(x - x0 - t * dx, y - y0 - t * dy));
    }
  }
  return result;
}

std::string hex_at(const Png& png, int x, int y) {
  const unsigned char* p = png.rgb.data() + 3 * (static_cast<std::size_t>(y) * png.width + x);
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", p[0], p[1], p[2]);
  return text;
}

// Every pixel whose centre lies inside a path, a pixel or more from its edges, has that
// path's colour in the PNG; the PNG is the picture's size (no legend).
TEST_F(MapCli, TheSunHoursPngHasTheSvgsColoursAtPixelCentres) {
  const fs::path db = generate("yard", kDay);
  const fs::path svg = dir_ / "map.svg";
  const fs::path png = dir_ / "map.png";
  const Outcome rendered =
      run({"render", db.string(), "--view", "main", "--sun-hours", "day", "--svg", svg.string(),
           "--png", png.string(), "--width", "400", "--height", "300"});
  ASSERT_EQ(rendered.code, 0) << rendered.err;
  const Png pixels = read_png(png);
  ASSERT_TRUE(pixels.ok);
  EXPECT_EQ(pixels.width, 400);
  EXPECT_EQ(pixels.height, 300);
  const std::vector<FillPath> paths = fill_paths(contents(svg), "data-band");
  ASSERT_GE(paths.size(), 3u);
  std::vector<std::vector<std::vector<std::pair<double, double>>>> loops;
  for (const FillPath& path : paths) loops.push_back(svg_path_loops(path.d));
  std::map<std::string, int> checked;
  int background = 0;
  for (int y = 0; y < pixels.height; ++y) {
    for (int x = 0; x < pixels.width; ++x) {
      int holder = -1;
      bool near_an_edge = false;
      for (std::size_t p = 0; p < paths.size(); ++p) {
        const Inside in = inside_loops(loops[p], x + 0.5, y + 0.5);
        near_an_edge = near_an_edge || in.distance < 1.0;
        if (in.inside) holder = static_cast<int>(p);
      }
      if (near_an_edge) continue;
      if (holder < 0) {
        EXPECT_EQ(hex_at(pixels, x, y), "#ffffff") << x << "," << y;
        ++background;
        continue;
      }
      ASSERT_EQ(hex_at(pixels, x, y), paths[holder].fill) << x << "," << y;
      ++checked[paths[holder].fill];
    }
  }
  EXPECT_EQ(checked.size(), paths.size());  // every colour met
  EXPECT_GT(background, 0);
}

// The share of white in `q` were it a mix of the colours `around` (one or two) and white:
// g in q = a + s·(b − a) + g·(white − a), least squares over the three channels.
double white_share(const std::vector<std::array<double, 3>>& around, const unsigned char* q) {
  const std::array<double, 3>& a = around[0];
  const std::array<double, 3>& b = around.size() > 1 ? around[1] : around[0];
  std::array<double, 3> u{}, w{}, r{};
  for (int c = 0; c < 3; ++c) {
    u[c] = b[c] - a[c];
    w[c] = 255.0 - a[c];
    r[c] = q[c] - a[c];
  }
  const auto dot = [](const std::array<double, 3>& x, const std::array<double, 3>& y) {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  };
  const double uu = dot(u, u), uw = dot(u, w), ww = dot(w, w), ur = dot(u, r), wr = dot(w, r);
  if (uu == 0.0) return wr / ww;
  const double det = uu * ww - uw * uw;
  return det == 0.0 ? 0.0 : (uu * wr - uw * ur) / det;
}

// Drawn by rsvg-convert, no pixel well inside the map (two pixels or more inside the union
// of the fills, away from the north arrow) lets the white background through where two
// colours meet: read as a mix of the one or two colours around it (shadowgen's own
// pixels of the fills say which) and white, it holds no more than 1 % of white (the
// outlines only darken).
TEST_F(MapCli, NoSeamsWhereColoursMeet) {
  const fs::path db = generate("yard", kDay);
  const fs::path svg = dir_ / "map.svg";
  const fs::path png = dir_ / "map.png";
  const fs::path ours = dir_ / "ours.png";
  ASSERT_EQ(run({"render", db.string(), "--view", "main", "--sun-hours", "day", "--svg",
                 svg.string(), "--png", ours.string()})
                .code,
            0);
  ASSERT_EQ(shell("rsvg-convert " + quoted(svg.string()) + " -o " + quoted(png.string())), 0);
  const Png drawn = read_png(png);
  const Png fills = read_png(ours);  // shadowgen's own pixels of the fills: which colours where
  ASSERT_TRUE(drawn.ok && fills.ok);
  int boundary = 0, seams = 0;
  double worst = 0.0;
  for (int y = 2; y + 2 < fills.height; ++y) {
    for (int x = 2; x + 2 < fills.width; ++x) {
      if (x > fills.width - 80 && y < 80) continue;  // the north arrow
      std::set<std::array<int, 3>> colours;
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          const unsigned char* p =
              fills.rgb.data() + 3 * (static_cast<std::size_t>(y + dy) * fills.width + x + dx);
          colours.insert({p[0], p[1], p[2]});
        }
      }
      if (colours.count({255, 255, 255}) > 0 || colours.size() != 2) continue;
      ++boundary;
      std::vector<std::array<double, 3>> around;
      for (const auto& c : colours) around.push_back({double(c[0]), double(c[1]), double(c[2])});
      const double white = white_share(
          around, drawn.rgb.data() + 3 * (static_cast<std::size_t>(y) * drawn.width + x));
      worst = std::max(worst, white);
      if (white > 0.01 && ++seams <= 5) {
        ADD_FAILURE() << "seam at " << x << "," << y << ": " << hex_at(drawn, x, y) << ", " << white
                      << " white";
      }
    }
  }
  std::printf("%d pixels where two colours meet; the most white in one: %.4f\n", boundary, worst);
  EXPECT_GT(boundary, 1000);
  EXPECT_EQ(seams, 0);
}

// A sun-hours map's pixels are its pieces': no view method finds them; one path per
// piece is a way to write the SVG, so it needs one.
TEST_F(MapCli, OptionsAMapCannotTakeAreUsageErrors) {
  const fs::path db = generate("yard", kDay);
  const std::string png = (dir_ / "map.png").string(), svg = (dir_ / "map.svg").string();
  const Outcome shadows = run({"render", db.string(), "--view", "main", "--sun-hours", "day", "-o",
                               png, "--shadows", "volumes"});
  EXPECT_EQ(shadows.code, 2);
  EXPECT_EQ(shadows.err.rfind("shadowgen: --shadows applies only to the lit picture: a sun-hours "
                              "map's pixels are its pieces'\n",
                              0),
            0u)
      << shadows.err;
  const Outcome pieces = run({"render", db.string(), "--view", "main", "-o", png, "--pieces"});
  EXPECT_EQ(pieces.code, 2);
  EXPECT_EQ(pieces.err.rfind("shadowgen: --pieces draws the SVG picture one path per piece: it "
                             "needs -o FILE.svg (or --svg)\n",
                             0),
            0u)
      << pieces.err;
  const Outcome full =
      run({"render", db.string(), "--view", "main", "-o", png, "--full-precision"});
  EXPECT_EQ(full.code, 2);
  EXPECT_EQ(full.err.rfind("shadowgen: --full-precision writes the SVG picture's coordinates "
                           "exactly: it needs -o FILE.svg (or --svg)\n",
                           0),
            0u)
      << full.err;
  EXPECT_FALSE(fs::exists(png));
  EXPECT_FALSE(fs::exists(svg));
}

}  // namespace
}  // namespace shadowgen::test
