#include "shadowgen/output/compressed_output.h"

#include "shadowgen/compressed/gzip_members.h"

namespace shadowgen {

bool gzip_named(const std::filesystem::path& path) { return path.extension() == ".gz"; }

void stream_file_compressed_as_named(const std::filesystem::path& path,
                                     const std::function<void(const OutputSink&)>& produce,
                                     int level) {
  if (!gzip_named(path)) {
    stream_file_atomically(path, produce);
    return;
  }
  stream_file_atomically(path, [&produce, level](const OutputSink& file) {
    compressed::GzipMembers members(file, level);
    produce([&members](std::string_view text) { members.write(text); });
    members.finish();
  });
}

}  // namespace shadowgen
