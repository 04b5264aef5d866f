#pragma once

// Whole-file output that never leaves a partial file behind: the content goes to a fresh
// temporary file in the destination's folder (so the rename stays on one file system),
// is flushed to disk, and then replaces the destination with one rename. A reader sees
// either the old file or the complete new one; on any failure the temporary file is
// removed and the destination is untouched.

#include <filesystem>
#include <string>

namespace shadowgen {

// Throws std::runtime_error naming `path` and the system's reason when it cannot write.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace shadowgen
