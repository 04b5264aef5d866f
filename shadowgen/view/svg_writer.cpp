#include "shadowgen/view/svg_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string_view>

#include "detail/xml_text.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/output/atomic_file.h"

namespace shadowgen {
namespace {

void append_colour(std::string& out, const Rgb& colour) {
  constexpr std::string_view kHex = "0123456789abcdef";
  out += '#';
  for (const double v : {colour.r, colour.g, colour.b}) {
    const double clamped = std::isfinite(v) ? std::fmin(std::fmax(v, 0.0), 1.0) : 0.0;
    const auto byte = static_cast<unsigned>(std::lround(255.0 * clamped));
    out += kHex[byte >> 4];
    out += kHex[byte & 15];
  }
}

void append_attribute_value(std::string& out, std::string_view text) {
  out += '"';
  detail::append_xml_text(out, text);
  out += '"';
}

void append_loop(std::string& out, const clipper::Loop2& loop) {
  for (std::size_t i = 0; i < loop.size(); ++i) {
    out += i == 0 ? (out.back() == '"' ? "M" : " M") : (i == 1 ? " L" : " ");
    append_shortest(out, loop[i].x);
    out += ',';
    append_shortest(out, loop[i].y);
  }
  out += " Z";
}

// The legend's layout, in pixels: a strip of kLegendWidth to the right of the picture.
constexpr int kLegendWidth = 220;
constexpr int kLegendMargin = 16;
constexpr int kCaptionLine = 18;  // caption baselines apart
constexpr int kEntryLine = 22;    // swatches apart
constexpr int kSwatchWidth = 28;
constexpr int kSwatchHeight = 16;
constexpr int kFontSize = 12;

int legend_height(const Legend& legend) {
  return 2 * kLegendMargin + static_cast<int>(legend.caption.size()) * kCaptionLine +
         static_cast<int>(legend.entries.size()) * kEntryLine;
}

void append_text(std::string& out, int x, int y, std::string_view text) {
  out += "<text x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(y) + "\">";
  detail::append_xml_text(out, text);
  out += "</text>\n";
}

// The caption, then a swatch and a label per entry, the most hours at the top.
void append_legend(std::string& out, const Legend& legend, int left) {
  const int x = left + kLegendMargin;
  out += "<g font-family=\"sans-serif\" font-size=\"" + std::to_string(kFontSize) +
         "\" fill=\"#000000\" data-legend=\"sun-hours\">\n";
  int y = kLegendMargin;
  for (const std::string& line : legend.caption) {
    append_text(out, x, y + kFontSize, line);
    y += kCaptionLine;
  }
  for (auto it = legend.entries.rbegin(); it != legend.entries.rend(); ++it) {
    out += "<rect x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(y + 2) + "\" width=\"" +
           std::to_string(kSwatchWidth) + "\" height=\"" + std::to_string(kSwatchHeight) +
           "\" fill=\"";
    append_colour(out, it->colour);
    out += "\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
    append_text(out, x + kSwatchWidth + 8, y + kFontSize + 3, it->label);
    y += kEntryLine;
  }
  out += "</g>\n";
}

}  // namespace

std::string svg_document(const Picture& picture) {
  const bool legend = !picture.legend.entries.empty();
  const int width = picture.width + (legend ? kLegendWidth : 0);
  const int height =
      legend ? std::max(picture.height, legend_height(picture.legend)) : picture.height;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"";
  out += std::to_string(width);
  out += "\" height=\"";
  out += std::to_string(height);
  out += "\" viewBox=\"0 0 ";
  out += std::to_string(width);
  out += ' ';
  out += std::to_string(height);
  out += '"';
  if (picture.pixels_per_unit > 0.0) {
    out += " data-pixels-per-unit=\"";
    append_shortest(out, picture.pixels_per_unit);
    out += '"';
  }
  out += ">\n<rect x=\"0\" y=\"0\" width=\"";
  out += std::to_string(width);
  out += "\" height=\"";
  out += std::to_string(height);
  out += "\" fill=\"";
  append_colour(out, picture.background);
  out += "\"/>\n";
  std::size_t open_layer = 0;
  for (const Piece& piece : picture.pieces) {
    if (piece.layer != open_layer) {
      if (open_layer != 0) out += "</g>\n";
      open_layer = piece.layer;
      out += "<g style=\"mix-blend-mode:plus-lighter\" data-light=";
      append_attribute_value(out, piece.light_set);
      out += ">\n";
    }
    out += "<path d=\"";
    append_loop(out, piece.shape.outer);
    for (const clipper::Loop2& hole : piece.shape.holes) append_loop(out, hole);
    out += "\" fill=\"";
    append_colour(out, piece.colour);
    out += "\" fill-rule=\"evenodd\" data-face=";
    append_attribute_value(out, piece.face_id);
    if (piece.sun_hours) {
      out += " data-hours=\"";
      append_shortest(out, *piece.sun_hours);
      out += '"';
    } else {
      out += " data-lights=";
      append_attribute_value(out, piece.light_set);
    }
    if (piece.back_side) out += " data-side=\"back\"";
    out += "/>\n";
  }
  if (open_layer != 0) out += "</g>\n";
  if (legend) append_legend(out, picture.legend, picture.width);
  out += "</svg>\n";
  return out;
}

void write_svg(const Picture& picture, const std::filesystem::path& path) {
  write_file_atomically(path, svg_document(picture));
}

}  // namespace shadowgen
