#pragma once

// The per-light loop both generators share (generate.h, estimate_shadows.h): the lights of
// a run in parallel, each timed and reported, in batches that are handed on in light order
// before the next batch starts, so that sun paths are summed a few instants at a time
// (sun_path_sums.h) and in one order whatever the thread count.

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <vector>

#include "hsr/parallel.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::shadows::detail {

// Lights generated before their instants are summed: few enough that a path's lit
// polygons never all sit in memory, enough to keep the threads busy.
inline constexpr std::size_t kLightsPerBatch = 16;

// An arena of `threads` threads (0: one per hardware thread).
inline tbb::task_arena arena_of(unsigned threads) {
  return tbb::task_arena(threads ? static_cast<int>(threads) : tbb::info::default_concurrency());
}

// Runs `light(l, stats[l])` for every light l of `lights`, in parallel, each timed into
// stats[l].seconds and then passed to `on_light_done` (one call at a time), and
// `batch_done(batch, results)` after each batch of lights, results[i] light batch[i]'s. One
// batch of all the lights where `batches` is false. Call it in the run's arena. The failure
// passed on is the first light's whatever the threads did.
template <class Light, class BatchDone>
void run_lights(const std::vector<std::size_t>& lights, bool batches,
                const std::function<void(std::size_t, const LightStats&)>& on_light_done,
                std::vector<LightStats>& stats, Light&& light, BatchDone&& batch_done) {
  using Result = decltype(light(std::size_t{}, stats.front()));
  std::mutex report_mutex;
  const std::size_t batch_size = batches ? kLightsPerBatch : lights.size();
  for (std::size_t first = 0; first < lights.size(); first += batch_size) {
    const std::vector<std::size_t> batch(
        lights.begin() + static_cast<std::ptrdiff_t>(first),
        lights.begin() + static_cast<std::ptrdiff_t>(std::min(lights.size(), first + batch_size)));
    std::vector<Result> results(batch.size());
    hsr::for_each_in_parallel(batch.size(), [&](std::size_t i) {
      const std::size_t l = batch[i];
      const auto start = std::chrono::steady_clock::now();
      results[i] = light(l, stats[l]);
      stats[l].seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (on_light_done) {
        const std::lock_guard lock(report_mutex);
        on_light_done(l, stats[l]);
      }
    });
    batch_done(batch, results);
  }
}

}  // namespace shadowgen::shadows::detail
