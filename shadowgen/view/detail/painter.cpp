#include "detail/painter.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <utility>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/tiles.h"
#include "hsr/plane_chart.h"
#include "shadowgen/view/map_marks.h"
#include "shadowgen/view/outlines.h"

namespace shadowgen::view::detail {
namespace {

// The most vertices of a region's image clipped whole; larger ones are cut into tiles
// of about half as many (clipper/tiles.h).
constexpr std::size_t kTileVertices = 256;

clipper::Box2 box_of(const clipper::PolygonSet2& set) {
  clipper::Box2 box;
  for (const clipper::PolygonWithHoles2& p : set) box.add(clipper::box_of(p));
  return box;
}

// The image of one region on one part of a face.
struct RegionImage {
  clipper::PolygonSet2 shape;
  clipper::Box2 box;
};

// Is every vertex of `polygon` inside the convex counter-clockwise `window`? A rounded
// test: it only saves clipping fragments that lie well inside.
bool inside_window(const clipper::PolygonWithHoles2& polygon, const clipper::Loop2& window) {
  const std::size_t n = window.size();
  for (const clipper::Point2& p : polygon.outer) {
    for (std::size_t i = 0; i < n; ++i) {
      const clipper::Point2& a = window[i];
      const clipper::Point2& b = window[(i + 1) % n];
      if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) <= 0.0) return false;
    }
  }
  return true;
}

// The area centroid of the 3D region seen at `image` on `plane`; the vertex mean when the
// region has no area to weigh by.
glm::dvec3 centroid_3d(const clipper::PolygonWithHoles2& image, const hsr::View& view,
                       const hsr::Plane3& plane) {
  std::vector<std::vector<glm::dvec3>> loops;
  auto lift = [&](const clipper::Loop2& loop) {
    std::vector<glm::dvec3> out;
    out.reserve(loop.size());
    for (const clipper::Point2& q : loop) {
      if (const std::optional<glm::dvec3> p = view.unproject(q, plane)) out.push_back(*p);
    }
    loops.push_back(std::move(out));
  };
  lift(image.outer);
  for (const clipper::Loop2& hole : image.holes) lift(hole);
  if (loops[0].empty()) return glm::dvec3(0.0);
  const glm::dvec3 o = loops[0][0];
  double weight = 0.0;
  glm::dvec3 moment(0.0);
  for (const std::vector<glm::dvec3>& loop : loops) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const glm::dvec3 a = loop[i] - o, b = loop[(i + 1) % loop.size()] - o;
      // Holes run the other way round, so their triangles weigh negatively.
      const double w = glm::dot(glm::cross(a, b), plane.normal);
      weight += w;
      moment += w * (a + b) / 3.0;
    }
  }
  if (weight != 0.0 && std::isfinite(weight)) {
    const glm::dvec3 c = o + moment / weight;
    if (std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) return c;
  }
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& p : loops[0]) mean += p - o;
  return o + mean / static_cast<double>(loops[0].size());
}

// Pixel coordinates, loops reversed: the map flips orientation, and reversing keeps outer
// loops at positive signed area.
clipper::PolygonWithHoles2 to_pixels(const clipper::PolygonWithHoles2& image,
                                     const CameraView& camera) {
  auto map = [&](const clipper::Loop2& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (auto it = loop.rbegin(); it != loop.rend(); ++it) out.push_back(camera.to_pixels(*it));
    return out;
  };
  clipper::PolygonWithHoles2 pixels{map(image.outer), {}};
  for (const clipper::Loop2& hole : image.holes) pixels.holes.push_back(map(hole));
  return pixels;
}

// The part of `box`, grown by an eighth of its size and one unit on every side, where
// f >= 0 (Sutherland–Hodgman, one line). Fewer than three points when there is none.
clipper::Loop2 nonnegative_part(const hsr::ChartAffine& f, const clipper::Box2& box) {
  const double margin = 0.125 * std::max(box.xmax - box.xmin, box.ymax - box.ymin) + 1.0;
  const clipper::Loop2 rectangle{{box.xmin - margin, box.ymin - margin},
                                 {box.xmax + margin, box.ymin - margin},
                                 {box.xmax + margin, box.ymax + margin},
                                 {box.xmin - margin, box.ymax + margin}};
  clipper::Loop2 keep;
  for (std::size_t e = 0; e < rectangle.size(); ++e) {
    const clipper::Point2& p = rectangle[e];
    const clipper::Point2& q = rectangle[(e + 1) % rectangle.size()];
    const double dp = f.at(p), dq = f.at(q);
    if (dp >= 0.0) keep.push_back(p);
    if ((dp < 0.0) != (dq < 0.0)) {
      const double t = dp / (dp - dq);
      keep.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return keep;
}

// The part of `polygon` where (p − eye)·forward >= 0: an orthographic camera's near plane
// through its eye. The cut is made in the polygon's own plane chart (hsr/plane_chart.h);
// the polygon's own vertices are kept exactly, new ones are lifted onto its plane, and
// the pieces keep the polygon's front side.
std::vector<hsr::Polygon3> in_front_of(const hsr::Polygon3& polygon, const glm::dvec3& eye,
                                       const glm::dvec3& forward) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto visit = [&](const hsr::Loop3& loop) {
    for (const glm::dvec3& p : loop) {
      const double z = glm::dot(p - eye, forward);
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
  };
  visit(polygon.outer);
  for (const hsr::Loop3& hole : polygon.holes) visit(hole);
  if (lo >= 0.0) return {polygon};
  if (hi <= 0.0) return {};
  const hsr::Plane3 plane = hsr::plane_of(polygon);
  if (!(glm::length(plane.normal) > 0.0)) return {polygon};  // no area: hsr drops it
  hsr::ChartedPlane chart(plane.normal, polygon.outer.front(), hsr::ChartFrom::kWorld);
  const clipper::PolygonWithHoles2 flat = chart.flatten_known(polygon);
  hsr::ChartAffine depth = chart.dot_on_plane(forward);
  depth.c -= glm::dot(forward, eye);
  const clipper::Loop2 keep = nonnegative_part(depth, clipper::box_of(flat));
  if (keep.size() < 3) return {};
  return chart.lift(clipper::intersection({flat}, {{keep, {}}}));
}

// The face parts hidden-surface removal is given, each with the (face, part) it is of.
struct Parents {
  std::vector<hsr::Polygon3> polygons;
  std::vector<std::pair<std::size_t, std::size_t>> owner;
};

Parents parents_of(const Scene& scene, const glm::dvec3& eye, const hsr::View& view) {
  Parents parents;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t p = 0; p < scene.faces[f].parts.size(); ++p) {
      if (view.is_perspective()) {
        parents.polygons.push_back(scene.faces[f].parts[p]);  // hsr cuts at the near plane
        parents.owner.emplace_back(f, p);
        continue;
      }
      for (hsr::Polygon3& piece : in_front_of(scene.faces[f].parts[p], eye, view.forward())) {
        parents.polygons.push_back(std::move(piece));
        parents.owner.emplace_back(f, p);
      }
    }
  }
  return parents;
}

using Fragments = std::vector<std::pair<std::size_t, clipper::PolygonWithHoles2>>;

// The visible fragments within the picture with their parents, sorted by parent.
// Perspective views are clipped to their window by hsr; orthographic ones here.
Fragments fragments_in_picture(std::vector<hsr::Fragment>& visible, const CameraView& camera) {
  Fragments fragments;
  if (camera.view().is_perspective()) {
    for (hsr::Fragment& fragment : visible) {
      fragments.emplace_back(fragment.parent, std::move(fragment.shape));
    }
  } else {
    const clipper::PolygonWithHoles2 window = camera.window();
    for (hsr::Fragment& fragment : visible) {
      if (inside_window(fragment.shape, window.outer)) {
        fragments.emplace_back(fragment.parent, std::move(fragment.shape));
        continue;
      }
      for (clipper::PolygonWithHoles2& piece : clipper::intersection({fragment.shape}, {window})) {
        fragments.emplace_back(fragment.parent, std::move(piece));
      }
    }
  }
  std::stable_sort(fragments.begin(), fragments.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  return fragments;
}

// Steps 2 and 3 of render.h: fragments split by their face's regions, given their
// region's look and mapped to pixels. Fragments come face by face; each face's regions are
// projected once, when its first fragment comes.
class Painter {
 public:
  Painter(const Scene& scene, FaceTiling& tiling, const CameraView& camera, const Parents& parents,
          const std::vector<hsr::Plane3>& planes, Picture& picture)
      : scene_(scene),
        tiling_(tiling),
        camera_(camera),
        parents_(parents),
        planes_(planes),
        picture_(picture),
        current_face_(scene.faces.size()) {}

  void paint(std::size_t parent, const clipper::PolygonWithHoles2& shape) {
    const auto [f, part] = parents_.owner[parent];
    const hsr::View& view = camera_.view();
    const hsr::Plane3& plane = planes_[parent];
    const bool front = view.is_perspective() ? plane.signed_distance(view.eye()) > 0.0
                                             : glm::dot(plane.normal, view.forward()) < 0.0;
    if (!front) {
      add_piece(parent, kNoRegion, true, shape);
      return;
    }
    if (f != current_face_) project_regions(f);
    if (tiling_.layered()) {
      paint_layers(parent, shape);
      return;
    }
    clipper::PolygonSet2 remaining{shape};
    const clipper::Box2 box = box_of(remaining);
    for (std::size_t r = 0; r < images_.size() && !remaining.empty(); ++r) {
      const RegionImage& image = images_[r][part];
      // A region whose box only touches the fragment's covers none of its area.
      if (image.shape.empty() || !image.box.overlaps(box)) continue;
      remaining = split_off(parent, r, remaining);
    }
    for (const clipper::PolygonWithHoles2& rest : remaining) {
      add_piece(parent, tiling_.rest(), false, rest);
    }
  }

 private:
  void project_regions(std::size_t f) {
    current_face_ = f;
    tiling_.load(f);
    images_.assign(tiling_.size(), std::vector<RegionImage>(scene_.faces[f].parts.size()));
    for (std::size_t r = 0; r < images_.size(); ++r) {
      if (r == tiling_.rest()) continue;  // it gets what the others leave
      for (const LitPolygon& lit : tiling_.polygons(r)) {
        for (clipper::PolygonWithHoles2& p : hsr::project_polygon(lit.polygon, camera_.view())) {
          // A region with a hole per building in front of it, as tiles: each fragment is
          // then clipped by the tiles its box meets, not by the whole region.
          for (clipper::PolygonWithHoles2& tile : clipper::split_into_tiles(p, kTileVertices)) {
            images_[r][lit.part].shape.push_back(std::move(tile));
          }
        }
      }
      for (RegionImage& image : images_[r]) image.box = box_of(image.shape);
    }
  }

  // The fragment whole, then what of it lies in each layer.
  void paint_layers(std::size_t parent, const clipper::PolygonWithHoles2& shape) {
    add_piece(parent, kNoRegion, false, shape);
    const clipper::Box2 box = clipper::box_of(shape);
    for (std::size_t r = 0; r < images_.size(); ++r) {
      const RegionImage& image = images_[r][parents_.owner[parent].second];
      if (image.shape.empty() || !image.box.overlaps(box)) continue;
      ++picture_.stats.region_clips;
      for (const clipper::PolygonWithHoles2& inside : clipper::clip(shape, image.shape).inside) {
        add_piece(parent, r, false, inside);
      }
    }
  }

  // Paints what of `remaining` lies in region r; returns the rest.
  clipper::PolygonSet2 split_off(std::size_t parent, std::size_t r,
                                 const clipper::PolygonSet2& remaining) {
    const RegionImage& image = images_[r][parents_.owner[parent].second];
    // One subject against the region's polygons: this form of the clip drops the
    // slivers that only rounding makes where two regions' images meet along a seam.
    clipper::PolygonSet2 outside;
    for (const clipper::PolygonWithHoles2& subject : remaining) {
      clipper::ClipResult split = clipper::clip(subject, image.shape);
      ++picture_.stats.region_clips;
      for (const clipper::PolygonWithHoles2& inside : split.inside) {
        add_piece(parent, r, false, inside);
      }
      for (clipper::PolygonWithHoles2& rest : split.outside) outside.push_back(std::move(rest));
    }
    return outside;
  }

  void add_piece(std::size_t parent, std::size_t region, bool back_side,
                 const clipper::PolygonWithHoles2& image) {
    if (!(clipper::area(image) > 0.0)) return;
    const hsr::Plane3& plane = planes_[parent];
    Piece piece;
    piece.face = parents_.owner[parent].first;
    piece.part = parents_.owner[parent].second;
    piece.back_side = back_side;
    tiling_.style(piece, region, centroid_3d(image, camera_.view(), plane), plane.normal);
    piece.shape = to_pixels(image, camera_);
    picture_.pieces.push_back(std::move(piece));
  }

  const Scene& scene_;
  FaceTiling& tiling_;
  const CameraView& camera_;
  const Parents& parents_;
  const std::vector<hsr::Plane3>& planes_;
  Picture& picture_;
  std::size_t current_face_;
  std::vector<std::vector<RegionImage>> images_;  // [region][part]
};

}  // namespace

Picture paint_picture(const Scene& scene, const Camera& camera, const RenderOptions& options,
                      FaceTiling& tiling) {
  const CameraView camera_view(camera, scene, options.width, options.height);
  const hsr::View& view = camera_view.view();

  Picture picture;
  picture.width = options.width;
  picture.height = options.height;
  picture.pixels_per_unit = camera_view.pixels_per_unit();
  picture.background = options.background;

  // 1. Hidden-surface removal on the parents only.
  const Parents parents = parents_of(scene, camera.eye, view);
  picture.stats.parent_polygons = parents.polygons.size();
  hsr::VisibleSurfaces visible = hsr::remove_hidden_surfaces(parents.polygons, view);
  picture.stats.hsr = visible.stats;
  const Fragments fragments = fragments_in_picture(visible.fragments, camera_view);
  picture.stats.fragments = fragments.size();

  // 2. and 3., face by face (fragments are sorted by parent, parents by face).
  Painter painter(scene, tiling, camera_view, parents, visible.planes, picture);
  for (const auto& [parent, shape] : fragments) painter.paint(parent, shape);
  if (tiling.layered()) {
    // The base first, then each layer whole (the painter met them fragment by fragment).
    std::stable_sort(picture.pieces.begin(), picture.pieces.end(),
                     [](const Piece& a, const Piece& b) { return a.layer < b.layer; });
  }
  picture.stats.pieces = picture.pieces.size();
  for (const Piece& piece : picture.pieces) picture.stats.back_side_pieces += piece.back_side;

  // The map's outlines and marks (outlines.h, map_marks.h).
  picture.outlines = picture_outlines(scene, picture.pieces);
  picture.north = north_arrow(scene, camera, camera_view);
  if (picture.pixels_per_unit > 0.0) {
    picture.scale_bar = scale_bar(picture.pixels_per_unit, picture.width, scene.site.has_value());
  }
  return picture;
}

}  // namespace shadowgen::view::detail
