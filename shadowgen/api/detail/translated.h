#pragma once

// The library's errors as the public API throws them (shadowgen/api/errors.h): every entry
// point runs its work through translated(), which turns the rooms' InputError and
// GenerationError, and a clip that did not settle, into the public types, what() and
// fields unchanged. Anything else (std::runtime_error of a write, std::bad_alloc, an
// error a caller's callback throws) passes through as it is.

#include <exception>
#include <utility>

namespace shadowgen::api::detail {

// Rethrows the exception in flight as a public error where it is one of the library's;
// otherwise as it is. Only inside a catch block.
[[noreturn]] void rethrow_public();

template <class Work>
decltype(auto) translated(Work&& work) {
  try {
    return std::forward<Work>(work)();
  } catch (...) {
    rethrow_public();
  }
}

}  // namespace shadowgen::api::detail
