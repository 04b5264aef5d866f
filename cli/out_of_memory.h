#pragma once

// Running out of memory, reported rather than aborted.
//
// Some destructors allocate: nlohmann::json frees a large tree through a stack of its
// children, a std::vector it grows as it goes. When an allocation fails while a scene is
// read, the unwinding destroys that tree, its allocation fails as well, and a destructor
// that throws ends the program (std::terminate: exit 134, and no word of which input).
// So a block is set aside at start; the first failed allocation frees it and throws
// std::bad_alloc, and the unwinding that follows allocates from what it gave back. The
// command line then reports the input and exits 1.

#include <cstddef>

namespace shadowgen::cli {

// Sets `bytes` aside (address space only: the pages are never touched) and installs the
// handler that gives them back on the first failed allocation. Call once, at start.
void set_aside_memory_for_unwinding(std::size_t bytes);

}  // namespace shadowgen::cli
