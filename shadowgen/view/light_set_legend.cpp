#include "shadowgen/view/light_set_legend.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "clipper/polygon.h"
#include "detail/colour_hex.h"

namespace shadowgen {
namespace {

struct SetDrawn {
  std::string name;
  std::map<std::string, double> area_by_colour;  // by "#rrggbb"
  double area = 0.0;
};

// `name` cut to at most kMaxLegendLabel bytes with "…", at the start of a UTF-8 character.
std::string legend_label(const std::string& name) {
  if (name.size() <= kMaxLegendLabel) return name;
  std::size_t end = kMaxLegendLabel - 1;
  while (end > 0 && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) --end;
  return name.substr(0, end) + "\u2026";
}

}  // namespace

Legend light_set_legend(std::span<const Piece> pieces) {
  std::map<std::vector<std::size_t>, SetDrawn> sets;
  std::map<std::string, Rgb> colour_of;
  for (const Piece& piece : pieces) {
    std::string hex;
    view::detail::append_colour(hex, piece.colour);
    colour_of.emplace(hex, piece.colour);
    SetDrawn& set = sets[piece.lights];
    set.name = piece.light_set;
    const double area = clipper::area(piece.shape);
    set.area_by_colour[hex] += area;
    set.area += area;
  }
  Legend legend;
  if (sets.empty()) return legend;
  legend.kind = "light-sets";
  legend.caption = {"Light sets"};
  std::vector<const SetDrawn*> kept;
  for (const auto& [lights, set] : sets) kept.push_back(&set);
  if (kept.size() > kMaxLegendSets) {
    legend.caption.push_back("the " + std::to_string(kMaxLegendSets) + " of " +
                             std::to_string(kept.size()) + " largest");
    std::vector<const SetDrawn*> by_area = kept;
    std::stable_sort(by_area.begin(), by_area.end(),
                     [](const SetDrawn* a, const SetDrawn* b) { return a->area > b->area; });
    const double least = by_area[kMaxLegendSets - 1]->area;
    std::vector<const SetDrawn*> largest;
    for (const SetDrawn* set : kept) {
      if (largest.size() < kMaxLegendSets && set->area >= least) largest.push_back(set);
    }
    kept = largest;
  }
  for (const SetDrawn* set : kept) {
    const auto most =
        std::max_element(set->area_by_colour.begin(), set->area_by_colour.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    legend.entries.push_back({colour_of.at(most->first), legend_label(set->name)});
  }
  return legend;
}

}  // namespace shadowgen
