#include "database_writable.h"

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>

namespace shadowgen::output::detail {
namespace {

using hsr::Loop3;
using hsr::Polygon3;

// The checks of one thing written (a light, a face, a sun path), whose failures name it.
class WriteCheck {
 public:
  explicit WriteCheck(std::string owner) : owner_(std::move(owner)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("shadowed database: " + owner_ + ": " + what);
  }
  void finite(double value, const char* what) const {
    if (!std::isfinite(value)) fail(std::string(what) + " is not a finite number");
  }
  void finite(const glm::dvec3& v, const char* what) const {
    for (int i = 0; i < 3; ++i) finite(v[i], what);
  }
  void loop(const Loop3& loop) const {
    if (loop.size() < 3) fail("a loop has fewer than three vertices");
    for (const glm::dvec3& p : loop) finite(p, "a vertex coordinate");
  }
  void loop(const clipper::Loop2& loop) const {
    if (loop.size() < 3) fail("a loop has fewer than three vertices");
    for (const clipper::Point2& p : loop) {
      finite(p.x, "a chart coordinate");
      finite(p.y, "a chart coordinate");
    }
  }
  void pieces(const SunHoursPieces& sums) const {
    for (const SunHoursPieces::Part& part : sums.parts) {
      for (const SunHoursPieces::Count& count : part.counts) {
        for (const clipper::PolygonWithHoles2& piece : count.pieces) {
          loop(piece.outer);
          for (const clipper::Loop2& hole : piece.holes) loop(hole);
        }
      }
    }
  }
  void polygons(std::span<const Polygon3> polygons) const {
    for (const Polygon3& polygon : polygons) {
      loop(polygon.outer);
      for (const Loop3& hole : polygon.holes) loop(hole);
    }
  }

 private:
  std::string owner_;
};

// Faces, lights and views: each kind's ids are unique (lit details are keyed by light id).
template <class Item>
void check_unique_ids(const std::vector<Item>& items, const char* kind) {
  std::unordered_set<std::string_view> seen;
  for (const Item& item : items) {
    if (!seen.insert(item.id).second) {
      throw std::invalid_argument(std::string("shadowed database: duplicate ") + kind + " id '" +
                                  item.id + "'");
    }
  }
}

}  // namespace

void check_writable(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene();
  check_unique_ids(scene.faces, "face");
  check_unique_ids(scene.lights, "light");
  check_unique_ids(scene.views, "view");
  if (const std::optional<Estimate>& estimate = shadowed.estimate()) {
    const WriteCheck check("a sampled method's lit areas");
    for (const std::vector<double>& column : estimate->lit_area) {
      for (const double a : column) check.finite(a, "a lit area");
    }
  }
  for (const Light& light : scene.lights) {
    const WriteCheck check("light '" + light.id + "'");
    check.finite(light.direction, "direction");
    check.finite(light.position, "position");
    check.finite(light.intensity, "intensity");
    if (light.range) {
      check.finite(light.range->falloff_start, "range.falloff_start");
      check.finite(light.range->end, "range.end");
      check.finite(light.range->exponent, "range.exponent");
    }
  }
  for (const SunPathHours& path : shadowed.sun_paths) {
    const WriteCheck check("sun path '" + path.id + "'");
    const std::vector<std::vector<SunHoursRegion>>& regions = path.regions;
    const bool sums_shaped =
        !path.regions_kept ||
        (shadowed.shard ? path.nodes.size() == scene.faces.size() && regions.empty()
                        : regions.size() == scene.faces.size());
    if (path.lit_area.size() != scene.faces.size() || !sums_shaped) {
      check.fail("sums not shaped [face]");
    }
    const std::size_t own =
        shadowed.shard ? path.shard_last - path.shard_first : path.instants.size();
    if (path.shard_first > path.shard_last || path.shard_last > path.instants.size()) {
      check.fail("a shard's instants beyond the path's");
    }
    for (const std::size_t l : path.instants) {
      if (l >= scene.lights.size() || !scene.lights[l].sun ||
          scene.lights[l].sun->sun_id != path.id) {
        check.fail("an instant that is not a light of this path");
      }
    }
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      if (path.lit_area[f].size() != own) check.fail("lit areas not per instant");
      for (const double a : path.lit_area[f]) check.finite(a, "a lit area");
      const std::size_t parts = scene.faces[f].parts.size();
      const std::vector<std::vector<double>>& on_parts = path.part_lit_area.at(f);
      if (on_parts.size() != (parts > 1 ? parts : 0)) check.fail("part lit areas not per part");
      for (const std::vector<double>& areas : on_parts) {
        if (areas.size() != own) check.fail("part lit areas not per instant");
        for (const double a : areas) check.finite(a, "a part's lit area");
      }
      if (!path.regions_kept) continue;
      if (shadowed.shard) {
        for (const SunHoursNode& node : path.nodes[f]) check.pieces(node.sums);
        continue;
      }
      for (const SunHoursRegion& region : path.regions[f]) {
        check.finite(region.hours, "sun hours");
        for (const LitPolygon& p : region.polygons) check.polygons({&p.polygon, 1});
      }
    }
  }
  for (const ViewSpec& view : scene.views) {
    const WriteCheck check("view '" + view.id + "'");
    check.finite(view.eye, "eye");
    check.finite(view.target, "target");
    check.finite(view.up, "up");
    check.finite(view.fov_deg, "fov_deg");
  }
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const WriteCheck check("face '" + scene.faces[f].id + "'");
    if (scene.faces[f].parts.empty()) check.fail("the face has no parts");
    check.polygons(scene.faces[f].parts);
    for (const std::vector<LitPolygon>& lit : shadowed.lit()[f]) {
      for (const LitPolygon& p : lit) {
        if (p.part >= scene.faces[f].parts.size()) {
          check.fail("a lit polygon on part " + std::to_string(p.part) + " of a face of " +
                     std::to_string(scene.faces[f].parts.size()) + " parts");
        }
        check.polygons({&p.polygon, 1});
      }
    }
  }
}

}  // namespace shadowgen::output::detail
