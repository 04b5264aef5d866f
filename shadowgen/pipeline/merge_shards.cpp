#include "shadowgen/pipeline/merge_shards.h"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <utility>

#include "clipper/clip.h"
#include "hsr/parallel.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/scene/database_reader.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/shadows/sun_hours.h"
#include "shadowgen/shadows/sun_hours_tree.h"

namespace shadowgen {
namespace {

// What every shard of one run shares, as text: the scene (faces, lights and views, as a
// database without lit details writes them) and each path's id, step, span and kind.
std::string run_text(const ShadowedScene& shard) {
  const ShadowedScene bare(shard.scene(),
                           LitTable(shard.scene().faces.size(), shard.scene().lights.size()));
  std::string text = database_json(bare);
  for (const SunPathHours& path : shard.sun_paths) {
    text += "\n" + path.id + " " + std::to_string(path.step_min) + " " + path.from + " " + path.to +
            (path.lit_polygons_kept ? " kept" : " dropped") +
            (path.regions_kept ? " regions" : " areas");
  }
  return text;
}

// The shards in order of their index, each once, all of one run.
std::vector<ShardFile> in_order(std::vector<ShardFile> shards) {
  if (shards.empty()) throw std::invalid_argument("merge_shards: no shards");
  for (const ShardFile& shard : shards) {
    if (!shard.shadowed.shard) {
      throw InputError(shard.file, "",
                       "is a whole shadowed database, not a shard of a run cut by "
                       "generate --instants K/N");
    }
  }
  const std::size_t count = shards.front().shadowed.shard->count;
  const std::string first_file = shards.front().file;
  std::vector<std::optional<ShardFile>> by_index(count);
  for (ShardFile& shard : shards) {
    const ShardPlace& place = *shard.shadowed.shard;
    if (place.count != count) {
      throw InputError(shard.file, "",
                       "is shard " + std::to_string(place.index + 1) + " of " +
                           std::to_string(place.count) + ", " + first_file + " one of " +
                           std::to_string(count));
    }
    if (by_index[place.index]) {
      throw InputError(shard.file, "",
                       "is shard " + std::to_string(place.index + 1) + " of " +
                           std::to_string(count) + ", as " + by_index[place.index]->file + " is");
    }
    by_index[place.index] = std::move(shard);
  }
  std::vector<ShardFile> out;
  std::string missing;
  for (std::size_t k = 0; k < count; ++k) {
    if (!by_index[k]) {
      missing += (missing.empty() ? "" : ", ") + std::to_string(k + 1);
    } else {
      out.push_back(std::move(*by_index[k]));
    }
  }
  if (!missing.empty()) {
    throw InputError(out.front().file, "",
                     "shards " + missing + " of " + std::to_string(count) +
                         " are missing: merge needs every shard of the run");
  }
  const std::string first = run_text(out.front().shadowed);
  for (std::size_t k = 1; k < count; ++k) {
    if (run_text(out[k].shadowed) != first) {
      throw InputError(out[k].file, "",
                       "is a shard of another scene than " + out.front().file +
                           " (its faces, lights, views or sun paths differ)");
    }
  }
  return out;
}

}  // namespace

ShadowedScene merge_shards(std::vector<ShardFile> given) {
  std::vector<ShardFile> shards = in_order(std::move(given));
  ShadowedScene merged = std::move(shards.front().shadowed);
  merged.shard.reset();
  const Scene& scene = merged.scene();
  const std::size_t faces = scene.faces.size();
  for (std::size_t p = 0; p < merged.sun_paths.size(); ++p) {
    SunPathHours& path = merged.sun_paths[p];
    // The lit areas, shard after shard; the nodes of every shard per face.
    std::vector<std::vector<SumsNode>> nodes(faces);
    std::vector<std::vector<SunHoursNode>> first_nodes = std::move(path.nodes);
    for (std::size_t k = 1; k < shards.size(); ++k) {
      SunPathHours& part = shards[k].shadowed.sun_paths[p];
      for (std::size_t f = 0; f < faces; ++f) {
        std::vector<double>& areas = path.lit_area[f];
        areas.insert(areas.end(), part.lit_area[f].begin(), part.lit_area[f].end());
        for (std::size_t i = 0; i < path.part_lit_area[f].size(); ++i) {
          std::vector<double>& on_part = path.part_lit_area[f][i];
          on_part.insert(on_part.end(), part.part_lit_area[f][i].begin(),
                         part.part_lit_area[f][i].end());
        }
      }
    }
    path.nodes.clear();
    path.shard_first = path.shard_last = 0;
    if (!path.regions_kept) continue;  // lit areas alone
    path.regions.assign(faces, {});
    const std::size_t blocks = block_count(path.instants.size());
    std::vector<std::optional<InputError>> bad(faces);
    hsr::for_each_in_parallel(faces, [&](std::size_t f) {
      const Face& face = scene.faces[f];
      std::vector<SumsNode> joined;
      for (std::size_t k = 0; k < shards.size(); ++k) {
        const std::vector<SunHoursNode>& own =
            k == 0 ? first_nodes[f] : shards[k].shadowed.sun_paths[p].nodes[f];
        for (const SunHoursNode& node : own) {
          SumsNode& sums = joined.emplace_back();
          sums.first_block = node.first_block;
          sums.level = node.level;
          if (node.sums.parts.empty()) continue;  // lit at none of its instants
          try {
            sums.sums.emplace(face, node.sums);
          } catch (const std::invalid_argument& e) {
            bad[f].emplace(shards[k].file, face.id,
                           "sun path '" + path.id + "': " + std::string(e.what()));
            return;
          }
        }
      }
      try {
        std::optional<FaceSunHours> hours = join_nodes(std::move(joined), blocks);
        if (!hours) hours.emplace(face);  // lit at no instant
        path.regions[f] = hours->regions(path.step_min);
      } catch (const clipper::SnapRoundingError& e) {
        throw GenerationError("", face.id, path.id,
                              "sun hours not computed: " + std::string(e.what()));
      } catch (const std::invalid_argument& e) {
        bad[f].emplace(shards.front().file, face.id,
                       "sun path '" + path.id + "': " + std::string(e.what()));
      }
    });
    for (std::optional<InputError>& error : bad) {
      if (error) throw *error;
    }
  }
  // The joined sums get the checks any database read gets (regions on their faces, tiling
  // them, agreeing with the lit areas): a shard edited by hand fails them here, before a
  // file is written, not in whichever command reads the file next.
  try {
    parse_database(database_json(merged), shards.front().file);
  } catch (const InputError& e) {
    throw InputError(shards.front().file, e.face_id(),
                     "the shards joined do not make a valid database: " + e.problem());
  }
  return merged;
}

}  // namespace shadowgen
