#include "shadowgen/shadows/generate.h"

#include <exception>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "clipper/clip.h"
#include "detail/closed_solids.h"
#include "detail/face_parts.h"
#include "detail/light_batches.h"
#include "detail/light_view_pass.h"
#include "detail/lit_parts.h"
#include "detail/part_failure.h"
#include "detail/receivers.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/shadows/light_views.h"
#include "shadowgen/shadows/sun_hours.h"
#include "shadowgen/shadows/sun_path_sums.h"

namespace shadowgen {
namespace {

// The lit detail polygons of every face for one light, lit[face]: the receivers in its
// range, seen through each of its views, the parts it grazes worked out in their planes,
// each part's views joined.
std::vector<std::vector<LitPolygon>> light_one(const shadows::detail::FaceParts& parts,
                                               const shadows::detail::ClosedSolids* solids,
                                               const Light& light, const GenerateOptions& options,
                                               LightStats& stats) {
  const shadows::detail::Receivers receivers(parts, light, stats, solids);
  const std::vector<hsr::View> views =
      light_views(light, receivers.polygons(), receivers.planes(), parts.centre);
  stats.frusta = views.size();
  std::vector<shadows::detail::LitPart> lit(parts.size());
  const hsr::HsrOptions hsr{.regions = options.image_regions};
  for (const hsr::View& view : views) {
    shadows::detail::light_through_view(receivers, view, hsr, lit, stats);
  }
  shadows::detail::relight_grazed_parts(receivers, lit, stats);
  return shadows::detail::join_per_face(parts, std::move(lit), stats);
}

// light_one, its failures named by the face and the light being worked on.
std::vector<std::vector<LitPolygon>> light_one_named(const Scene& scene,
                                                     const shadows::detail::FaceParts& parts,
                                                     const shadows::detail::ClosedSolids* solids,
                                                     std::size_t light,
                                                     const GenerateOptions& options,
                                                     LightStats& stats) {
  const std::string& light_id = scene.lights[light].id;
  try {
    return light_one(parts, solids, scene.lights[light], options, stats);
  } catch (const shadows::detail::PartFailure& e) {
    const std::string& face_id = scene.faces[parts.owners[e.part()].face].id;
    throw GenerationError("", face_id, light_id,
                          "lit region not computed: " + std::string(e.what()));
  } catch (const clipper::SnapRoundingError& e) {
    throw GenerationError("", "", light_id, "lit region not computed: " + std::string(e.what()));
  } catch (const std::bad_alloc&) {
    throw;  // out of memory: the command line names the input
  } catch (const std::exception& e) {
    // Any other failure of a stage (a view that cannot be built, say) still names the
    // light, and the caller adds the file: never a bare internal message.
    throw GenerationError("", "", light_id, "lit region not computed: " + std::string(e.what()));
  }
}

}  // namespace

std::string GenerationError::format(const std::string& file, const std::string& face_id,
                                    const std::string& light_id, const std::string& problem) {
  std::string s = file.empty() ? "" : file + ": ";
  if (!face_id.empty()) s += "face '" + face_id + "'" + (light_id.empty() ? ": " : ", ");
  if (!light_id.empty()) s += "light '" + light_id + "': ";
  return one_line(s + problem);
}

GenerateResult generate_shadows(const Scene& scene, const GenerateOptions& options) {
  return generate_shadows(Scene(scene), options);
}

GenerateResult generate_shadows(Scene&& input, const GenerateOptions& options) {
  GenerateResult result;
  ShadowedScene& shadowed = result.shadowed;
  const std::size_t faces = input.faces.size(), lights = input.lights.size();
  std::vector<bool> kept(lights);
  for (std::size_t l = 0; l < lights; ++l) {
    kept[l] = !in_sun_path(input.lights[l]) || options.keep_instant_polygons;
  }
  shadowed = ShadowedScene(std::move(input), LitTable(faces, lights, std::move(kept)));
  const Scene& scene = shadowed.scene();
  shadowed.shard = options.shard;
  result.stats.resize(lights);
  shadowed.sun_paths = sun_paths_of(scene);
  SunPathSums sums(scene, shadowed.sun_paths, options.keep_instant_polygons,
                   options.sun_hours_regions, options.shard);
  const std::vector<std::size_t> todo = sums.lights_of_run();
  if (todo.empty()) {
    sums.finish();
    return result;
  }

  tbb::task_arena arena = shadows::detail::arena_of(options.threads);
  shadows::detail::FaceParts parts;
  std::optional<shadows::detail::ClosedSolids> solids;
  arena.execute([&] {
    parts = shadows::detail::flatten(scene);
    if (options.leave_out_solids_backs) solids.emplace(parts);
  });
  // Lights in parallel, and within each light the regions of its views (hsr/
  // image_regions.h) and its receivers, all on one pool of `threads` threads. With sun
  // paths, the lights go in batches, each summed before the next starts.
  arena.execute([&] {
    shadows::detail::run_lights(
        todo, !shadowed.sun_paths.empty(), options.on_light_done, result.stats,
        [&](std::size_t l, LightStats& stats) {
          return light_one_named(scene, parts, solids ? &*solids : nullptr, l, options, stats);
        },
        [&](const std::vector<std::size_t>& batch,
            std::vector<std::vector<std::vector<LitPolygon>>>& lit) {
          sums.add_lit(batch, lit);
          for (std::size_t i = 0; i < batch.size(); ++i) {
            const std::size_t l = batch[i];
            if (!shadowed.lit().kept(l)) continue;
            for (std::size_t f = 0; f < faces; ++f) shadowed.lit_at(f, l) = std::move(lit[i][f]);
          }
        });
    sums.finish();
  });
  return result;
}

}  // namespace shadowgen
