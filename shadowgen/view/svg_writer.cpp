#include "shadowgen/view/svg_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <span>
#include <string_view>
#include <vector>

#include "detail/colour_hex.h"
#include "detail/path_data.h"
#include "detail/xml_text.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/view/colour_paths.h"

namespace shadowgen {
namespace {

using view::detail::append_colour;

void append_attribute_value(std::string& out, std::string_view text) {
  out += '"';
  view::detail::append_xml_text(out, text);
  out += '"';
}

void append_number(std::string& out, double value) { append_shortest(out, value); }

// The legend's layout, in pixels: a strip of kLegendWidth to the right of the picture.
constexpr int kLegendWidth = 220;
constexpr int kLegendMargin = 16;
constexpr int kCaptionLine = 18;  // caption baselines apart
constexpr int kEntryLine = 22;    // swatches apart
constexpr int kSwatchWidth = 28;
constexpr int kSwatchHeight = 16;
constexpr int kFontSize = 12;

// The base layer's paths are stroked this wide in their own colour (append_colour_paths).
constexpr std::string_view kSeamStroke = "1.5";
// Outlines: thin and dark.
constexpr std::string_view kOutlineColour = "#262626";
constexpr std::string_view kOutlineWidth = "0.75";
// The marks: a north arrow in the top right corner, a scale bar in the bottom left.
constexpr int kMarkMargin = 16;
constexpr double kArrowLength = 28.0;
constexpr int kBarHeight = 6;
constexpr std::string_view kMarkText =
    "font-family=\"sans-serif\" font-size=\"12\" fill=\"#000000\" stroke=\"#ffffff\" "
    "stroke-width=\"3\" paint-order=\"stroke\"";

int legend_height(const Legend& legend) {
  return 2 * kLegendMargin + static_cast<int>(legend.caption.size()) * kCaptionLine +
         static_cast<int>(legend.entries.size()) * kEntryLine;
}

void append_text(std::string& out, int x, int y, std::string_view text) {
  out += "<text x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(y) + "\">";
  view::detail::append_xml_text(out, text);
  out += "</text>\n";
}

// The caption, then a swatch and a label per entry, the most hours at the top.
void append_legend(std::string& out, const Legend& legend, int left) {
  const int x = left + kLegendMargin;
  out += "<g font-family=\"sans-serif\" font-size=\"" + std::to_string(kFontSize) +
         "\" fill=\"#000000\" data-legend=";
  append_attribute_value(out, legend.kind);
  out += ">\n";
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

// A map's shapes (paths per colour, outlines) on the grid of detail/path_data.h, or exact
// with SvgOptions::full_precision.
void append_map_path_data(std::string& out, std::span<const clipper::PolygonWithHoles2> shapes,
                          const SvgOptions& options) {
  if (options.full_precision) {
    view::detail::append_exact_path_data(out, shapes);
  } else {
    view::detail::append_grid_path_data(out, shapes);
  }
}

// Opens the group of layer `layer` where it differs from the one open, closing that.
void switch_layer(std::string& out, std::size_t& open_layer, std::size_t layer,
                  std::string_view light) {
  if (layer == open_layer) return;
  if (open_layer != 0) out += "</g>\n";
  open_layer = layer;
  if (layer == 0) return;
  out += "<g style=\"mix-blend-mode:plus-lighter\" data-light=";
  append_attribute_value(out, light);
  out += ">\n";
}

// One path per piece, with its face, its light set or hours, its side.
void append_pieces(std::string& out, const std::vector<Piece>& pieces) {
  std::size_t open_layer = 0;
  for (const Piece& piece : pieces) {
    switch_layer(out, open_layer, piece.layer, piece.light_set);
    out += "<path d=\"";
    view::detail::append_exact_path_data(out, {&piece.shape, 1});
    out += "\" fill=\"";
    append_colour(out, piece.colour);
    out += "\" fill-rule=\"evenodd\" data-face=";
    append_attribute_value(out, piece.face_id);
    if (piece.sun_hours) {
      out += " data-hours=\"";
      append_number(out, *piece.sun_hours);
      out += '"';
    } else if (piece.kwh_per_m2) {
      out += " data-kwh-per-m2=\"";
      append_number(out, *piece.kwh_per_m2);
      out += '"';
    } else {
      out += " data-lights=";
      append_attribute_value(out, piece.light_set);
    }
    if (piece.back_side) out += " data-side=\"back\"";
    out += "/>\n";
  }
  if (open_layer != 0) out += "</g>\n";
}

// One path per colour. The base layer's paths are stroked in their own colour, 1.5 pixels
// wide (three quarters of a pixel beyond their edges), so that where two colours meet the
// boundary pixels are covered by the two and the background does not show through their
// antialiased edges: a pixel an edge cuts at t of its width from one side is covered
// min(1, t + h) by that side's path and 1 − t by the other, leaving (1 − t − h)·t of
// background, at most ((1 − h)/2)² = 1/64 for h = 3/4 (1/4 without a stroke; rsvg's
// pictures in the tests show at most 0.5 %). The layers, which a viewer adds up, are not
// stroked (a stroke would be added twice).
void append_colour_paths(std::string& out, const std::vector<ColourPath>& paths,
                         const SvgOptions& options) {
  std::size_t open_layer = 0;
  for (const ColourPath& path : paths) {
    switch_layer(out, open_layer, path.layer, path.light_set);
    out += "<path d=\"";
    append_map_path_data(out, path.shape, options);
    out += "\" fill=\"";
    append_colour(out, path.colour);
    out += '"';
    if (path.layer == 0) {
      out += " stroke=\"";
      append_colour(out, path.colour);
      out += "\" stroke-width=\"" + std::string(kSeamStroke) + "\" stroke-linejoin=\"round\"";
    }
    out += " fill-rule=\"evenodd\"";
    if (path.banded) {
      out += " data-band=";
      append_attribute_value(out, path.band);
    } else {
      out += " data-lights=";
      append_attribute_value(out, path.light_set);
    }
    if (path.back_side) out += " data-side=\"back\"";
    out += "/>\n";
  }
  if (open_layer != 0) out += "</g>\n";
}

void append_outlines(std::string& out, const std::vector<Outline>& outlines,
                     const SvgOptions& options) {
  if (outlines.empty()) return;
  out += "<g fill=\"none\" stroke=\"" + std::string(kOutlineColour) + "\" stroke-width=\"" +
         std::string(kOutlineWidth) + "\" stroke-linejoin=\"round\" data-outlines=\"\">\n";
  for (const Outline& outline : outlines) {
    if (outline.shape.empty()) continue;
    out += "<path d=\"";
    append_map_path_data(out, outline.shape, options);
    out += '"';
    if (outline.object.empty()) {
      out += " data-face=";
      append_attribute_value(out, outline.face_id);
    } else {
      out += " data-object=";
      append_attribute_value(out, outline.object);
    }
    out += "/>\n";
  }
  out += "</g>\n";
}

// An arrow in the picture's top right corner, drawn pointing up and turned by the
// north's angle about its centre, and an N beyond its tip.
void append_north_arrow(std::string& out, const NorthArrow& north, int width) {
  const double cx = width - kMarkMargin - kArrowLength / 2.0;
  const double cy = kMarkMargin + kArrowLength / 2.0 + kFontSize;
  const double half = kArrowLength / 2.0;
  out += "<g data-north-arrow=\"";
  append_number(out, north.angle_deg);
  out += "\">\n<path d=\"M";
  append_number(out, cx);
  out += ',';
  append_number(out, cy - half);
  out += " L";
  append_number(out, cx + 0.4 * half);
  out += ',';
  append_number(out, cy + half);
  out += " L";
  append_number(out, cx);
  out += ',';
  append_number(out, cy + 0.5 * half);
  out += " L";
  append_number(out, cx - 0.4 * half);
  out += ',';
  append_number(out, cy + half);
  out += " Z\" fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\"1\" transform=\"rotate(";
  append_number(out, north.angle_deg);
  out += ' ';
  append_number(out, cx);
  out += ' ';
  append_number(out, cy);
  out += ")\"/>\n";
  const double turn = north.angle_deg * std::numbers::pi / 180.0;
  const double reach = half + kFontSize;
  out += "<text x=\"";
  append_number(out, std::round(10.0 * (cx + reach * std::sin(turn))) / 10.0);
  out += "\" y=\"";
  append_number(out, std::round(10.0 * (cy - reach * std::cos(turn) + kFontSize / 2.5)) / 10.0);
  out += "\" " + std::string(kMarkText) + " text-anchor=\"middle\">N</text>\n</g>\n";
}

// A bar in the picture's bottom left corner, its length written above it.
void append_scale_bar(std::string& out, const ScaleBar& bar, int height) {
  const int x = kMarkMargin;
  const int y = height - kMarkMargin - kBarHeight;
  out += "<g data-scale-bar=\"";
  append_number(out, bar.length);
  out += "\" data-pixels=\"";
  append_number(out, bar.pixels);
  out += "\">\n<rect x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(y) + "\" width=\"";
  append_number(out, bar.pixels);
  out += "\" height=\"" + std::to_string(kBarHeight) +
         "\" fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\"1\"/>\n";
  out += "<text x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(y - 4) + "\" " +
         std::string(kMarkText) + ">";
  view::detail::append_xml_text(out, bar.label);
  out += "</text>\n</g>\n";
}

}  // namespace

std::string svg_document(const Picture& picture, const SvgOptions& options) {
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
  if (options.pieces) {
    append_pieces(out, picture.pieces);
  } else {
    append_colour_paths(out, colour_paths(picture), options);
  }
  append_outlines(out, picture.outlines, options);
  if (picture.north) append_north_arrow(out, *picture.north, picture.width);
  if (picture.scale_bar) append_scale_bar(out, *picture.scale_bar, picture.height);
  if (legend) append_legend(out, picture.legend, picture.width);
  out += "</svg>\n";
  return out;
}

void write_svg(const Picture& picture, const std::filesystem::path& path,
               const SvgOptions& options) {
  write_file_atomically(path, svg_document(picture, options));
}

}  // namespace shadowgen
