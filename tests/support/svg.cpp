#include "tests/support/svg.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

namespace shadowgen::test {

using clipper::Loop2;
using clipper::Point2;
using clipper::PolygonWithHoles2;

void write_svg(const std::string& path, const std::vector<SvgLayer>& layers) {
  double xmin = std::numeric_limits<double>::infinity();
  double ymin = xmin;
  double xmax = -xmin;
  double ymax = -xmin;
  for (const SvgLayer& layer : layers) {
    for (const PolygonWithHoles2& polygon : *layer.polygons) {
      for (const Point2& p : polygon.outer) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y);
        ymax = std::max(ymax, p.y);
      }
    }
  }
  if (!(xmin <= xmax)) xmin = ymin = 0.0, xmax = ymax = 1.0;
  // Drawn in coordinates relative to the box's corner, so that far-off or tiny cases
  // keep their detail in the file's six significant digits.
  const double size = std::max({xmax - xmin, ymax - ymin, std::numeric_limits<double>::min()});
  const double scale = 1000.0 / size;
  const double margin = 20.0;
  std::ofstream out(path);
  if (!out) return;
  out.precision(10);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 1000 + 2 * margin << "\" height=\""
      << 1000 + 2 * margin + 20.0 * static_cast<double>(layers.size()) << "\">\n";
  out << "<!-- box: x " << xmin << " .. " << xmax << ", y " << ymin << " .. " << ymax << " -->\n";
  auto map = [&](const Point2& p) {
    return std::to_string(margin + (p.x - xmin) * scale) + "," +
           std::to_string(margin + (ymax - p.y) * scale);
  };
  for (const SvgLayer& layer : layers) {
    out << "<g fill=\"" << layer.fill << "\" fill-opacity=\"0.35\" stroke=\"" << layer.stroke
        << "\" stroke-width=\"1.5\" fill-rule=\"evenodd\">\n";
    for (const PolygonWithHoles2& polygon : *layer.polygons) {
      out << "<path d=\"";
      auto ring = [&](const Loop2& loop) {
        for (std::size_t i = 0; i < loop.size(); ++i) out << (i == 0 ? "M" : " L") << map(loop[i]);
        if (!loop.empty()) out << " Z ";
      };
      ring(polygon.outer);
      for (const Loop2& hole : polygon.holes) ring(hole);
      out << "\"/>\n";
      for (const Point2& p : polygon.outer) {
        out << "<circle cx=\"" << margin + (p.x - xmin) * scale << "\" cy=\""
            << margin + (ymax - p.y) * scale << "\" r=\"2\" fill=\"" << layer.stroke << "\"/>\n";
      }
    }
    out << "</g>\n";
  }
  double y = 1000 + 2 * margin;
  for (const SvgLayer& layer : layers) {
    out << "<text x=\"" << margin << "\" y=\"" << y + 14 << "\" fill=\"" << layer.stroke
        << "\" font-family=\"sans-serif\" font-size=\"14\">" << layer.label << "</text>\n";
    y += 20;
  }
  out << "</svg>\n";
}

}  // namespace shadowgen::test
