#include "piece_split.h"

#include <cstddef>
#include <utility>

#include "clipper/clip.h"

namespace shadowgen::detail {

LitClips::LitClips(std::vector<clipper::PolygonWithHoles2> clips) : clips_(std::move(clips)) {
  boxes_.reserve(clips_.size());
  for (const clipper::PolygonWithHoles2& c : clips_) boxes_.push_back(clipper::box_of(c));
}

void LitClips::split(const clipper::PolygonSet2& pieces, clipper::PolygonSet2& inside,
                     clipper::PolygonSet2& outside) const {
  std::vector<std::size_t> near;
  std::vector<clipper::PolygonWithHoles2> some;
  for (const clipper::PolygonWithHoles2& piece : pieces) {
    const clipper::Box2 box = clipper::box_of(piece);
    near.clear();
    for (std::size_t c = 0; c < clips_.size(); ++c) {
      if (boxes_[c].overlaps(box)) near.push_back(c);
    }
    if (near.empty()) {
      outside.push_back(piece);
      continue;
    }
    // Every lit polygon near: clipped against them in place, without copies.
    if (near.size() < clips_.size()) {
      some.clear();
      for (const std::size_t c : near) some.push_back(clips_[c]);
    }
    clipper::ClipResult r =
        clipper::clip(piece, near.size() == clips_.size() ? std::span(clips_) : std::span(some));
    for (auto& p : r.inside) inside.push_back(std::move(p));
    for (auto& p : r.outside) outside.push_back(std::move(p));
  }
}

}  // namespace shadowgen::detail
