#include "shadowgen/shadows/generate.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <glm/geometric.hpp>
#include <mutex>
#include <span>
#include <thread>
#include <unordered_map>

#include "clipper/box.h"
#include "clipper/merge.h"
#include "detail/coplanar_groups.h"
#include "detail/grazing_light.h"
#include "detail/part_plane.h"
#include "hsr/convex_window.h"
#include "hsr/hidden_surface.h"
#include "hsr/spatial_grid.h"
#include "shadowgen/shadows/light_views.h"

namespace shadowgen {
namespace {

// Every part of every face, flattened: hidden-surface removal works on these.
struct Parts {
  std::vector<hsr::Polygon3> polygons;
  std::vector<hsr::Plane3> planes;
  std::vector<std::size_t> face;  // owner face index
  std::vector<std::size_t> part;  // index among the owner's parts
  std::vector<int> coplanar;      // detail::coplanar_groups
  glm::dvec3 centre{0.0};
};

Parts flatten(const Scene& scene) {
  Parts parts;
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t k = 0; k < scene.faces[f].parts.size(); ++k) {
      const hsr::Polygon3& p = scene.faces[f].parts[k];
      parts.polygons.push_back(p);
      parts.part.push_back(k);
      parts.planes.push_back(hsr::plane_of(p));
      parts.face.push_back(f);
      for (const glm::dvec3& v : p.outer) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
    }
  }
  if (!parts.polygons.empty()) parts.centre = 0.5 * (lo + hi);
  parts.coplanar = detail::coplanar_groups(parts.polygons, parts.planes);
  return parts;
}

// Does the light reach the front side of this plane at all? A light in the plane (or
// parallel to it) leaves it unlit, as the spec settles.
bool faces_light(const hsr::Plane3& plane, const Light& light) {
  if (glm::length(plane.normal) == 0.0) return false;
  if (light.type == LightType::kDirectional) return glm::dot(plane.normal, light.direction) < 0.0;
  return plane.signed_distance(light.position) > 0.0;
}

// Maps image points of one view back onto a part's plane: the part's own vertices come
// back exactly, other points are cast onto the plane along the light's ray.
class BackProjector {
 public:
  BackProjector(const hsr::View& view, const hsr::Polygon3& polygon, const hsr::Plane3& plane)
      : view_(view), normal_(plane.normal) {
    auto add = [this](const hsr::Loop3& loop) {
      for (const glm::dvec3& v : loop) original_.emplace(view_.project(v), v);
    };
    add(polygon.outer);
    for (const hsr::Loop3& h : polygon.holes) add(h);
    // The plane relative to the eye: a scene far from the origin keeps its precision.
    offset_from_eye_ = view_.offset_from_eye(polygon.outer, normal_);
  }

  hsr::Loop3 lift(const clipper::Loop2& loop) const {
    hsr::Loop3 out;
    out.reserve(loop.size());
    for (const clipper::Point2& q : loop) {
      const auto it = original_.find(q);
      if (it != original_.end()) {
        out.push_back(it->second);
      } else if (const auto d = view_.unproject_offset(q, normal_, offset_from_eye_)) {
        out.push_back(view_.eye() + *d);
      }
    }
    return out;
  }

  hsr::Polygon3 lift(const clipper::PolygonWithHoles2& p) const {
    hsr::Polygon3 out{lift(p.outer), {}};
    for (const clipper::Loop2& h : p.holes) out.holes.push_back(lift(h));
    return out;
  }

 private:
  const hsr::View& view_;
  glm::dvec3 normal_;
  double offset_from_eye_ = 0.0;
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> original_;
};

// The lit detail polygons of every face for one light.
std::vector<std::vector<LitPolygon>> light_one(const Parts& parts, const Light& light,
                                               LightStats& stats) {
  const std::size_t n = parts.polygons.size();
  // Per part, the lit polygons grouped by the light view that saw them.
  std::vector<std::vector<std::vector<hsr::Polygon3>>> lit_by_part(n);

  // Model only what the light requires: faces wholly beyond range.end are left out.
  std::vector<std::size_t> considered;
  considered.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (light.type == LightType::kPoint && light.range &&
        distance_to_polygon(light.position, parts.polygons[i], parts.planes[i]) >
            light.range->end) {
      ++stats.faces_culled_range;
      continue;
    }
    considered.push_back(i);
    if (!faces_light(parts.planes[i], light)) ++stats.faces_facing_away;
  }
  stats.faces_considered = considered.size();
  // A light without range (the sun) considers every part: no copy of them then.
  std::span<const hsr::Polygon3> polygons = parts.polygons;
  std::span<const hsr::Plane3> planes = parts.planes;
  std::vector<hsr::Polygon3> polygons_in_range;
  std::vector<hsr::Plane3> planes_in_range;
  if (considered.size() < n) {
    polygons_in_range.reserve(considered.size());
    planes_in_range.reserve(considered.size());
    for (std::size_t i : considered) {
      polygons_in_range.push_back(parts.polygons[i]);
      planes_in_range.push_back(parts.planes[i]);
    }
    polygons = polygons_in_range;
    planes = planes_in_range;
  }

  const std::vector<hsr::View> views = light_views(light, polygons, planes, parts.centre);
  stats.frusta = views.size();
  for (const hsr::View& view : views) {
    hsr::VisibleSurfaces visible = hsr::remove_hidden_surfaces(polygons, view);
    stats.fragments += visible.fragments.size();
    // Fragments per considered polygon, in image space.
    std::vector<clipper::PolygonSet2> seen(polygons.size());
    for (hsr::Fragment& f : visible.fragments) seen[f.parent].push_back(std::move(f.shape));

    // Coplanar faces do not shadow each other: a front-facing face is lit wherever the
    // plane it shares with others is visible within its own image. Every member counts as
    // a receiver, also one that got no fragment at all (a rug lying on the ground, whose
    // overlap hidden-surface removal gave to the ground).
    std::unordered_map<int, std::vector<std::size_t>> groups;
    for (std::size_t k = 0; k < polygons.size(); ++k) {
      const int g = parts.coplanar[considered[k]];
      if (g >= 0) groups[g].push_back(k);
    }
    std::vector<clipper::PolygonSet2> extra(polygons.size());
    for (const auto& [g, members] : groups) {
      if (members.size() < 2) continue;
      // The visible pieces of the group in a grid of their boxes: a receiver clips only the
      // pieces whose box overlaps its image's (a ground of 16,641 coplanar tiles would
      // otherwise clip every tile against every other). Boxes that only touch hold regions
      // that share no area, so their intersection would be empty anyway.
      struct Owned {
        std::size_t owner;
        const clipper::PolygonWithHoles2* shape;
      };
      std::vector<Owned> pieces;
      std::vector<clipper::Box2> boxes;
      clipper::Box2 extent;
      for (std::size_t m : members) {
        for (const auto& piece : seen[m]) {
          pieces.push_back({m, &piece});
          boxes.push_back(clipper::box_of(piece));
          extent.add(boxes.back());
        }
      }
      if (pieces.empty()) continue;
      hsr::SpatialGrid grid(extent, pieces.size());
      for (std::size_t i = 0; i < pieces.size(); ++i) grid.insert(i, boxes[i]);
      std::vector<std::size_t> near;
      for (std::size_t k : members) {
        if (!faces_light(planes[k], light)) continue;
        const clipper::PolygonSet2 image = hsr::project_polygon(polygons[k], view);
        if (image.empty()) continue;
        clipper::Box2 box;
        std::vector<hsr::ConvexWindow> windows;
        for (const auto& p : image) {
          box.add(clipper::box_of(p));
          windows.emplace_back(p);
        }
        near.clear();
        grid.query(box, near);
        // In the pieces' own order, so the result does not depend on the grid's.
        std::sort(near.begin(), near.end());
        for (std::size_t i : near) {
          if (pieces[i].owner == k || !box.overlaps(boxes[i])) continue;
          // The image's parts are disjoint: the piece within each, in turn.
          for (const hsr::ConvexWindow& window : windows) {
            for (auto& q : window.clip(*pieces[i].shape).inside) extra[k].push_back(std::move(q));
          }
        }
      }
    }

    for (std::size_t k = 0; k < polygons.size(); ++k) {
      if (!faces_light(planes[k], light)) continue;
      if (seen[k].empty() && extra[k].empty()) continue;
      clipper::PolygonSet2 lit = std::move(seen[k]);
      for (auto& q : extra[k]) lit.push_back(std::move(q));
      const BackProjector back(view, polygons[k], planes[k]);
      std::vector<hsr::Polygon3>& seen_here = lit_by_part[considered[k]].emplace_back();
      for (const clipper::PolygonWithHoles2& p : clipper::merge_adjacent(lit)) {
        hsr::Polygon3 detail = back.lift(p);
        if (detail.outer.size() >= 3) seen_here.push_back(std::move(detail));
      }
    }
  }

  // Faces the light grazes: cast back from its image, their lit region would carry the
  // image's rounding divided by a tiny sine; it is worked out in their plane instead.
  std::vector<int> coplanar;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    if (!faces_light(planes[k], light) || !detail::grazes(polygons[k], planes[k], light)) continue;
    if (coplanar.empty()) {
      coplanar.reserve(considered.size());
      for (std::size_t i : considered) coplanar.push_back(parts.coplanar[i]);
    }
    ++stats.faces_grazed;
    lit_by_part[considered[k]] = {
        detail::lit_by_grazing_light(k, polygons, planes, coplanar, light)};
  }

  std::vector<std::vector<LitPolygon>> lit_by_face;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t f = parts.face[i];
    if (lit_by_face.size() <= f) lit_by_face.resize(f + 1);
    std::vector<hsr::Polygon3> lit;
    if (lit_by_part[i].size() == 1) {
      lit = std::move(lit_by_part[i][0]);
    } else if (lit_by_part[i].size() > 1) {
      // Lit through several frusta of a point light: one region, not overlapping pieces.
      lit = detail::unite_views(lit_by_part[i], parts.planes[i]);
    }
    // A part seen almost edge-on by the light: cast back onto its plane, a rounded image
    // point can land far off the part. Its lit region is the part's at most.
    if (!lit.empty() && !detail::inside_box_of(lit, parts.polygons[i])) {
      lit = detail::within_part(lit, parts.polygons[i], parts.planes[i]);
    }
    for (hsr::Polygon3& p : lit) {
      ++stats.lit_polygons;
      lit_by_face[f].push_back({parts.part[i], std::move(p)});
    }
  }
  return lit_by_face;
}

}  // namespace

GenerateResult generate_shadows(const Scene& scene, const GenerateOptions& options) {
  GenerateResult result;
  result.shadowed.scene = scene;
  const std::size_t faces = scene.faces.size(), lights = scene.lights.size();
  result.shadowed.lit.assign(faces, std::vector<std::vector<LitPolygon>>(lights));
  result.stats.resize(lights);
  if (lights == 0) return result;

  const Parts parts = flatten(scene);
  std::vector<std::vector<std::vector<LitPolygon>>> per_light(lights);
  std::atomic<std::size_t> next{0};
  std::mutex report_mutex;
  std::exception_ptr failure;
  auto worker = [&] {
    for (std::size_t l = next++; l < lights; l = next++) {
      try {
        const auto start = std::chrono::steady_clock::now();
        per_light[l] = light_one(parts, scene.lights[l], result.stats[l]);
        result.stats[l].seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (options.on_light_done) {
          const std::lock_guard lock(report_mutex);
          options.on_light_done(l, result.stats[l]);
        }
      } catch (...) {
        const std::lock_guard lock(report_mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t count = std::min<std::size_t>(options.threads ? options.threads : hw, lights);
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < count; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);

  for (std::size_t l = 0; l < lights; ++l) {
    for (std::size_t f = 0; f < faces && f < per_light[l].size(); ++f) {
      result.shadowed.lit[f][l] = std::move(per_light[l][f]);
    }
  }
  return result;
}

}  // namespace shadowgen
