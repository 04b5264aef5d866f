#pragma once

// Text made of many independent records (a report's rows), written in chunks on the
// calling task arena's threads and joined in order: the same bytes as one loop writing
// them in turn, whatever the threads.

#include <cstddef>
#include <string>
#include <vector>

#include "hsr/parallel.h"

namespace shadowgen::output::detail {

// Records per chunk: a row of a report takes about a microsecond to write, so a chunk is
// far above a task's cost and far below a thread's share of a large scene's rows.
inline constexpr std::size_t kRecordsPerChunk = 2048;

// Appends to `out` what write(text, i) appends for every record i in [0, count), in order.
// write may run on several threads at once, each call on its own string; where calls
// throw, the exception of the lowest record is passed on (as writing in order meets it
// first) and `out` is left as it was.
template <class Write>
void append_in_chunks(std::string& out, std::size_t count, Write&& write) {
  const std::size_t chunks = (count + kRecordsPerChunk - 1) / kRecordsPerChunk;
  std::vector<std::string> texts(chunks);
  hsr::for_each_in_parallel(chunks, [&](std::size_t c) {
    const std::size_t last = std::min(count, (c + 1) * kRecordsPerChunk);
    for (std::size_t i = c * kRecordsPerChunk; i < last; ++i) write(texts[c], i);
  });
  std::size_t size = out.size();
  for (const std::string& text : texts) size += text.size();
  out.reserve(size);
  for (const std::string& text : texts) out += text;
}

}  // namespace shadowgen::output::detail
