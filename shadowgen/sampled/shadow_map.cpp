#include "shadowgen/sampled/shadow_map.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <optional>
#include <vector>

#include "detail/depth_map.h"
#include "detail/map_view.h"

namespace shadowgen::sampled {
namespace {

using detail::DepthMap;
using detail::Frame;
using detail::frame_along;
using detail::TexelBox;

}  // namespace

// Which occluders' images reach each tile of a whole view's map (resolution / 256 texels a
// side, at least 1):
// what a face's own map draws (ShadowMap::lit_face).
struct ShadowMap::Tiles {
  int tile = 1, columns = 0, rows = 0;
  std::vector<std::vector<std::uint32_t>> cells;  // [row · columns + column]: occluder indices

  // Calls visit(cell's occluders) for each tile that `box` (texel coordinates) reaches,
  // the view's edge tiles standing for all beyond it.
  template <typename Visit>
  void for_each_under(const TexelBox& box, Visit&& visit) {
    const auto index = [this](double t, int count) {
      return std::clamp(static_cast<int>(std::floor(std::clamp(t, 0.0, 1e9) / tile)), 0, count - 1);
    };
    for (int r = index(box.v0, rows); r <= index(box.v1, rows); ++r) {
      for (int c = index(box.u0, columns); c <= index(box.u1, columns); ++c) {
        visit(cells[static_cast<std::size_t>(r) * columns + c]);
      }
    }
  }

  void add(std::uint32_t occluder, const TexelBox& box, int nx, int ny) {
    // A face's map reaches kMarginTexels past the face, so past the view's edge too.
    const double m = kMarginTexels + 1.0;
    if (!(box.u1 >= -m && box.u0 <= nx + m && box.v1 >= -m && box.v0 <= ny + m)) return;
    for_each_under(box, [occluder](std::vector<std::uint32_t>& cell) { cell.push_back(occluder); });
  }
};

ShadowMap::ShadowMap(const Light& light, std::span<const Triangle3> occluders, int resolution)
    : occluders_(occluders.begin(), occluders.end()), resolution_(resolution) {
  perspective_ = light.type == LightType::kPoint;
  view_count_ = perspective_ ? 6 : 1;
  views_ = std::make_unique<View[]>(static_cast<std::size_t>(view_count_));
  tiles_ = std::make_unique<Tiles[]>(static_cast<std::size_t>(view_count_));
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const Triangle3& t : occluders) {
    for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
      lo = glm::min(lo, *v);
      hi = glm::max(hi, *v);
    }
  }
  const double diagonal = occluders.empty() ? 0.0 : glm::length(hi - lo);
  // Each map reaches kMarginTexels past what it must show (the box of the occluders, a
  // cube face's 90°), as a fraction of its half-width: so that a sample at its edge, at a
  // cube map's seam included, is filtered with texels that hold what the light sees there
  // rather than the edge's own texels repeated.
  const double margin = 2.0 * kMarginTexels / resolution;
  const double half = 0.5 * resolution;
  if (perspective_) {
    eye_ = light.position;
    static const std::array<glm::dvec3, 6> kAxes = {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0),
                                                    glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0),
                                                    glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)};
    for (int k = 0; k < 6; ++k) {
      View& view = views_[k];
      view.frame = frame_along(kAxes[k]);
      view.origin = eye_;
      view.perspective = true;
      // x/z and y/z in [−spread, spread], spread a margin past 1.
      const double spread = 1.0 + margin;
      view.tx = view.ty = spread / half;
      view.x0 = view.y0 = -spread;
    }
  } else {
    View& view = views_[0];
    view.frame = frame_along(light.direction);
    view.origin = occluders.empty() ? glm::dvec3(0.0) : 0.5 * (lo + hi);
    double extent = 0.0;
    for (const Triangle3& t : occluders) {
      for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
        const glm::dvec3 e = view.frame.to(*v - view.origin);
        extent = std::max({extent, std::fabs(e.x), std::fabs(e.y)});
      }
    }
    // A hair wider than the box, so that its outermost vertices fall inside the last texel,
    // and the margin.
    if (extent > 0.0) view.tx = view.ty = 2.0 * extent * (1.0 + 1e-9) * (1.0 + margin) / resolution;
    view.x0 = view.y0 = -half * view.tx;
  }
  near_ = std::max(1e-9 * diagonal, DBL_MIN);
  if (perspective_) {
    // Each occluder's bounding cone from the light, for the maps of faces across the cube's
    // seams: about the direction of its vertices' mean, through its bounding sphere
    // (every way where the sphere holds the light).
    cones_.reserve(occluders.size());
    for (const Triangle3& t : occluders) {
      const glm::dvec3 middle = (t.a + t.b + t.c) / 3.0;
      const double radius = std::max(
          {glm::length(t.a - middle), glm::length(t.b - middle), glm::length(t.c - middle)});
      const double distance = glm::length(middle - eye_);
      Cone cone;
      if (distance > radius * (1.0 + 1e-9)) {
        cone.axis = (middle - eye_) / distance;
        cone.sin_alpha = radius * (1.0 + 1e-9) / distance;
        cone.cos_alpha = std::sqrt(1.0 - cone.sin_alpha * cone.sin_alpha);
      }
      cones_.push_back(cone);
    }
  }
  const int tile = std::max(1, resolution / 256);
  for (int k = 0; k < view_count_; ++k) {
    View& view = views_[k];
    view.map = DepthMap(resolution, resolution);
    Tiles& tiles = tiles_[k];
    tiles.tile = tile;
    tiles.columns = tiles.rows = (resolution + tile - 1) / tile;
    tiles.cells.resize(static_cast<std::size_t>(tiles.columns) * tiles.rows);
    for (std::size_t o = 0; o < occluders.size(); ++o) {
      const Triangle3& t = occluders[o];
      const std::optional<TexelBox> box =
          view.draw({view.frame.to(t.a - view.origin), view.frame.to(t.b - view.origin),
                     view.frame.to(t.c - view.origin)},
                    near_);
      if (box) tiles.add(static_cast<std::uint32_t>(o), *box, resolution, resolution);
    }
  }
}

ShadowMap::~ShadowMap() = default;

int ShadowMap::view_of(const glm::dvec3& point) const {
  if (!perspective_) return 0;
  // The cube face the point's direction from the light falls in: its largest component.
  const glm::dvec3 d = point - eye_;
  const glm::dvec3 a = glm::abs(d);
  return a.x >= a.y && a.x >= a.z ? (d.x > 0 ? 0 : 1)
         : a.y >= a.z             ? (d.y > 0 ? 2 : 3)
                                  : (d.z > 0 ? 4 : 5);
}

double ShadowMap::lit(const glm::dvec3& point, const glm::dvec3& normal) const {
  return whole_lit(point, normal, nullptr);
}

double ShadowMap::whole_lit(const glm::dvec3& point, const glm::dvec3& normal, bool* own) const {
  const View& view = views_[view_of(point)];
  return view.lit(view.frame.to(point - view.origin), view.frame.to(normal), own);
}

void ShadowMap::lit_face(std::span<const Triangle3> face, std::span<const glm::dvec3> points,
                         std::span<const glm::dvec3> normals, std::span<double> out) const {
  const auto whole_view = [&] {
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = lit(points[i], normals[i]);
  };
  if (face.empty() || points.empty()) return whole_view();
  // The frame the face's map turns: the whole view's that holds the face, whose tiles tell
  // which occluders reach it; for a face of a point light's that straddles a seam of the
  // cube, a perspective view of its own towards the face's middle, every occluder drawn.
  const int k = view_of(face.front().a);
  bool one_view = true;
  glm::dvec3 middle(0.0);
  for (const Triangle3& t : face) {
    for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
      one_view = one_view && view_of(*v) == k;
      middle += *v;
    }
  }
  const View& whole = views_[k];
  const Frame base = one_view
                         ? whole.frame
                         : frame_along(middle / (3.0 * static_cast<double>(face.size())) - eye_);
  const auto image_of = [&](const glm::dvec3& e) {
    return whole.perspective ? glm::dvec2(e.x / e.z, e.y / e.z) : glm::dvec2(e.x, e.y);
  };
  // The face's image in that frame, and its principal axis: the map's texels are cut
  // along and across it, so that a sliver lying askew is cut finely across, not along.
  thread_local std::vector<glm::dvec2> image;
  image.clear();
  glm::dvec2 mean(0.0);
  double zmin = INFINITY, zmax = -INFINITY;
  for (const Triangle3& t : face) {
    for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
      const glm::dvec3 e = base.to(*v - whole.origin);
      // A face reaching nearer to a point light than the near distance keeps the cube.
      if (whole.perspective && !(e.z >= near_)) return whole_view();
      image.push_back(image_of(e));
      mean += image.back();
      zmin = std::min(zmin, e.z);
      zmax = std::max(zmax, e.z);
    }
  }
  mean /= static_cast<double>(image.size());
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (const glm::dvec2& p : image) {
    const glm::dvec2 d = p - mean;
    sxx += d.x * d.x;
    sxy += d.x * d.y;
    syy += d.y * d.y;
  }
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  const double cosine = std::cos(angle), sine = std::sin(angle);
  const auto turned = [&](const glm::dvec2& p) {
    return glm::dvec2(cosine * p.x + sine * p.y, -sine * p.x + cosine * p.y);
  };
  TexelBox box;  // in the turned frame's image coordinates
  for (const glm::dvec2& p : image) box.add(turned(p));
  // Its extent in the whole view's texels.
  const double w = (box.u1 - box.u0) / whole.tx, h = (box.v1 - box.v0) / whole.ty;
  const double least = face_texels(resolution_);
  if (!(w > 0.0 && h > 0.0) || (one_view && w >= least && h >= least)) return whole_view();
  // Where every tap of every point shows the face's own plane, the whole map has seen the
  // face lit throughout: a map of its own would find the same.
  bool own = true;
  for (std::size_t i = 0; i < points.size() && own; ++i) {
    out[i] = whole_lit(points[i], normals[i], &own);
  }
  if (own) return;
  // The face's own map: its image's box and kMarginTexels about it, each side at least
  // `least` texels (those of the whole view where it has more); an orthographic one
  // measures depth from the face's middle, where its floats are finest.
  // One per thread, its map's storage kept from face to face.
  thread_local View local;
  local.perspective = whole.perspective;
  local.frame = base;
  local.frame.right = cosine * base.right + sine * base.up;
  local.frame.up = -sine * base.right + cosine * base.up;
  local.origin = whole.origin;
  if (!local.perspective) local.origin += base.forward * (0.5 * (zmin + zmax));
  local.tx = whole.tx * (w / std::max(w, least));
  local.ty = whole.ty * (h / std::max(h, least));
  local.x0 = box.u0 - kMarginTexels * local.tx;
  local.y0 = box.v0 - kMarginTexels * local.ty;
  const int nx = static_cast<int>(std::ceil(std::max(w, least) + 2.0 * kMarginTexels));
  const int ny = static_cast<int>(std::ceil(std::max(h, least) + 2.0 * kMarginTexels));
  local.map.reset(nx, ny);
  // An occluder wholly farther from the light than the face's farthest point by more than
  // the reach of its plane (lit()'s clamp) makes every tap it covers pass, as an empty texel
  // does: it is not drawn, and the ground far behind a small face costs nothing.
  const double reach = kPlaneReachTexels * std::max(local.tx, local.ty);
  const double beyond = local.perspective ? zmax * (1.0 + reach) : 0.5 * (zmax - zmin) + reach;
  const auto draw = [&](const Triangle3& t) {
    const glm::dvec3 a = t.a - local.origin, b = t.b - local.origin, c = t.c - local.origin;
    const glm::dvec3& forward = local.frame.forward;
    if (std::min({glm::dot(a, forward), glm::dot(b, forward), glm::dot(c, forward)}) > beyond) {
      return;
    }
    local.draw({local.frame.to(a), local.frame.to(b), local.frame.to(c)}, near_);
  };
  if (!one_view) {
    // Those whose bounding cones from the light meet the cone about the face's map: the
    // angle between their axes at most the sum of the half-angles, cos β ≥ cos(θ + α).
    const glm::dvec3& axis = local.frame.forward;
    double cos_theta = 1.0;
    for (const double x : {local.x0, local.x0 + nx * local.tx}) {
      for (const double y : {local.y0, local.y0 + ny * local.ty}) {
        const glm::dvec3 corner = x * local.frame.right + y * local.frame.up + axis;
        cos_theta = std::min(cos_theta, glm::dot(axis, corner) / glm::length(corner));
      }
    }
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    for (std::size_t o = 0; o < occluders_.size(); ++o) {
      const Cone& cone = cones_[o];
      // θ < π/2 (the map's corners lie in front of the light) and α ≤ π/2, so θ + α < π.
      if (cone.sin_alpha < 0.0 || glm::dot(cone.axis, axis) >= cos_theta * cone.cos_alpha -
                                                                   sin_theta * cone.sin_alpha -
                                                                   1e-12) {
        draw(occluders_[o]);
      }
    }
  } else {
    // What the whole view's tiles under the face's map hold (its corners turned back into
    // the whole view's texels, and a texel more), each occluder once: a stamp per occluder,
    // the call's number where this call has drawn it (numbers only grow on a thread).
    TexelBox under;
    for (const double x : {local.x0, local.x0 + nx * local.tx}) {
      for (const double y : {local.y0, local.y0 + ny * local.ty}) {
        const glm::dvec2 p(cosine * x - sine * y, sine * x + cosine * y);
        under.add({(p.x - whole.x0) / whole.tx, (p.y - whole.y0) / whole.ty});
      }
    }
    under.u0 -= 1.0;
    under.u1 += 1.0;
    under.v0 -= 1.0;
    under.v1 += 1.0;
    thread_local std::vector<std::uint64_t> stamps;
    thread_local std::uint64_t call = 0;
    ++call;
    if (stamps.size() < occluders_.size()) stamps.resize(occluders_.size(), 0);
    tiles_[k].for_each_under(under, [&](const std::vector<std::uint32_t>& cell) {
      for (const std::uint32_t o : cell) {
        if (stamps[o] == call) continue;
        stamps[o] = call;
        draw(occluders_[o]);
      }
    });
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    out[i] = local.lit(local.frame.to(points[i] - local.origin), local.frame.to(normals[i]));
  }
}

}  // namespace shadowgen::sampled
