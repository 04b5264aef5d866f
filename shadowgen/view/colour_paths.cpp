#include "shadowgen/view/colour_paths.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <tuple>
#include <utility>

#include "detail/colour_hex.h"
#include "detail/merged_shapes.h"

namespace shadowgen {

namespace {

// The tile of a piece: that of its bounding box's least corner.
std::pair<long, long> tile_of(const clipper::PolygonWithHoles2& shape) {
  double x = shape.outer.front().x, y = shape.outer.front().y;
  for (const clipper::Point2& p : shape.outer) {
    x = std::min(x, p.x);
    y = std::min(y, p.y);
  }
  return {static_cast<long>(std::floor(x / kMergeTile)),
          static_cast<long>(std::floor(y / kMergeTile))};
}

// A map's piece, coloured by its band (Piece::band) rather than its light set.
bool banded(const Piece& piece) { return piece.sun_hours || piece.kwh_per_m2; }

}  // namespace

std::vector<ColourPath> colour_paths(const Picture& picture) {
  using Key = std::tuple<std::size_t, std::string, std::string, bool, std::string, bool>;
  std::map<Key, std::size_t> group_of;
  std::vector<ColourPath> paths;
  // Per path, its pieces by tile.
  std::vector<std::map<std::pair<long, long>, std::vector<clipper::PolygonWithHoles2>>> shapes;
  for (const Piece& piece : picture.pieces) {
    std::string hex;
    view::detail::append_colour(hex, piece.colour);
    const Key key{piece.layer, hex, piece.light_set, banded(piece), piece.band, piece.back_side};
    const auto [it, added] = group_of.emplace(key, paths.size());
    if (added) {
      ColourPath path;
      path.layer = piece.layer;
      path.colour = piece.colour;
      path.light_set = piece.light_set;
      path.banded = banded(piece);
      path.band = piece.band;
      path.back_side = piece.back_side;
      paths.push_back(std::move(path));
      shapes.emplace_back();
    }
    if (!piece.shape.outer.empty()) {
      shapes[it->second][tile_of(piece.shape)].push_back(piece.shape);
    }
    ++paths[it->second].pieces;
  }
  for (std::size_t g = 0; g < paths.size(); ++g) {
    for (const auto& [tile, pieces] : shapes[g]) {
      clipper::PolygonSet2 merged = view::detail::merged_shapes(pieces);
      paths[g].shape.insert(paths[g].shape.end(), std::make_move_iterator(merged.begin()),
                            std::make_move_iterator(merged.end()));
    }
  }
  return paths;
}

}  // namespace shadowgen
