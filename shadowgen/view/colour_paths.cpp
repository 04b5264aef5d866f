#include "shadowgen/view/colour_paths.h"

#include <map>
#include <tuple>

#include "detail/colour_hex.h"
#include "detail/merged_shapes.h"

namespace shadowgen {

std::vector<ColourPath> colour_paths(const Picture& picture) {
  using Key = std::tuple<std::size_t, std::string, std::string, bool, std::string, bool>;
  std::map<Key, std::size_t> group_of;
  std::vector<ColourPath> paths;
  std::vector<std::vector<clipper::PolygonWithHoles2>> shapes;
  for (const Piece& piece : picture.pieces) {
    std::string hex;
    detail::append_colour(hex, piece.colour);
    const Key key{piece.layer,    hex, piece.light_set, piece.sun_hours.has_value(), piece.band,
                  piece.back_side};
    const auto [it, added] = group_of.emplace(key, paths.size());
    if (added) {
      ColourPath path;
      path.layer = piece.layer;
      path.colour = piece.colour;
      path.light_set = piece.light_set;
      path.sun_hours = piece.sun_hours.has_value();
      path.band = piece.band;
      path.back_side = piece.back_side;
      paths.push_back(std::move(path));
      shapes.emplace_back();
    }
    shapes[it->second].push_back(piece.shape);
    ++paths[it->second].pieces;
  }
  for (std::size_t g = 0; g < paths.size(); ++g) {
    paths[g].shape = detail::merged_shapes(shapes[g]);
  }
  return paths;
}

}  // namespace shadowgen
