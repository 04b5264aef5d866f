#include "shadowgen/view/render.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "clipper/clip.h"
#include "shadowgen/shadows/light_regions.h"

namespace shadowgen {
namespace {

struct Box {
  double x0 = std::numeric_limits<double>::infinity();
  double y0 = std::numeric_limits<double>::infinity();
  double x1 = -std::numeric_limits<double>::infinity();
  double y1 = -std::numeric_limits<double>::infinity();

  void add(const clipper::Loop2& loop) {
    for (const clipper::Point2& p : loop) {
      x0 = std::min(x0, p.x);
      y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x);
      y1 = std::max(y1, p.y);
    }
  }
  void add(const clipper::PolygonSet2& set) {
    for (const clipper::PolygonWithHoles2& p : set) add(p.outer);
  }
  bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

// The image of one light-set region on one part of a face.
struct RegionImage {
  clipper::PolygonSet2 shape;
  Box box;
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

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

// The part of `polygon` where (p − eye)·forward >= 0: an orthographic camera's near plane
// through its eye. The cut is made in the polygon's own plane, in the chart that drops the
// normal's largest axis; the polygon's own vertices are kept exactly, new ones are lifted
// onto its plane.
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
  const glm::dvec3 a = glm::abs(plane.normal);
  if (!(glm::length(plane.normal) > 0.0)) return {polygon};  // no area: hsr drops it
  const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> original;
  auto to_chart = [&](const hsr::Loop3& loop) {
    clipper::Loop2 out;
    for (const glm::dvec3& p : loop) {
      out.push_back({p[i], p[j]});
      original.emplace(out.back(), p);
    }
    return out;
  };
  clipper::PolygonWithHoles2 flat{to_chart(polygon.outer), {}};
  for (const hsr::Loop3& hole : polygon.holes) flat.holes.push_back(to_chart(hole));
  const glm::dvec3& n = plane.normal;
  // depth = fu·u + fv·v + f0 on the chart.
  const double fu = forward[i] - forward[k] * n[i] / n[k];
  const double fv = forward[j] - forward[k] * n[j] / n[k];
  const double f0 = forward[k] * plane.offset / n[k] - glm::dot(forward, eye);
  Box box;
  box.add(flat.outer);
  const double margin = 0.125 * std::max(box.x1 - box.x0, box.y1 - box.y0) + 1.0;
  const clipper::Loop2 rectangle{{box.x0 - margin, box.y0 - margin},
                                 {box.x1 + margin, box.y0 - margin},
                                 {box.x1 + margin, box.y1 + margin},
                                 {box.x0 - margin, box.y1 + margin}};
  // The rectangle cut by the half-plane depth >= 0 (Sutherland–Hodgman, one plane).
  clipper::Loop2 keep;
  auto depth = [&](const clipper::Point2& q) { return fu * q.x + fv * q.y + f0; };
  for (std::size_t e = 0; e < rectangle.size(); ++e) {
    const clipper::Point2& p = rectangle[e];
    const clipper::Point2& q = rectangle[(e + 1) % rectangle.size()];
    const double dp = depth(p), dq = depth(q);
    if (dp >= 0.0) keep.push_back(p);
    if ((dp < 0.0) != (dq < 0.0)) {
      const double t = dp / (dp - dq);
      keep.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  if (keep.size() < 3) return {};
  auto lift = [&](const clipper::Loop2& loop) {
    hsr::Loop3 out;
    for (const clipper::Point2& q : loop) {
      if (const auto it = original.find(q); it != original.end()) {
        out.push_back(it->second);
        continue;
      }
      glm::dvec3 p(0.0);
      p[i] = q.x;
      p[j] = q.y;
      p[k] = (plane.offset - n[i] * q.x - n[j] * q.y) / n[k];
      out.push_back(p);
    }
    return out;
  };
  std::vector<hsr::Polygon3> front;
  for (const clipper::PolygonWithHoles2& piece : clipper::intersection({flat}, {{keep, {}}})) {
    hsr::Polygon3 p{lift(piece.outer), {}};
    for (const clipper::Loop2& hole : piece.holes) p.holes.push_back(lift(hole));
    // The chart may mirror the plane: keep the part's own orientation (its front side).
    if (glm::dot(hsr::plane_of(p).normal, n) < 0.0) {
      std::reverse(p.outer.begin(), p.outer.end());
      for (hsr::Loop3& hole : p.holes) std::reverse(hole.begin(), hole.end());
    }
    front.push_back(std::move(p));
  }
  return front;
}

}  // namespace

Rgb shade(const Scene& scene, const std::vector<std::size_t>& lights, const glm::dvec3& point,
          const glm::dvec3& normal, const RenderOptions& options) {
  Rgb sum;
  for (const std::size_t index : lights) {
    const Light& light = scene.lights.at(index);
    glm::dvec3 toward;
    double falloff = 1.0;
    if (light.type == LightType::kDirectional) {
      toward = -light.direction;
    } else {
      toward = light.position - point;
      const double d = glm::length(toward);
      if (light.range) {
        const LightRange& r = *light.range;
        if (d >= r.end) {
          falloff = 0.0;
        } else if (d > r.falloff_start) {
          falloff = std::pow(1.0 - (d - r.falloff_start) / (r.end - r.falloff_start), r.exponent);
        }
      }
    }
    const double length = glm::length(toward);
    if (!(length > 0.0)) continue;
    const double cosine = std::max(0.0, glm::dot(normal, toward) / length);
    const double k = cosine * falloff;
    sum.r += light.intensity.x * k;
    sum.g += light.intensity.y * k;
    sum.b += light.intensity.z * k;
  }
  const double weight =
      (1.0 - options.ambient) / static_cast<double>(std::max<std::size_t>(1, scene.lights.size()));
  return {clamp01(options.albedo.r * (options.ambient + weight * sum.r)),
          clamp01(options.albedo.g * (options.ambient + weight * sum.g)),
          clamp01(options.albedo.b * (options.ambient + weight * sum.b))};
}

Picture render(const ShadowedScene& shadowed, const Camera& camera, const RenderOptions& options) {
  const Scene& scene = shadowed.scene;
  if (shadowed.lit.size() != scene.faces.size()) {
    throw std::invalid_argument("the shadowed database's lit polygons are not one list per face");
  }
  for (const auto& per_light : shadowed.lit) {
    if (per_light.size() != scene.lights.size()) {
      throw std::invalid_argument(
          "the shadowed database's lit polygons are not one list per (face, light)");
    }
  }
  const CameraView camera_view(camera, scene, options.width, options.height);
  const hsr::View& view = camera_view.view();

  Picture picture;
  picture.width = options.width;
  picture.height = options.height;
  picture.pixels_per_unit = camera_view.pixels_per_unit();
  picture.background = options.background;

  // 1. Hidden-surface removal on the parents only.
  std::vector<hsr::Polygon3> parents;
  std::vector<std::pair<std::size_t, std::size_t>> owner;  // (face, part) per parent
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t p = 0; p < scene.faces[f].parts.size(); ++p) {
      if (view.is_perspective()) {
        parents.push_back(scene.faces[f].parts[p]);  // hsr cuts at the near plane itself
        owner.emplace_back(f, p);
        continue;
      }
      for (hsr::Polygon3& piece :
           in_front_of(scene.faces[f].parts[p], camera.eye, view.forward())) {
        parents.push_back(std::move(piece));
        owner.emplace_back(f, p);
      }
    }
  }
  picture.stats.parent_polygons = parents.size();
  hsr::VisibleSurfaces visible = hsr::remove_hidden_surfaces(parents, view);
  picture.stats.hsr = visible.stats;

  // Perspective views are clipped to their window by hsr; orthographic ones here.
  std::vector<std::pair<std::size_t, clipper::PolygonWithHoles2>> fragments;
  if (view.is_perspective()) {
    for (hsr::Fragment& fragment : visible.fragments) {
      fragments.emplace_back(fragment.parent, std::move(fragment.shape));
    }
  } else {
    const clipper::PolygonWithHoles2 window = camera_view.window();
    for (hsr::Fragment& fragment : visible.fragments) {
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
  picture.stats.fragments = fragments.size();

  // 2. and 3., face by face (fragments are sorted by parent, parents by face).
  std::size_t current_face = scene.faces.size();
  std::vector<LightRegion> regions;
  std::vector<std::vector<RegionImage>> images;  // [region][part]
  auto add_piece = [&](std::size_t f, std::size_t part, std::size_t parent,
                       const std::vector<std::size_t>& lights, bool back_side,
                       const clipper::PolygonWithHoles2& image) {
    if (!(clipper::area(image) > 0.0)) return;
    const hsr::Plane3& plane = visible.planes[parent];
    Piece piece;
    piece.face = f;
    piece.part = part;
    piece.face_id = scene.faces[f].id;
    piece.lights = lights;
    piece.light_set = light_set_name(scene, lights);
    piece.back_side = back_side;
    piece.colour = shade(scene, lights, centroid_3d(image, view, plane), plane.normal, options);
    piece.shape = to_pixels(image, camera_view);
    picture.pieces.push_back(std::move(piece));
  };

  for (auto& [parent, shape] : fragments) {
    const auto [f, part] = owner[parent];
    const hsr::Plane3& plane = visible.planes[parent];
    const bool front = view.is_perspective() ? plane.signed_distance(view.eye()) > 0.0
                                             : glm::dot(plane.normal, view.forward()) < 0.0;
    if (!front) {
      add_piece(f, part, parent, {}, true, shape);
      continue;
    }
    if (f != current_face) {
      current_face = f;
      const Face& face = scene.faces[f];
      regions = light_regions(shadowed, f);
      images.assign(regions.size(), std::vector<RegionImage>(face.parts.size()));
      for (std::size_t r = 0; r < regions.size(); ++r) {
        if (regions[r].lights.empty()) continue;  // shadow is what the others leave
        for (const LitPolygon& lit : regions[r].polygons) {
          for (clipper::PolygonWithHoles2& p : hsr::project_polygon(lit.polygon, view)) {
            images[r][lit.part].shape.push_back(std::move(p));
          }
        }
        for (RegionImage& image : images[r]) image.box.add(image.shape);
      }
    }
    clipper::PolygonSet2 remaining{shape};
    Box box;
    box.add(remaining);
    for (std::size_t r = 0; r < regions.size() && !remaining.empty(); ++r) {
      const RegionImage& image = images[r][part];
      if (image.shape.empty() || !image.box.overlaps(box)) continue;
      // One subject against the region's polygons: this form of the clip drops the
      // slivers that only rounding makes where two regions' images meet along a seam.
      clipper::PolygonSet2 outside;
      for (const clipper::PolygonWithHoles2& subject : remaining) {
        clipper::ClipResult split = clipper::clip(subject, image.shape);
        ++picture.stats.region_clips;
        for (const clipper::PolygonWithHoles2& inside : split.inside) {
          add_piece(f, part, parent, regions[r].lights, false, inside);
        }
        for (clipper::PolygonWithHoles2& rest : split.outside) outside.push_back(std::move(rest));
      }
      remaining = std::move(outside);
    }
    for (const clipper::PolygonWithHoles2& rest : remaining) {
      add_piece(f, part, parent, {}, false, rest);
    }
  }
  picture.stats.pieces = picture.pieces.size();
  for (const Piece& piece : picture.pieces) picture.stats.back_side_pieces += piece.back_side;
  return picture;
}

}  // namespace shadowgen
