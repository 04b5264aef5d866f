#pragma once

// The registry of temporary files being written, which the signal cleanup of
// atomic_file.h reads: install_temporary_file_cleanup() and remove_temporary_files() are
// defined with it. Kept apart from the writer because everything here must stay
// async-signal-safe, which the writer need not be.

#include <filesystem>

namespace shadowgen::output::detail {

// Records `path` (made absolute, so that a change of the working folder cannot send the
// unlink elsewhere) for the signal handlers to remove. Returns the slot now holding it,
// or -1 when none is free or the path is too long: that write then goes unprotected
// against signals, though it is still removed on every failure the program sees.
int register_temporary(const std::filesystem::path& path);

// Frees a slot from register_temporary (-1: nothing). Unlink the file first, so that a
// signal in between still finds it.
void unregister_temporary(int slot);

}  // namespace shadowgen::output::detail
