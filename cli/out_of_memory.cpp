#include "cli/out_of_memory.h"

#include <cstdlib>
#include <new>

namespace shadowgen::cli {
namespace {

void* reserve = nullptr;

// operator new's handler: give the reserve back and fail this allocation. Once the
// reserve is spent, operator new throws std::bad_alloc by itself.
void give_back_reserve() {
  std::free(reserve);
  reserve = nullptr;
  std::set_new_handler(nullptr);
  throw std::bad_alloc();
}

}  // namespace

void set_aside_memory_for_unwinding(std::size_t bytes) {
  if (reserve != nullptr) return;
  reserve = std::malloc(bytes);
  if (reserve != nullptr) std::set_new_handler(give_back_reserve);
}

}  // namespace shadowgen::cli
