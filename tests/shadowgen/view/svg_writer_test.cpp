// SVG text of a picture (shadowgen/svg_writer.h): the document's frame, one path per
// piece with its holes (--pieces) or per colour, coordinates that read back to the same
// doubles, escaped ids, outlines and a map's marks.

#include "shadowgen/view/svg_writer.h"

#include <gtest/gtest.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace shadowgen {
namespace {

Picture two_pieces() {
  Picture picture;
  picture.width = 64;
  picture.height = 48;
  picture.background = {1.0, 1.0, 1.0};
  Piece square;
  square.face_id = "wall";
  square.light_set = "sun+lamp";
  square.lights = {0, 1};
  square.colour = {0.5, 0.25, 1.0};
  square.shape.outer = {{1.0 / 3.0, 2}, {20, 2}, {20, 0.1 + 0.2}, {1.0 / 3.0, 30}};
  square.shape.holes = {{{5, 5}, {5, 6}, {6, 6}, {6, 5}}};
  Piece odd;
  odd.face_id = "a&b<\"c\">'d";
  odd.light_set = "shadow";
  odd.back_side = true;
  odd.shape.outer = {{30, 30}, {31, 30}, {30, 1e-300}};
  picture.pieces = {square, odd};
  return picture;
}

// One path per piece, as the tests before the paths per colour.
constexpr SvgOptions kPieces{.pieces = true};

std::vector<double> numbers_of(const std::string& path_data) {
  std::vector<double> out;
  const char* p = path_data.data();
  const char* end = p + path_data.size();
  while (p < end) {
    if (*p == 'M' || *p == 'L' || *p == 'Z' || *p == ' ' || *p == ',') {
      ++p;
      continue;
    }
    double v = 0.0;
    const auto [next, error] = std::from_chars(p, end, v);
    EXPECT_EQ(error, std::errc()) << path_data;
    if (error != std::errc()) break;
    out.push_back(v);
    p = next;
  }
  return out;
}

TEST(SvgWriter, FrameBackgroundAndOnePathPerPieceWithPieces) {
  const std::string svg = svg_document(two_pieces(), kPieces);
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0), 0u) << svg;
  EXPECT_NE(svg.find("width=\"64\" height=\"48\" viewBox=\"0 0 64 48\""), std::string::npos);
  EXPECT_NE(svg.find("<rect x=\"0\" y=\"0\" width=\"64\" height=\"48\" fill=\"#ffffff\"/>"),
            std::string::npos);
  EXPECT_EQ(svg.find("data-pixels-per-unit"), std::string::npos);  // perspective
  std::size_t paths = 0;
  for (std::size_t at = svg.find("<path "); at != std::string::npos;
       at = svg.find("<path ", at + 1)) {
    ++paths;
  }
  EXPECT_EQ(paths, 2u);
  EXPECT_NE(svg.find("fill=\"#8040ff\" fill-rule=\"evenodd\" data-face=\"wall\" "
                     "data-lights=\"sun+lamp\"/>"),
            std::string::npos)
      << svg;
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
}

// Layers by light: the base's paths bare, then each layer's in one blending group named
// by its light; every group closed before the next opens and before the document ends.
TEST(SvgWriter, LayersByLightAreGroupsBlendedOverTheBase) {
  Picture picture = two_pieces();
  picture.layered = true;
  Piece base = picture.pieces[0], sun = base, sun_too = base, lamp = base;
  base.lights = {};
  base.light_set = "shadow";
  sun.lights = {0};
  sun.light_set = "sun";
  sun.layer = 1;
  sun_too.lights = {0};
  sun_too.light_set = "sun";
  sun_too.layer = 1;
  lamp.lights = {1};
  lamp.light_set = "l\"amp";
  lamp.layer = 2;
  picture.pieces = {base, base, sun, sun_too, lamp};
  const std::string svg = svg_document(picture, kPieces);
  const std::string sun_group = "<g style=\"mix-blend-mode:plus-lighter\" data-light=\"sun\">\n";
  const std::string lamp_group =
      "<g style=\"mix-blend-mode:plus-lighter\" data-light=\"l&quot;amp\">\n";
  const std::size_t first_sun = svg.find(sun_group), first_lamp = svg.find(lamp_group);
  ASSERT_NE(first_sun, std::string::npos) << svg;
  ASSERT_NE(first_lamp, std::string::npos) << svg;
  EXPECT_EQ(svg.find(sun_group, first_sun + 1), std::string::npos);
  // Two base paths before the first group, two in the sun's, one in the lamp's.
  auto paths = [&svg](std::size_t from, std::size_t to) {
    std::size_t n = 0;
    for (std::size_t at = svg.find("<path", from); at < to; at = svg.find("<path", at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(paths(0, first_sun), 2u);
  EXPECT_EQ(paths(first_sun, first_lamp), 2u);
  EXPECT_EQ(paths(first_lamp, svg.size()), 1u);
  EXPECT_NE(svg.find("/>\n</g>\n<g style"), std::string::npos);
  EXPECT_NE(svg.find("/>\n</g>\n</svg>\n"), std::string::npos);
  // A picture not in layers has no group.
  EXPECT_EQ(svg_document(two_pieces(), kPieces).find("<g"), std::string::npos);
}

TEST(SvgWriter, CoordinatesReadBackExactly) {
  const Picture picture = two_pieces();
  const std::string svg = svg_document(picture, kPieces);
  const std::size_t start = svg.find("<path d=\"") + 9;
  const std::string d = svg.substr(start, svg.find('"', start) - start);
  // Outer loop, then the hole, each a closed subpath.
  EXPECT_EQ(d.rfind("M0.3333333333333333,2 L20,2 20,0.30000000000000004 ", 0), 0u) << d;
  EXPECT_NE(d.find(" Z M5,5 L"), std::string::npos) << d;
  std::vector<double> expected;
  for (const clipper::Point2& p : picture.pieces[0].shape.outer) {
    expected.insert(expected.end(), {p.x, p.y});
  }
  for (const clipper::Point2& p : picture.pieces[0].shape.holes[0]) {
    expected.insert(expected.end(), {p.x, p.y});
  }
  EXPECT_EQ(numbers_of(d), expected);
  EXPECT_NE(svg.find("30,1e-300 Z"), std::string::npos) << svg;
}

TEST(SvgWriter, AttributesAreEscaped) {
  const std::string svg = svg_document(two_pieces(), kPieces);
  EXPECT_NE(svg.find("data-face=\"a&amp;b&lt;&quot;c&quot;&gt;&apos;d\" data-lights=\"shadow\" "
                     "data-side=\"back\"/>"),
            std::string::npos)
      << svg;
  Picture bad = two_pieces();
  bad.pieces[0].face_id = std::string("x\x01y\xff") + "\xc3\xa9";  // control, bad byte, é
  const std::string text = svg_document(bad, kPieces);
  EXPECT_NE(text.find("data-face=\"x\xEF\xBF\xBDy\xEF\xBF\xBD\xc3\xa9\""), std::string::npos);
}

TEST(SvgWriter, SunHoursPiecesCarryTheirHoursAndTheLegendWidensThePicture) {
  Picture picture = two_pieces();
  for (Piece& piece : picture.pieces) {
    piece.lights.clear();
    piece.light_set.clear();
  }
  picture.pieces[0].sun_hours = 1.5;
  picture.pieces[1].sun_hours = 0.0;
  picture.legend.kind = "sun-hours";
  picture.legend.caption = {"Sun hours: a<b", "4 instants, every 30 min"};
  picture.legend.entries = {{{0, 0, 0}, "0\u20131 h"}, {{1, 1, 1}, "\u2265 1 h"}};
  const std::string svg = svg_document(picture, kPieces);
  EXPECT_EQ(svg.find("data-lights"), std::string::npos) << svg;
  EXPECT_NE(svg.find("data-face=\"wall\" data-hours=\"1.5\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("data-hours=\"0\" data-side=\"back\"/>"), std::string::npos) << svg;
  // A strip of 220 pixels to the right; the legend (16 + 2 × 18 + 2 × 22 + 16 = 112
  // pixels) is taller than the picture, so the document is too.
  EXPECT_NE(svg.find("width=\"284\" height=\"112\" viewBox=\"0 0 284 112\""), std::string::npos)
      << svg;
  EXPECT_NE(svg.find("<rect x=\"0\" y=\"0\" width=\"284\" height=\"112\" fill=\"#ffffff\"/>"),
            std::string::npos);
  // After the pieces: the caption, escaped, then the entries, the most hours on top.
  const std::size_t legend = svg.find("<g font-family=\"sans-serif\"");
  ASSERT_NE(legend, std::string::npos);
  EXPECT_GT(legend, svg.rfind("<path "));
  EXPECT_EQ(svg.substr(legend),
            "<g font-family=\"sans-serif\" font-size=\"12\" fill=\"#000000\" "
            "data-legend=\"sun-hours\">\n"
            "<text x=\"80\" y=\"28\">Sun hours: a&lt;b</text>\n"
            "<text x=\"80\" y=\"46\">4 instants, every 30 min</text>\n"
            "<rect x=\"80\" y=\"54\" width=\"28\" height=\"16\" fill=\"#ffffff\" "
            "stroke=\"#000000\" stroke-width=\"0.5\"/>\n"
            "<text x=\"116\" y=\"67\">\u2265 1 h</text>\n"
            "<rect x=\"80\" y=\"76\" width=\"28\" height=\"16\" fill=\"#000000\" "
            "stroke=\"#000000\" stroke-width=\"0.5\"/>\n"
            "<text x=\"116\" y=\"89\">0\u20131 h</text>\n"
            "</g>\n</svg>\n");
}

TEST(SvgWriter, OrthographicScaleIsRecordedAndFilesAreWholeOrAbsent) {
  Picture picture = two_pieces();
  picture.pixels_per_unit = 37.5;
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "svg-writer";
  std::filesystem::create_directories(dir);
  write_svg(picture, dir / "p.svg");
  std::ifstream in(dir / "p.svg", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), svg_document(picture));
  EXPECT_NE(text.str().find("data-pixels-per-unit=\"37.5\""), std::string::npos);
  EXPECT_THROW(write_svg(picture, dir / "missing" / "p.svg"), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
  std::filesystem::remove_all(dir);
}

// Three unit squares in a row: the two of one colour and light set that share an edge
// become one path of area 2 with no inner edge, stroked in its colour against seams; the
// third, of another colour, its own path.
Picture three_squares() {
  Picture picture;
  picture.width = 64;
  picture.height = 48;
  picture.background = {1.0, 1.0, 1.0};
  const auto square = [](double x, const std::string& face, const std::string& set, Rgb colour) {
    Piece piece;
    piece.face_id = face;
    piece.light_set = set;
    piece.colour = colour;
    piece.shape.outer = {{x, 10}, {x + 1, 10}, {x + 1, 11}, {x, 11}};
    return piece;
  };
  picture.pieces = {square(10, "a", "sun", {1, 0, 0}), square(11, "b", "sun", {1, 0, 0}),
                    square(12, "b", "shadow", {0, 0, 1})};
  return picture;
}

TEST(SvgWriter, PiecesOfOneColourThatTouchAreOnePathStrokedInItsColour) {
  const std::string svg = svg_document(three_squares());
  // On the grid, relative (detail/path_data.h).
  EXPECT_NE(svg.find("<path d=\"M10 10h2v1h-2z\" fill=\"#ff0000\" "
                     "stroke=\"#ff0000\" stroke-width=\"1.5\" stroke-linejoin=\"round\" "
                     "fill-rule=\"evenodd\" data-lights=\"sun\"/>\n"),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find("<path d=\"M12 10h1v1h-1z\" fill=\"#0000ff\" "
                     "stroke=\"#0000ff\" stroke-width=\"1.5\" stroke-linejoin=\"round\" "
                     "fill-rule=\"evenodd\" data-lights=\"shadow\"/>\n"),
            std::string::npos)
      << svg;
  // With full precision, each coordinate as the double it is, absolute.
  const std::string exact = svg_document(three_squares(), {.full_precision = true});
  EXPECT_NE(exact.find("<path d=\"M10,10 L12,10 12,11 10,11 Z\" fill=\"#ff0000\" "),
            std::string::npos)
      << exact;
  // No face on a path of several faces: the outlines name them.
  EXPECT_EQ(svg.find("data-face"), std::string::npos) << svg;
  Picture sun_hours = three_squares();
  for (Piece& piece : sun_hours.pieces) {
    piece.light_set.clear();
    piece.sun_hours = 1.0;
    piece.band = "0\u20132 h";
  }
  const std::string map = svg_document(sun_hours);
  EXPECT_NE(map.find("fill-rule=\"evenodd\" data-band=\"0\u20132 h\"/>"), std::string::npos) << map;
  EXPECT_EQ(map.find("data-lights"), std::string::npos) << map;
}

TEST(SvgWriter, OutlinesNorthArrowAndScaleBarAreDrawnOverTheFills) {
  Picture picture = three_squares();
  picture.outlines = {{"a", "", {{{{10, 10}, {11, 10}, {11, 11}, {10, 11}}, {}}}},
                      {"", "block 7", {{{{11, 10}, {13, 10}, {13, 11}, {11, 11}}, {}}}}};
  picture.north = NorthArrow{330};
  picture.scale_bar = ScaleBar{20, 140, "20 m"};
  const std::string svg = svg_document(picture);
  const std::size_t outlines = svg.find(
      "<g fill=\"none\" stroke=\"#262626\" stroke-width=\"0.75\" stroke-linejoin=\"round\" "
      "data-outlines=\"\">\n<path d=\"M10 10h1v1h-1z\" data-face=\"a\"/>\n"
      "<path d=\"M11 10h2v1h-2z\" data-object=\"block 7\"/>\n</g>\n");
  ASSERT_NE(outlines, std::string::npos) << svg;
  EXPECT_GT(outlines, svg.rfind("data-lights"));
  // The arrow in the top right corner of the 64 × 48 picture, turned about its centre
  // (64 − 16 − 14, 16 + 14 + 12) = (34, 42).
  EXPECT_NE(svg.find("<g data-north-arrow=\"330\">\n<path d=\"M34,28 L39.6,56 L34,49 L28.4,56 Z\" "
                     "fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\"1\" "
                     "transform=\"rotate(330 34 42)\"/>\n"),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find("<g data-scale-bar=\"20\" data-pixels=\"140\">\n<rect x=\"16\" y=\"26\" "
                     "width=\"140\" height=\"6\" fill=\"#000000\" stroke=\"#ffffff\" "
                     "stroke-width=\"1\"/>\n<text x=\"16\" y=\"22\" "),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find(">20 m</text>\n</g>\n</svg>\n"), std::string::npos) << svg;
}

}  // namespace
}  // namespace shadowgen
