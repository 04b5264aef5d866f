#include "shadowgen/shadows/generate.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <new>
#include <optional>

#include "clipper/clip.h"
#include "detail/face_parts.h"
#include "detail/light_view_pass.h"
#include "detail/lit_parts.h"
#include "detail/part_failure.h"
#include "detail/receivers.h"
#include "hsr/area.h"
#include "hsr/parallel.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/shadows/light_views.h"
#include "shadowgen/shadows/sun_hours.h"

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

namespace {

// Instants generated before they are summed: few enough that a path's lit polygons never
// all sit in memory, enough to keep the threads busy. A fixed number, so that the sums
// are made in one order whatever the thread count.
constexpr std::size_t kInstantsPerBatch = 16;

// Where each light stands in the scene's sun paths: (path, k) for instant k of a path.
struct PathPlace {
  std::size_t path = 0, instant = 0;
};

// Sums sun paths as their instants come, face by face.
class PathSums {
 public:
  PathSums(const Scene& scene, std::vector<SunPathHours>& paths, bool keep_polygons)
      : scene_(scene), paths_(paths), place_(scene.lights.size()) {
    hours_.resize(paths.size());
    for (std::size_t p = 0; p < paths.size(); ++p) {
      paths[p].lit_polygons_kept = keep_polygons;
      const std::size_t instants = paths[p].instants.size();
      paths[p].lit_area.assign(scene.faces.size(), std::vector<double>(instants));
      paths[p].part_lit_area.assign(scene.faces.size(), {});
      for (std::size_t f = 0; f < scene.faces.size(); ++f) {
        const std::size_t face_parts = scene.faces[f].parts.size();
        if (face_parts > 1) {
          paths[p].part_lit_area[f].assign(face_parts, std::vector<double>(instants));
        }
      }
      hours_[p].resize(scene.faces.size());
      for (std::size_t k = 0; k < paths[p].instants.size(); ++k) {
        place_[paths[p].instants[k]] = PathPlace{p, k};
      }
    }
  }

  bool in_path(std::size_t light) const { return place_[light].has_value(); }

  // Adds lights [first, last)'s lit polygons, lit[l - first][face], to their paths, in
  // light order, each face on its own.
  void add(std::size_t first, std::size_t last,
           const std::vector<std::vector<std::vector<LitPolygon>>>& lit) {
    hsr::for_each_in_parallel(scene_.faces.size(), [&](std::size_t f) {
      for (std::size_t l = first; l < last; ++l) {
        if (!place_[l]) continue;
        const std::size_t p = place_[l]->path, k = place_[l]->instant;
        const std::vector<LitPolygon>& polygons = lit[l - first][f];
        paths_[p].lit_area[f][k] = lit_area(polygons);
        if (!paths_[p].part_lit_area[f].empty()) {
          for (const LitPolygon& lit_polygon : polygons) {
            paths_[p].part_lit_area[f].at(lit_polygon.part)[k] += hsr::area(lit_polygon.polygon);
          }
        }
        if (polygons.empty()) continue;
        named(f, p, [&] {
          std::optional<FaceSunHours>& hours = hours_[p][f];
          if (!hours) hours.emplace(scene_.faces[f]);
          hours->add(polygons);
        });
      }
    });
  }

  // Every path's regions, once all its instants are added.
  void finish() {
    for (std::size_t p = 0; p < paths_.size(); ++p) {
      paths_[p].regions.resize(scene_.faces.size());
      hsr::for_each_in_parallel(scene_.faces.size(), [&](std::size_t f) {
        std::optional<FaceSunHours>& hours = hours_[p][f];
        if (!hours) hours.emplace(scene_.faces[f]);  // lit at no instant
        paths_[p].regions[f] = hours->regions(paths_[p].step_min);
        hours.reset();
      });
    }
  }

 private:
  // Work on face f's sums of path p, a failure named by the face and the path.
  template <class Work>
  void named(std::size_t f, std::size_t p, Work&& work) const {
    try {
      work();
    } catch (const clipper::SnapRoundingError& e) {
      throw GenerationError("", scene_.faces[f].id, paths_[p].id,
                            "sun hours not computed: " + std::string(e.what()));
    }
  }

  const Scene& scene_;
  std::vector<SunPathHours>& paths_;
  std::vector<std::optional<PathPlace>> place_;
  std::vector<std::vector<std::optional<FaceSunHours>>> hours_;  // [path][face]
};

}  // namespace

GenerateResult generate_shadows(const Scene& scene, const GenerateOptions& options) {
  GenerateResult result;
  result.shadowed.scene = scene;
  const std::size_t faces = scene.faces.size(), lights = scene.lights.size();
  result.shadowed.lit.assign(faces, std::vector<std::vector<LitPolygon>>(lights));
  result.stats.resize(lights);
  result.shadowed.sun_paths = sun_paths_of(scene);
  PathSums sums(scene, result.shadowed.sun_paths, options.keep_instant_polygons);
  if (lights == 0) return result;

  const detail::FaceParts parts = detail::flatten(scene);
  std::mutex report_mutex;
  // Lights in parallel, and within each light the regions of its views (hsr/
  // image_regions.h) and its receivers, all on one pool of `threads` threads. The failure
  // passed on is the first light's whatever the threads did. With sun paths, the lights
  // go in batches, each summed before the next starts.
  const int threads =
      options.threads ? static_cast<int>(options.threads) : tbb::info::default_concurrency();
  const std::size_t batch = result.shadowed.sun_paths.empty() ? lights : kInstantsPerBatch;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    for (std::size_t first = 0; first < lights; first += batch) {
      const std::size_t last = std::min(lights, first + batch);
      std::vector<std::vector<std::vector<LitPolygon>>> per_light(last - first);
      hsr::for_each_in_parallel(last - first, [&](std::size_t i) {
        const std::size_t l = first + i;
        const auto start = std::chrono::steady_clock::now();
        per_light[i] = light_one_named(scene, parts, l, options, result.stats[l]);
        result.stats[l].seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (options.on_light_done) {
          const std::lock_guard lock(report_mutex);
          options.on_light_done(l, result.stats[l]);
        }
      });
      sums.add(first, last, per_light);
      for (std::size_t l = first; l < last; ++l) {
        if (sums.in_path(l) && !options.keep_instant_polygons) continue;
        for (std::size_t f = 0; f < faces; ++f) {
          result.shadowed.lit[f][l] = std::move(per_light[l - first][f]);
        }
      }
    }
    sums.finish();
  });
  return result;
}

}  // namespace shadowgen
