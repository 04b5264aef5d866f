#pragma once

// Work on shadows runs on the threads they were made with (GenerateSettings::threads; 0:
// every hardware thread): what sums or writes in parallel (a report's rows, a database's
// chunks) takes no more threads than the caller gave the generation, whichever thread
// calls. The result is the same for any number. Its errors are translated (translated.h).

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <utility>

#include "detail/handles.h"
#include "detail/translated.h"

namespace shadowgen::api::detail {

// An arena of `threads` threads (GenerateSettings::threads; 0: every hardware thread).
inline tbb::task_arena arena_of(unsigned threads) {
  return tbb::task_arena(threads != 0 ? static_cast<int>(threads)
                                      : tbb::info::default_concurrency());
}

template <class Work>
decltype(auto) on_threads(const Shadows& shadows, Work&& work) {
  tbb::task_arena arena = arena_of(shadows.impl().threads);
  return arena.execute([&]() -> decltype(auto) { return translated(std::forward<Work>(work)); });
}

}  // namespace shadowgen::api::detail
