#include "cli/out_of_memory.h"

#include <sys/mman.h>

#include <new>

namespace shadowgen::cli {
namespace {

void* reserve = nullptr;
std::size_t reserve_bytes = 0;

// operator new's handler: give the reserve back and fail this allocation. Once the
// reserve is spent, operator new throws std::bad_alloc by itself. The reserve is a
// mapping of its own, unmapped here, so that the address space goes back to the system
// whatever the allocator keeps for itself of what it is given back (jemalloc retains
// freed address space for its own later use, in sizes it chooses).
void give_back_reserve() {
  munmap(reserve, reserve_bytes);
  reserve = nullptr;
  std::set_new_handler(nullptr);
  throw std::bad_alloc();
}

}  // namespace

void set_aside_memory_for_unwinding(std::size_t bytes) {
  if (reserve != nullptr) return;
  void* block = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (block == MAP_FAILED) return;
  reserve = block;
  reserve_bytes = bytes;
  std::set_new_handler(give_back_reserve);
}

}  // namespace shadowgen::cli
