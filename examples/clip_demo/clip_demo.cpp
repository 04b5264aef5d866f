// clip_demo: two concave polygons with holes, a letter A and a seven-pointed star with an
// octagonal hole, clipped against each other with clipper/clip.h. Prints the areas and
// writes an SVG picture of the inputs (left) and of the inside and outside pieces (right).
//
//   clip_demo [OUTPUT.svg]        (default clip_demo.svg; -h or --help: this usage)
//
// The picture is written to a temporary file beside OUTPUT and renamed over it, so a
// reader never sees a partial file. Exit status: 0 on success, 1 when the file cannot be
// written, 2 when the areas do not add up (inside + outside must equal the subject) or
// the arguments are not an optional file name (an option other than --help, two names).

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <system_error>

#include "clipper/clip.h"
#include "clipper/polygon.h"

namespace {

using shadowgen::clipper::ClipResult;
using shadowgen::clipper::Loop2;
using shadowgen::clipper::Point2;
using shadowgen::clipper::PolygonSet2;
using shadowgen::clipper::PolygonWithHoles2;

// A capital A, 90 wide and 100 tall: concave between the legs, with a triangular counter.
PolygonWithHoles2 letter_a() {
  return {{{0, 0}, {20, 0}, {28, 25}, {62, 25}, {70, 0}, {90, 0}, {55, 100}, {35, 100}},
          {{{33, 42}, {45, 78}, {57, 42}}}};
}

// A regular polygon or star around `center`: `points` tips at radius `outer`, and, when
// `inner` > 0, notches at radius `inner` between them. Counter-clockwise.
Loop2 star_loop(Point2 center, int points, double outer, double inner) {
  Loop2 loop;
  const int steps = inner > 0 ? 2 * points : points;
  for (int k = 0; k < steps; ++k) {
    const double angle = std::numbers::pi / 2 + 2 * std::numbers::pi * k / steps;
    const double r = (inner > 0 && k % 2 == 1) ? inner : outer;
    loop.push_back({center.x + r * std::cos(angle), center.y + r * std::sin(angle)});
  }
  return loop;
}

PolygonWithHoles2 holed_star() {
  const Point2 center{60, 55};
  Loop2 hole = star_loop(center, 8, 9, 0);
  Loop2 clockwise(hole.rbegin(), hole.rend());
  return {star_loop(center, 7, 45, 20), {clockwise}};
}

struct Box {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  void add(const PolygonWithHoles2& polygon) {
    for (const Point2& p : polygon.outer) {
      x0 = std::fmin(x0, p.x);
      y0 = std::fmin(y0, p.y);
      x1 = std::fmax(x1, p.x);
      y1 = std::fmax(y1, p.y);
    }
  }
};

// Places one panel of the picture: model coordinates (y up) to SVG pixels (y down).
class Panel {
 public:
  Panel(const Box& box, double left, double top, double size) : box_(box), left_(left), top_(top) {
    scale_ = size / std::fmax(box.x1 - box.x0, box.y1 - box.y0);
  }

  // One <path> per polygon with holes; evenodd makes the holes show whatever their
  // orientation.
  std::string path(const PolygonWithHoles2& polygon, const std::string& style) const {
    std::ostringstream d;
    d.precision(6);
    d << std::fixed;
    auto add_loop = [&](const Loop2& loop) {
      for (std::size_t i = 0; i < loop.size(); ++i) {
        d << (i == 0 ? "M" : " L") << left_ + (loop[i].x - box_.x0) * scale_ << ' '
          << top_ + (box_.y1 - loop[i].y) * scale_;
      }
      d << " Z ";
    };
    add_loop(polygon.outer);
    for (const Loop2& hole : polygon.holes) add_loop(hole);
    return "    <path fill-rule=\"evenodd\" " + style + " d=\"" + d.str() + "\"/>\n";
  }

  double height() const { return (box_.y1 - box_.y0) * scale_; }

  std::string paths(const PolygonSet2& set, const std::string& style) const {
    std::string out;
    for (const PolygonWithHoles2& polygon : set) out += path(polygon, style);
    return out;
  }

 private:
  Box box_;
  double left_;
  double top_;
  double scale_ = 1;
};

std::string svg(const PolygonWithHoles2& subject, const PolygonWithHoles2& clip_region,
                const ClipResult& result) {
  Box box;
  box.add(subject);
  box.add(clip_region);
  constexpr double kSize = 400, kMargin = 40;
  const Panel input(box, kMargin, kMargin, kSize);
  const Panel output(box, 2 * kMargin + kSize, kMargin, kSize);
  const std::string subject_style =
      "fill=\"#4e79a7\" fill-opacity=\"0.5\" stroke=\"#2b4a6f\" stroke-width=\"1.5\"";
  const std::string clip_style =
      "fill=\"#f28e2b\" fill-opacity=\"0.5\" stroke=\"#a8581a\" stroke-width=\"1.5\"";
  const std::string inside_style = "fill=\"#59a14f\" stroke=\"#2f5e29\" stroke-width=\"1.5\"";
  const std::string outside_style = "fill=\"#e15759\" stroke=\"#8c2a2c\" stroke-width=\"1.5\"";
  const std::string clip_outline =
      "fill=\"none\" stroke=\"#555555\" stroke-width=\"1\" stroke-dasharray=\"4 3\"";

  std::ostringstream out;
  const double width = 3 * kMargin + 2 * kSize, height = 2 * kMargin + input.height();
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n"
      << "  <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "  <g id=\"subject\">\n"
      << input.path(subject, subject_style) << "  </g>\n"
      << "  <g id=\"clip\">\n"
      << input.path(clip_region, clip_style) << "  </g>\n"
      << "  <g id=\"inside\">\n"
      << output.paths(result.inside, inside_style) << "  </g>\n"
      << "  <g id=\"outside\">\n"
      << output.paths(result.outside, outside_style) << "  </g>\n"
      << "  <g id=\"clip-outline\">\n"
      << output.path(clip_region, clip_outline) << "  </g>\n"
      << "  <g font-family=\"sans-serif\" font-size=\"14\">\n"
      << "    <text x=\"" << kMargin << "\" y=\"24\">subject (blue) and clip (orange)</text>\n"
      << "    <text x=\"" << 2 * kMargin + kSize
      << "\" y=\"24\">inside pieces (green), outside pieces (red)</text>\n"
      << "  </g>\n"
      << "</svg>\n";
  return out.str();
}

// Writes `text` to a temporary file in the target's folder, then renames it over the
// target (atomic on POSIX), so no partial picture is ever left behind.
bool write_atomically(const std::filesystem::path& target, const std::string& text) {
  std::random_device random;
  std::filesystem::path temporary = target;
  temporary += ".tmp" + std::to_string(random());
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file << text;
    file.close();
    if (!file) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      return false;
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, target, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return false;
  }
  return true;
}

}  // namespace

constexpr const char* kUsage =
    "usage: clip_demo [OUTPUT.svg]\n"
    "Clips a letter A and a seven-pointed star with a hole against each other, prints the\n"
    "areas and writes a picture of the inputs and the pieces to OUTPUT.svg (default\n"
    "clip_demo.svg).\n";

int main(int argc, char** argv) {
  // One optional argument, a file name; an option is never taken for one (--help once
  // wrote a picture named "--help").
  const std::string first = argc > 1 ? argv[1] : "";
  if (first == "-h" || first == "--help") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (argc > 2 || (first.size() > 1 && first[0] == '-')) {
    std::fprintf(stderr, "clip_demo: unexpected argument '%s'\n%s", argc > 2 ? argv[2] : argv[1],
                 kUsage);
    return 2;
  }
  const std::filesystem::path output = first.empty() ? "clip_demo.svg" : first;
  const PolygonWithHoles2 subject = letter_a();
  const PolygonWithHoles2 clip_region = holed_star();
  const ClipResult result = shadowgen::clipper::clip(subject, clip_region);

  const double subject_area = shadowgen::clipper::area(subject);
  const double inside_area = shadowgen::clipper::area(result.inside);
  const double outside_area = shadowgen::clipper::area(result.outside);
  std::printf("subject (letter A)        area %10.4f\n", subject_area);
  std::printf("clip (star with a hole)   area %10.4f\n", shadowgen::clipper::area(clip_region));
  std::printf("inside  (A and star)      area %10.4f in %zu piece(s)\n", inside_area,
              result.inside.size());
  std::printf("outside (A minus star)    area %10.4f in %zu piece(s)\n", outside_area,
              result.outside.size());
  const double mismatch = std::fabs(inside_area + outside_area - subject_area);
  std::printf("inside + outside - subject     %10.3g\n", mismatch);

  if (!write_atomically(output, svg(subject, clip_region, result))) {
    std::fprintf(stderr, "clip_demo: cannot write %s\n", output.c_str());
    return 1;
  }
  std::printf("wrote %s\n", output.c_str());
  // The constructed crossings are rounded (clip.h bounds the error), so allow a few ulps
  // of the subject's area.
  return mismatch <= 1e-12 * subject_area ? 0 : 2;
}
