#pragma once

// One run of the reader fuzzer on one input, shared by the libFuzzer entry point
// (reader_fuzzer.cpp) and the corpus replay (replay_main.cpp).

#include <cstdint>
#include <span>

namespace shadowgen::fuzz {

// Reads `bytes` with the reader its first byte selects and checks the invariants listed
// in reader_fuzzer.cpp. Returns false for input the harness leaves out (a scene that
// names a file outside the fuzzer's folder, or a reader skipped by SHADOWGEN_FUZZ_SKIP).
// A broken invariant prints the input and traps: that is the fuzzer's signal.
bool run_reader_case(std::span<const std::uint8_t> bytes);

}  // namespace shadowgen::fuzz
