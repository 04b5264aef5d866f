#include "shadowgen/shadows/generate.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <new>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "clipper/clip.h"
#include "detail/closed_solids.h"
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
#include "shadowgen/shadows/sun_hours_tree.h"

namespace shadowgen {
namespace {

// The lit detail polygons of every face for one light, lit[face]: the receivers in its
// range, seen through each of its views, the parts it grazes worked out in their planes,
// each part's views joined.
std::vector<std::vector<LitPolygon>> light_one(const detail::FaceParts& parts,
                                               const detail::ClosedSolids* solids,
                                               const Light& light, const GenerateOptions& options,
                                               LightStats& stats) {
  const detail::Receivers receivers(parts, light, stats, solids);
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
std::vector<std::vector<LitPolygon>> light_one_named(
    const Scene& scene, const detail::FaceParts& parts, const detail::ClosedSolids* solids,
    std::size_t light, const GenerateOptions& options, LightStats& stats) {
  const std::string& light_id = scene.lights[light].id;
  try {
    return light_one(parts, solids, scene.lights[light], options, stats);
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

// Lights generated before their instants are summed: few enough that a path's lit
// polygons never all sit in memory, enough to keep the threads busy. The sums are made in
// one order whatever the thread count.
constexpr std::size_t kLightsPerBatch = 16;

// Where each light stands in the scene's sun paths: (path, k) for instant k of a path.
struct PathPlace {
  std::size_t path = 0, instant = 0;
};

// Sums sun paths as their instants come, face by face: each block of instants
// (sun_hours_tree.h) added instant by instant, the blocks joined in the path's tree.
// With a shard, only its own instants are summed, and its nodes are what it keeps.
class PathSums {
 public:
  PathSums(const Scene& scene, std::vector<SunPathHours>& paths, bool keep_polygons, bool regions,
           const std::optional<ShardPlace>& shard)
      : scene_(scene),
        paths_(paths),
        regions_(regions),
        shard_(shard),
        place_(scene.lights.size()) {
    const std::size_t faces = scene.faces.size();
    state_.resize(paths.size());
    for (std::size_t p = 0; p < paths.size(); ++p) {
      SunPathHours& path = paths[p];
      path.lit_polygons_kept = keep_polygons;
      path.regions_kept = regions;
      const std::size_t instants = path.instants.size();
      const IndexRun own = shard ? shard_instants(instants, *shard) : IndexRun{0, instants};
      if (shard) {
        path.shard_first = own.first;
        path.shard_last = own.last;
      }
      const std::size_t count = own.last - own.first;
      path.lit_area.assign(faces, std::vector<double>(count));
      path.part_lit_area.assign(faces, {});
      for (std::size_t f = 0; f < faces; ++f) {
        const std::size_t face_parts = scene.faces[f].parts.size();
        if (face_parts > 1) path.part_lit_area[f].assign(face_parts, std::vector<double>(count));
      }
      state_[p].first = own.first;
      state_[p].last = own.last;
      state_[p].block.resize(faces);
      state_[p].nodes.resize(faces);
      for (std::size_t k = own.first; k < own.last; ++k) {
        place_[path.instants[k]] = PathPlace{p, k};
      }
      for (std::size_t k = 0; k < instants; ++k) in_any_path_.insert(path.instants[k]);
    }
  }

  // Whether light `light` is an instant of some path (this shard's or not).
  bool in_path(std::size_t light) const { return in_any_path_.count(light) > 0; }
  // Whether light `light` is an instant this run sums.
  bool summed_here(std::size_t light) const { return place_[light].has_value(); }

  // Adds the lit polygons of lights `batch`, lit[i][face] for light batch[i], to their
  // paths, in light order, each face on its own; or, for a sampled method, the lit areas
  // estimated[i][face][part].
  void add(const std::vector<std::size_t>& batch,
           const std::vector<std::vector<std::vector<LitPolygon>>>& lit,
           const std::vector<std::vector<std::vector<double>>>& estimated) {
    hsr::for_each_in_parallel(scene_.faces.size(), [&](std::size_t f) {
      for (std::size_t i = 0; i < batch.size(); ++i) {
        const std::size_t l = batch[i];
        if (!place_[l]) continue;
        const std::size_t p = place_[l]->path, k = place_[l]->instant;
        PathState& state = state_[p];
        const std::size_t own = k - state.first;
        const bool by_part = !paths_[p].part_lit_area[f].empty();
        if (!estimated.empty()) {
          const std::vector<double>& parts = estimated[i][f];
          double sum = 0.0;
          for (std::size_t part = 0; part < parts.size(); ++part) {
            sum += parts[part];
            if (by_part) paths_[p].part_lit_area[f].at(part)[own] = parts[part];
          }
          paths_[p].lit_area[f][own] = sum;
          continue;
        }
        const std::vector<LitPolygon>& polygons = lit[i][f];
        paths_[p].lit_area[f][own] = lit_area(polygons);
        if (by_part) {
          for (const LitPolygon& lit_polygon : polygons) {
            paths_[p].part_lit_area[f].at(lit_polygon.part)[own] += hsr::area(lit_polygon.polygon);
          }
        }
        if (!regions_) continue;
        named(f, p, [&] {
          std::optional<FaceSunHours>& block = state.block[f];
          if (!polygons.empty()) {
            if (!block) block.emplace(scene_.faces[f]);
            block->add(polygons);
          }
          if ((k + 1) % kInstantsPerBlock == 0 || k + 1 == state.last) {
            state.nodes[f].push(k / kInstantsPerBlock, std::move(block));
            block.reset();
          }
        });
      }
    });
  }

  // Every path's regions (or, in a shard, its nodes), once all its instants are added.
  void finish() {
    for (std::size_t p = 0; p < paths_.size(); ++p) {
      SunPathHours& path = paths_[p];
      if (!regions_) continue;  // lit areas alone: no regions, no nodes
      const std::size_t faces = scene_.faces.size();
      if (shard_) {
        path.nodes.resize(faces);
      } else {
        path.regions.resize(faces);
      }
      hsr::for_each_in_parallel(faces, [&](std::size_t f) {
        std::vector<SumsNode> nodes = state_[p].nodes[f].take();
        if (shard_) {
          for (SumsNode& node : nodes) {
            path.nodes[f].push_back(
                {node.first_block, node.level, node.sums ? node.sums->pieces() : SunHoursPieces{}});
          }
          return;
        }
        std::optional<FaceSunHours> hours;
        named(f, p,
              [&] { hours = join_nodes(std::move(nodes), block_count(path.instants.size())); });
        if (!hours) hours.emplace(scene_.faces[f]);  // lit at no instant
        path.regions[f] = hours->regions(path.step_min);
      });
    }
  }

 private:
  struct PathState {
    std::size_t first = 0, last = 0;                 // the instants summed here
    std::vector<std::optional<FaceSunHours>> block;  // [face]: the block being summed
    std::vector<SunHoursNodes> nodes;                // [face]
  };

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
  bool regions_ = true;
  std::optional<ShardPlace> shard_;
  std::vector<std::optional<PathPlace>> place_;
  std::set<std::size_t> in_any_path_;
  std::vector<PathState> state_;  // [path]
};

}  // namespace

GenerateResult generate_shadows(const Scene& scene, const GenerateOptions& options) {
  return generate_shadows(Scene(scene), options);
}

GenerateResult generate_shadows(Scene&& input, const GenerateOptions& options) {
  const bool sampled = static_cast<bool>(options.estimate);
  if (sampled && (options.method.exact() || options.shard)) {
    throw std::invalid_argument(
        "generate_shadows: an estimate needs a sampled method and no shard");
  }
  GenerateResult result;
  result.shadowed.scene = std::move(input);
  const Scene& scene = result.shadowed.scene;
  result.shadowed.shard = options.shard;
  result.shadowed.method = options.method;
  const std::size_t faces = scene.faces.size(), lights = scene.lights.size();
  result.stats.resize(lights);
  result.shadowed.sun_paths = sun_paths_of(scene);
  PathSums sums(scene, result.shadowed.sun_paths, options.keep_instant_polygons && !sampled,
                options.sun_hours_regions && !sampled, options.shard);
  std::vector<bool> kept(lights);
  for (std::size_t l = 0; l < lights; ++l) {
    kept[l] = !sampled && (!sums.in_path(l) || options.keep_instant_polygons);
  }
  result.shadowed.lit = LitTable(faces, lights, std::move(kept));
  if (sampled) result.shadowed.estimated_lit_area.resize(lights);
  // The lights this run works out: in a shard, its own instants, and the lights that are
  // no instant in shard 0 alone.
  std::vector<std::size_t> todo;
  for (std::size_t l = 0; l < lights; ++l) {
    const bool wanted =
        sums.in_path(l) ? sums.summed_here(l) : !options.shard || options.shard->index == 0;
    if (wanted) todo.push_back(l);
  }
  if (todo.empty()) {
    sums.finish();
    return result;
  }

  const int threads =
      options.threads ? static_cast<int>(options.threads) : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  detail::FaceParts parts;
  std::optional<detail::ClosedSolids> solids;
  arena.execute([&] {
    parts = detail::flatten(scene);
    if (!sampled && options.leave_out_solids_backs) solids.emplace(parts);
  });
  std::mutex report_mutex;
  // Lights in parallel, and within each light the regions of its views (hsr/
  // image_regions.h) and its receivers, all on one pool of `threads` threads. The failure
  // passed on is the first light's whatever the threads did. With sun paths, the lights
  // go in batches, each summed before the next starts.
  const std::size_t batch_size = result.shadowed.sun_paths.empty() ? todo.size() : kLightsPerBatch;
  arena.execute([&] {
    for (std::size_t first = 0; first < todo.size(); first += batch_size) {
      const std::vector<std::size_t> batch(
          todo.begin() + static_cast<std::ptrdiff_t>(first),
          todo.begin() + static_cast<std::ptrdiff_t>(std::min(todo.size(), first + batch_size)));
      std::vector<std::vector<std::vector<LitPolygon>>> per_light(sampled ? 0 : batch.size());
      std::vector<std::vector<std::vector<double>>> estimated(sampled ? batch.size() : 0);
      hsr::for_each_in_parallel(batch.size(), [&](std::size_t i) {
        const std::size_t l = batch[i];
        const auto start = std::chrono::steady_clock::now();
        if (sampled) {
          estimated[i] = options.estimate(scene.lights[l]);
        } else {
          per_light[i] = light_one_named(scene, parts, solids ? &*solids : nullptr, l, options,
                                         result.stats[l]);
        }
        result.stats[l].seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (options.on_light_done) {
          const std::lock_guard lock(report_mutex);
          options.on_light_done(l, result.stats[l]);
        }
      });
      sums.add(batch, per_light, estimated);
      for (std::size_t i = 0; i < batch.size(); ++i) {
        const std::size_t l = batch[i];
        if (sampled) {
          if (sums.in_path(l)) continue;
          std::vector<double>& column = result.shadowed.estimated_lit_area[l];
          column.assign(faces, 0.0);
          for (std::size_t f = 0; f < faces; ++f) {
            for (const double a : estimated[i].at(f)) column[f] += a;
          }
          continue;
        }
        if (!result.shadowed.lit.kept(l)) continue;
        for (std::size_t f = 0; f < faces; ++f)
          result.shadowed.lit[f][l] = std::move(per_light[i][f]);
      }
    }
    sums.finish();
  });
  return result;
}

}  // namespace shadowgen
