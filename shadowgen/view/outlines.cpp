#include "shadowgen/view/outlines.h"

#include <map>
#include <string>
#include <utility>

#include "detail/merged_shapes.h"

namespace shadowgen {

std::vector<Outline> picture_outlines(const Scene& scene, std::span<const Piece> pieces) {
  // Keyed by (is an object, the object's name or the face's index).
  std::map<std::pair<bool, std::string>, std::size_t> outline_of;
  std::vector<Outline> outlines;
  std::vector<std::vector<clipper::PolygonWithHoles2>> shapes;
  for (const Piece& piece : pieces) {
    if (piece.layer != 0) continue;
    const Face& face = scene.faces[piece.face];
    const bool by_object = !face.origin.object.empty();
    const auto key = by_object ? std::pair(true, face.origin.object)
                               : std::pair(false, std::to_string(piece.face));
    const auto [it, added] = outline_of.emplace(key, outlines.size());
    if (added) {
      outlines.push_back(by_object ? Outline{"", face.origin.object, {}}
                                   : Outline{face.id, "", {}});
      shapes.emplace_back();
    }
    shapes[it->second].push_back(piece.shape);
  }
  for (std::size_t o = 0; o < outlines.size(); ++o) {
    outlines[o].shape = view::detail::merged_shapes(shapes[o]);
  }
  return outlines;
}

}  // namespace shadowgen
