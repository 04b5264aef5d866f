#pragma once

// Shadow generation (Atherton, Weiler and Greenberg 1978, section IV): hidden-surface
// removal from every light; what a light sees becomes lit detail polygons on their parent
// faces, in 3D, in the scene's own coordinates.
//
// Per light:
//   - directional: one orthographic light view along the light's direction, centred on
//     the scene's bounding box's point nearest the origin (the paper's "fitting the
//     environment into the viewbox", keeping each point's own precision);
//   - point: up to six 90-degree perspective frusta around the light (cube-map style),
//     only those that see part of the scene, so a light may stand anywhere, inside the
//     scene included;
//   - faces wholly beyond range.end are left out entirely; faces turned away from the
//     light (or seeing it edge-on) get no lit area but still occlude, except on the back
//     of a closed solid the light is outside of, where the solid's faces toward the
//     light occlude all they would (detail/closed_solids.h).
// The visible fragments are mapped back onto their parent face's plane and merged per
// (face, light). Lights are independent and run in parallel. The stages of one light are
// in detail/: receivers.h (the parts in range), light_view_pass.h (per view: hidden-
// surface removal, coplanar_receivers.h, back-projection), lit_parts.h (grazed faces,
// views joined per face).
//
// Coplanar faces do not shadow each other (the spec's meaning of "lit"): where hidden-
// surface removal gives an overlap of exactly coplanar faces to one of them, the lit
// region of each is its own area within the visible region of the plane they share.

#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

struct LightStats {
  std::size_t faces_considered = 0;  // within range
  std::size_t faces_culled_range = 0;
  std::size_t faces_facing_away = 0;
  // Of those, the ones on the back of a closed solid the light is outside of, left out of
  // hidden-surface removal (detail/closed_solids.h): they shadow nothing the solid's
  // parts facing the light do not.
  std::size_t faces_behind_solids = 0;
  std::size_t faces_grazed = 0;  // lit regions worked out in their plane (grazing_light.h)
  std::size_t frusta = 0;        // light views used (1 for directional lights)
  std::size_t fragments = 0;
  std::size_t lit_polygons = 0;
  double seconds = 0.0;
};

// The exact method's options (a sampled method's are estimate_shadows.h's EstimateOptions).
struct GenerateOptions {
  // Threads for the lights and, within each, its views' image regions and its receivers
  // (0: one per hardware thread). The result does not depend on them.
  unsigned threads = 0;
  // Regions each light view's image is cut into and settled independently (hsr/
  // image_regions.h); 0: as many as the number of pieces calls for. Tests set it to cut
  // small scenes.
  std::size_t image_regions = 0;
  // Sun paths are summed into sun hours as their instants are generated (sun_hours.h,
  // ShadowedScene::sun_paths), a few instants' lit polygons in memory at a time. Their
  // instants' lit polygons are then dropped, only their lit areas kept, unless this is
  // set: then each instant keeps its lit polygons as any light does.
  bool keep_instant_polygons = false;
  // Whether turned-away parts of closed solids are left out as occluders
  // (detail/closed_solids.h): the lit regions are the same either way (tests compare);
  // false keeps every part in hidden-surface removal.
  bool leave_out_solids_backs = true;
  // Whether sun paths get their sun-hours regions (SunPathHours::regions_kept). Without
  // them a path costs its instants' lit areas alone, in time and memory linear in its
  // instants: all that EnergyPlus schedules and irradiation need, and the only way to a
  // year of instants on a large scene (the regions are the arrangement of every instant's
  // shadow edges, which grows with the square of the instants where shadows sweep a face).
  bool sun_hours_regions = true;
  // Only shard `index` of `count` of every sun path (ShadowedScene::shard; sun_hours_tree.h
  // says which instants are its own): the paths keep their tree nodes, not regions, and
  // the lights that are no instant are lit in shard 0 alone. Not with
  // keep_instant_polygons.
  std::optional<ShardPlace> shard;
  // Called after each light is done (from the worker that finished it); for progress.
  std::function<void(std::size_t light, const LightStats&)> on_light_done;
};

struct GenerateResult {
  ShadowedScene shadowed;
  std::vector<LightStats> stats;  // per light
};

// Shadows that could not be computed: an internal failure, not the input's fault. Names the face
// (where one was being worked on) and the light, and the file where the caller knows it; its
// message is the line to show, like InputError's. The one cause so far: a clip whose snap rounding
// did not settle (clipper::SnapRoundingError, clipper/clip.h), whose pieces could have wrong areas.
class GenerationError : public std::runtime_error {
 public:
  GenerationError(std::string file, std::string face_id, std::string light_id,
                  const std::string& problem)
      : std::runtime_error(format(file, face_id, light_id, problem)),
        file_(std::move(file)),
        face_id_(std::move(face_id)),
        light_id_(std::move(light_id)),
        problem_(problem) {}

  const std::string& file() const { return file_; }          // empty when not known
  const std::string& face_id() const { return face_id_; }    // empty when no face is to blame
  const std::string& light_id() const { return light_id_; }  // empty when no one light is
  const std::string& problem() const { return problem_; }

 private:
  static std::string format(const std::string& file, const std::string& face_id,
                            const std::string& light_id, const std::string& problem);
  std::string file_, face_id_, light_id_, problem_;
};

// Throws GenerationError (with no file) where the shadows of a face cannot be computed;
// nothing else of the result comes back then.
GenerateResult generate_shadows(const Scene& scene, const GenerateOptions& options = {});
// The same on a scene the result takes over (ShadowedScene::scene), saving its copy.
GenerateResult generate_shadows(Scene&& scene, const GenerateOptions& options = {});

}  // namespace shadowgen
