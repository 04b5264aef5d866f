#pragma once

// One run of the clip fuzzer on one input, shared by the libFuzzer entry point and the
// corpus replay (replay_main.cpp).

#include <cstdint>
#include <span>

namespace shadowgen::fuzz {

// Decodes `bytes` (fuzz_input.h) and, when both sets are well formed (region_validity.h),
// clips them and checks the invariants listed in clip_fuzzer.cpp. Returns false for input
// outside clip()'s contract, which is skipped. A broken invariant prints the decoded input
// and traps: that is the fuzzer's signal.
bool run_clip_case(std::span<const std::uint8_t> bytes);

}  // namespace shadowgen::fuzz
