#include "coplanar_receivers.h"

#include <algorithm>
#include <optional>
#include <unordered_map>

#include "clipper/box.h"
#include "hsr/convex_window.h"
#include "hsr/hidden_surface.h"
#include "hsr/parallel.h"
#include "hsr/spatial_grid.h"
#include "part_failure.h"

namespace shadowgen::shadows::detail {
namespace {

// The visible pieces of one coplanar group in a grid of their boxes: a receiver clips
// only the pieces whose box overlaps its image's (a ground of 16,641 coplanar tiles would
// otherwise clip every tile against every other). Boxes that only touch hold regions that
// share no area, so their intersection would be empty anyway.
class GroupPieces {
 public:
  GroupPieces(const std::vector<std::size_t>& members,
              const std::vector<clipper::PolygonSet2>& seen) {
    for (std::size_t m : members) {
      for (const auto& piece : seen[m]) {
        pieces_.push_back({m, &piece});
        boxes_.push_back(clipper::box_of(piece));
        extent_.add(boxes_.back());
      }
    }
    if (pieces_.empty()) return;
    grid_.emplace(extent_, pieces_.size());
    for (std::size_t i = 0; i < pieces_.size(); ++i) grid_->insert(i, boxes_[i]);
  }

  bool empty() const { return pieces_.empty(); }

  // The pieces of other members than `receiver` within `image`, the receiver's image,
  // appended to `out`. Not when empty().
  // Not when empty(). Calls may run in parallel.
  void within(std::size_t receiver, const clipper::PolygonSet2& image,
              clipper::PolygonSet2& out) const {
    clipper::Box2 box;
    std::vector<hsr::ConvexWindow> windows;
    for (const auto& p : image) {
      box.add(clipper::box_of(p));
      windows.emplace_back(p);
    }
    std::vector<std::size_t> near;
    grid_->query_shared(box, near);
    // Once each, in the pieces' own order, so the result does not depend on the grid's.
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (std::size_t i : near) {
      if (pieces_[i].owner == receiver || !box.overlaps(boxes_[i])) continue;
      // The image's parts are disjoint: the piece within each, in turn.
      const clipper::PolygonWithHoles2& piece = *pieces_[i].shape;
      for (const hsr::ConvexWindow& window : windows) {
        std::optional<clipper::ClipResult> met = window.clip_unless_apart(piece);
        if (!met) continue;
        for (auto& q : met->inside) out.push_back(std::move(q));
      }
    }
  }

 private:
  struct Owned {
    std::size_t owner;  // receiver
    const clipper::PolygonWithHoles2* shape;
  };
  std::vector<Owned> pieces_;
  std::vector<clipper::Box2> boxes_;
  clipper::Box2 extent_;
  std::optional<hsr::SpatialGrid> grid_;  // of the boxes, when there are pieces
};

// The receivers of each coplanar group of two or more.
std::unordered_map<int, std::vector<std::size_t>> coplanar_receivers(const Receivers& receivers) {
  std::unordered_map<int, std::vector<std::size_t>> groups;
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    const int g = receivers.coplanar()[k];
    if (g >= 0) groups[g].push_back(k);
  }
  std::erase_if(groups, [](const auto& group) { return group.second.size() < 2; });
  return groups;
}

}  // namespace

std::vector<clipper::PolygonSet2> seen_on_shared_planes(
    const Receivers& receivers, const hsr::View& view,
    const std::vector<clipper::PolygonSet2>& seen) {
  std::vector<clipper::PolygonSet2> extra(receivers.size());
  const std::span<const hsr::Polygon3> polygons = receivers.polygons();
  for (const auto& group : coplanar_receivers(receivers)) {
    const std::vector<std::size_t>& members = group.second;
    const GroupPieces pieces(members, seen);
    if (pieces.empty()) continue;
    // The members in parallel (a city's grounds are one group): each writes its own list.
    hsr::for_each_in_parallel(members.size(), [&](std::size_t i) {
      const std::size_t k = members[i];
      if (!receivers.lit_side(k)) return;
      on_part(receivers.part(k), [&] {
        const clipper::PolygonSet2 image =
            hsr::project_polygon(polygons[k], view, receivers.planes()[k]);
        if (!image.empty()) pieces.within(k, image, extra[k]);
      });
    });
  }
  return extra;
}

}  // namespace shadowgen::shadows::detail
