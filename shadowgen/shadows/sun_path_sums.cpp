#include "shadowgen/shadows/sun_path_sums.h"

#include <string>
#include <utility>

#include "clipper/clip.h"
#include "hsr/area.h"
#include "hsr/parallel.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {

SunPathSums::SunPathSums(const Scene& scene, std::vector<SunPathHours>& paths, bool keep_polygons,
                         bool regions, const std::optional<ShardPlace>& shard)
    : scene_(scene), paths_(paths), regions_(regions), shard_(shard), place_(scene.lights.size()) {
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

std::vector<std::size_t> SunPathSums::lights_of_run() const {
  std::vector<std::size_t> lights;
  for (std::size_t l = 0; l < place_.size(); ++l) {
    const bool wanted = in_path(l) ? place_[l].has_value() : !shard_ || shard_->index == 0;
    if (wanted) lights.push_back(l);
  }
  return lights;
}

template <class Work>
void SunPathSums::named(std::size_t f, std::size_t p, Work&& work) const {
  try {
    work();
  } catch (const clipper::SnapRoundingError& e) {
    throw GenerationError("", scene_.faces[f].id, paths_[p].id,
                          "sun hours not computed: " + std::string(e.what()));
  }
}

template <class Work>
void SunPathSums::each_summed(const std::vector<std::size_t>& batch, Work&& work) {
  hsr::for_each_in_parallel(scene_.faces.size(), [&](std::size_t f) {
    for (std::size_t i = 0; i < batch.size(); ++i) {
      const std::optional<PathPlace>& place = place_[batch[i]];
      if (place) work(i, f, place->path, place->instant);
    }
  });
}

void SunPathSums::add_lit(const std::vector<std::size_t>& batch,
                          const std::vector<std::vector<std::vector<LitPolygon>>>& lit) {
  each_summed(batch, [&](std::size_t i, std::size_t f, std::size_t p, std::size_t k) {
    PathState& state = state_[p];
    const std::size_t own = k - state.first;
    const std::vector<LitPolygon>& polygons = lit[i][f];
    paths_[p].lit_area[f][own] = lit_area(polygons);
    if (!paths_[p].part_lit_area[f].empty()) {
      for (const LitPolygon& lit_polygon : polygons) {
        paths_[p].part_lit_area[f].at(lit_polygon.part)[own] += hsr::area(lit_polygon.polygon);
      }
    }
    if (!regions_) return;
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
  });
}

void SunPathSums::add_estimated(const std::vector<std::size_t>& batch,
                                const std::vector<std::vector<std::vector<double>>>& estimated) {
  each_summed(batch, [&](std::size_t i, std::size_t f, std::size_t p, std::size_t k) {
    const std::size_t own = k - state_[p].first;
    const bool by_part = !paths_[p].part_lit_area[f].empty();
    const std::vector<double>& parts = estimated[i][f];
    double sum = 0.0;
    for (std::size_t part = 0; part < parts.size(); ++part) {
      sum += parts[part];
      if (by_part) paths_[p].part_lit_area[f].at(part)[own] = parts[part];
    }
    paths_[p].lit_area[f][own] = sum;
  });
}

void SunPathSums::finish() {
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
      named(f, p, [&] { hours = join_nodes(std::move(nodes), block_count(path.instants.size())); });
      if (!hours) hours.emplace(scene_.faces[f]);  // lit at no instant
      path.regions[f] = hours->regions(path.step_min);
    });
  }
}

}  // namespace shadowgen
