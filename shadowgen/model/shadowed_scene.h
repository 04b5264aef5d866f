#pragma once

// The shadowed database in memory: the scene plus, for every (face, light), the lit detail
// polygons, in the face's own plane and the scene's coordinates (the paper's "lighted
// details attached to parent polygons"). Everything later output needs comes from it.

#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "clipper/polygon.h"
#include "hsr/polygon3.h"
#include "shadowgen/model/lit_table.h"
#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"

namespace shadowgen {

// Part of a face with a constant number of sun hours over a sun path.
struct SunHoursRegion {
  double hours = 0.0;
  std::vector<LitPolygon> polygons;  // on their face's parts, like lit detail polygons
};

// The sums of one face over a run of a path's instants, as FaceSunHours holds them
// (shadows/sun_hours.h): per part with area, the pieces of the part lit at each count of
// instants, in the part's exact plane chart (hsr/plane_chart.h), not merged. A shard's
// database keeps them so that `merge` goes on exactly where the shard stopped.
struct SunHoursPieces {
  struct Count {
    std::size_t count = 0;
    clipper::PolygonSet2 pieces;
  };
  struct Part {
    std::size_t part = 0;       // in Face::parts
    std::vector<Count> counts;  // increasing counts, none empty
  };
  std::vector<Part> parts;  // increasing parts; none: lit at no instant
};

// A node of a path's fixed tree of instant blocks (shadows/sun_hours_tree.h): the sums of
// blocks [first_block, first_block + 2^level).
struct SunHoursNode {
  std::size_t first_block = 0;
  unsigned level = 0;
  SunHoursPieces sums;
};

// Shard `index` of `count` of every sun path (generate --instants K/N, K = index + 1):
// which instants are its own is fixed by the tree (shadows/sun_hours_tree.h).
struct ShardPlace {
  std::size_t index = 0, count = 1;
};

// A sun path summed over its instants (docs/scene-format.md, "Sun hours"): the instants
// are lights of the scene (Light::sun), but only their lit areas are kept per face, not
// their lit polygons, so a path of thousands of instants costs what its sum costs.
struct SunPathHours {
  std::string id;        // the `sun` entry's id
  int step_min = 0;      // the minutes each instant stands for
  std::string from, to;  // the entry's span, local standard time (sun/civil_time.h civil_text)
  std::vector<std::size_t> instants;  // indices into scene.lights, in time order
  bool lit_polygons_kept = false;     // whether `lit` holds the instants' polygons too
  // Whether the path's sun-hours regions were made (generate --areas-only sums the lit
  // areas alone, which EnergyPlus schedules and irradiation need: its regions are empty).
  bool regions_kept = true;
  std::vector<std::vector<double>> lit_area;  // [face][k]: lit area at instant k
  // [face][part][k]: the lit area on each part at instant k, for a face of several parts
  // (the triangles of a non-planar polygon, each turned its own way to the sun, as
  // irradiation needs); empty for a face of one part, whose lit_area it is.
  std::vector<std::vector<std::vector<double>>> part_lit_area;
  // [face]: sun-hours regions in increasing hours (0 included), tiling the face.
  std::vector<std::vector<SunHoursRegion>> regions;
  // In a shard (ShadowedScene::shard) only: its own instants are [shard_first,
  // shard_last), the only ones lit_area and part_lit_area hold; its sums are the tree's
  // nodes over its blocks, nodes[face] in increasing blocks, and regions is empty.
  std::size_t shard_first = 0, shard_last = 0;
  std::vector<std::vector<SunHoursNode>> nodes;
};

// A sampled method's answer (docs/scene-format.md, "Methods"): lit areas alone, no lit
// polygons, so that an estimate is never taken for the exact answer.
struct Estimate {
  Method method;  // a sampled one: never Method::exact()
  // [light][face]: the estimated lit area of every face, for each light that is no
  // instant of a sun path (in_sun_path); empty for an instant, whose lit areas are its
  // path's (SunPathHours::lit_area).
  std::vector<std::vector<double>> lit_area;
};

// A shadowed scene, exact or estimated. Its rules hold from construction and through every
// change it allows, so no consumer checks them again: the lit table has one row per face of
// the scene and one list per light; an estimate keeps no light's polygons, and has one row
// per light, of one area per face (empty only for an instant of a sun path). Breaking a
// rule is a caller's mistake, never bad input: std::invalid_argument, naming what does not
// fit.
class ShadowedScene {
 public:
  // No face, no light: exact.
  ShadowedScene() = default;
  // The exact method's result: `lit` holds the lit polygons of `scene`.
  ShadowedScene(Scene scene, LitTable lit);
  // A sampled method's result: `lit` keeps no light (Estimate::lit_area holds the areas).
  ShadowedScene(Scene scene, LitTable lit, Estimate estimate);

  const Scene& scene() const { return scene_; }
  // lit()[face][light]: polygons with holes covering exactly the lit region; empty when
  // unlit. The instants of a path in sun_paths that keeps only their lit areas are lights
  // the table does not keep (see LitAreas). The polygons of one part do not overlap.
  const LitTable& lit() const { return lit_; }
  // How the lit areas were found: absent for the exact method, the lit polygons
  // themselves; a sampled method's lit areas otherwise.
  const std::optional<Estimate>& estimate() const { return estimate_; }
  bool is_exact() const { return !estimate_; }
  // The method that found the lit areas, to be named (a report's "method"): the exact one,
  // or the estimate's.
  Method method() const { return estimate_ ? estimate_->method : Method{}; }

  // The lit polygons of (face, light), to fill: throws std::out_of_range outside the table,
  // std::logic_error for a light the table does not keep.
  LitTable::Polygons& lit_at(std::size_t face, std::size_t light) { return lit_.at(face, light); }
  // Appends `face` with no lit polygon (a database is read face by face). For an
  // estimate, `estimated` holds its lit area for every light, none for the instants of a
  // sun path (as for the faces before it); for the exact method, nothing.
  void add_face(Face face, const std::vector<std::optional<double>>& estimated = {});
  // Changes the scene but its faces (the file, groups, sun paths, the lights):
  // `edit` gets it without its faces, which it cannot change, and may change the lights but
  // not so as to break the rules above; where it does, the lights are as they were and
  // std::invalid_argument is thrown.
  template <class Edit>
  void edit_scene(const Edit& edit) {
    std::vector<Face> faces = std::move(scene_.faces);
    scene_.faces.clear();
    std::vector<Light> lights = scene_.lights;
    edit(scene_);
    if (!scene_.faces.empty()) {
      scene_.faces = std::move(faces);
      scene_.lights = std::move(lights);
      throw std::invalid_argument("ShadowedScene::edit_scene: the faces cannot change");
    }
    scene_.faces = std::move(faces);
    try {
      check();
    } catch (const std::invalid_argument&) {
      scene_.lights = std::move(lights);
      throw;
    }
  }
  // Changes face `face` (its id, its parts) through `edit`; throws std::out_of_range for
  // a face the scene lacks.
  template <class Edit>
  void edit_face(std::size_t face, const Edit& edit) {
    edit(scene_.faces.at(face));
  }
  // Keeps the lights marked in `keep` (one flag per light), in order, renumbered, with
  // their lit polygons and estimated areas.
  void keep_lights(const std::vector<bool>& keep);

  std::vector<SunPathHours> sun_paths;
  // Set in a shard of a sun-path run, which only `merge` reads: lights that are not
  // instants of a path are lit in shard 0 alone.
  std::optional<ShardPlace> shard;

 private:
  // Throws std::invalid_argument where a rule above does not hold.
  void check() const;

  Scene scene_;
  LitTable lit_;
  std::optional<Estimate> estimate_;
};

// The sun path whose id is `id`. Throws InputError naming `file` where there is none,
// listing the ids of the paths there are, or saying that there is no sun path at all.
const SunPathHours& sun_path_named(const ShadowedScene& shadowed, std::string_view id,
                                   const std::string& file);

// The same check on a scene read but not yet generated, so that a command asked for a
// path the scene does not have stops before computing its shadows: throws what
// sun_path_named throws where no `sun` entry of the scene with from, to and step_min has
// that id (Scene::sun_paths, or the lights its instants placed).
void require_sun_path(const Scene& scene, std::string_view id, const std::string& file);

// Throws InputError naming `file` where `path` was summed into lit areas alone
// (SunPathHours::regions_kept false), for what needs its sun-hours regions (`what`).
void require_regions(const SunPathHours& path, const std::string& file, std::string_view what);

// Lit area of every (face, light): from its lit polygons or, for an instant of a sun path
// that keeps only its instants' lit areas, from the path's, or a sampled method's estimate
// (Estimate::lit_area).
class LitAreas {
 public:
  explicit LitAreas(const ShadowedScene& shadowed);

  double operator()(std::size_t face, std::size_t light) const;

  // The sun path light `light` is an instant of, where the path keeps only its instants'
  // lit areas (no lit polygons in ShadowedScene::lit); nullptr for any other light.
  const SunPathHours* summed_path(std::size_t light) const { return place_[light].path; }

 private:
  struct Place {
    const SunPathHours* path = nullptr;
    std::size_t instant = 0;
  };
  const ShadowedScene& shadowed_;
  std::vector<Place> place_;  // per light
};

// The lit area on part `part` of face `face` at instant `k` of `path`.
double part_lit_area(const SunPathHours& path, std::size_t face, std::size_t part, std::size_t k);

// Total area of lit detail polygons (hsr::area of each).
double lit_area(std::span<const LitPolygon> lit);

// The polygons of `lit`, whatever part they lie on.
std::vector<hsr::Polygon3> polygons_of(std::span<const LitPolygon> lit);

// The polygons of `lit` that lie on part `part`.
std::vector<hsr::Polygon3> polygons_on_part(std::span<const LitPolygon> lit, std::size_t part);

}  // namespace shadowgen
