#include "shadowgen/shadows/generate.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <new>

#include "clipper/clip.h"
#include "detail/face_parts.h"
#include "detail/light_view_pass.h"
#include "detail/lit_parts.h"
#include "detail/part_failure.h"
#include "detail/receivers.h"
#include "hsr/parallel.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/shadows/light_views.h"

namespace shadowgen {
namespace {

// The lit detail polygons of every face for one light, lit[face]: the receivers in its
// range, seen through each of its views, the parts it grazes worked out in their planes,
// each part's views joined.
std::vector<std::vector<LitPolygon>> light_one(const detail::FaceParts& parts, const Light& light,
                                               const GenerateOptions& options, LightStats& stats) {
  const detail::Receivers receivers(parts, light, stats);
  const std::vector<hsr::View> views =
      light_views(light, receivers.polygons(), receivers.planes(), parts.centre);
  stats.frusta = views.size();
  std::vector<detail::LitPart> lit(parts.size());
  const hsr::HsrOptions hsr{.regions = options.image_regions};
  for (const hsr::View& view : views) {
    detail::light_through_view(receivers, view, hsr, lit, stats);
  }
  detail::relight_grazed_parts(receivers, lit, stats);
  return detail::join_per_face(parts, std::move(lit), stats);
}

// light_one, its failures named by the face and the light being worked on.
std::vector<std::vector<LitPolygon>> light_one_named(const Scene& scene,
                                                     const detail::FaceParts& parts,
                                                     std::size_t light,
                                                     const GenerateOptions& options,
                                                     LightStats& stats) {
  const std::string& light_id = scene.lights[light].id;
  try {
    return light_one(parts, scene.lights[light], options, stats);
  } catch (const detail::PartFailure& e) {
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
  GenerateResult result;
  result.shadowed.scene = scene;
  const std::size_t faces = scene.faces.size(), lights = scene.lights.size();
  result.shadowed.lit.assign(faces, std::vector<std::vector<LitPolygon>>(lights));
  result.stats.resize(lights);
  if (lights == 0) return result;

  const detail::FaceParts parts = detail::flatten(scene);
  std::vector<std::vector<std::vector<LitPolygon>>> per_light(lights);
  std::mutex report_mutex;
  // Lights in parallel, and within each light the regions of its views (hsr/
  // image_regions.h) and its receivers, all on one pool of `threads` threads. The failure
  // passed on is the first light's whatever the threads did.
  const int threads =
      options.threads ? static_cast<int>(options.threads) : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  arena.execute([&] {
    hsr::for_each_in_parallel(lights, [&](std::size_t l) {
      const auto start = std::chrono::steady_clock::now();
      per_light[l] = light_one_named(scene, parts, l, options, result.stats[l]);
      result.stats[l].seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (options.on_light_done) {
        const std::lock_guard lock(report_mutex);
        options.on_light_done(l, result.stats[l]);
      }
    });
  });

  for (std::size_t l = 0; l < lights; ++l) {
    for (std::size_t f = 0; f < faces; ++f) result.shadowed.lit[f][l] = std::move(per_light[l][f]);
  }
  return result;
}

}  // namespace shadowgen
