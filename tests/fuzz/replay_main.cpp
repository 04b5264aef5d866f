// Replays clip fuzzer inputs without libFuzzer, so the corpus runs under CTest with any
// compiler: clip_fuzz_replay [--require-well-formed] FILE_OR_DIRECTORY...
// A directory stands for the regular files directly inside it, in name order. A broken
// invariant traps inside the case (after printing the file name and the decoded input);
// --require-well-formed also fails when an input is outside clip()'s contract, which a
// seed corpus should never be.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <vector>

#include "tests/fuzz/clip_fuzz_case.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  bool require_well_formed = false;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--require-well-formed") {
      require_well_formed = true;
    } else if (fs::is_directory(arg)) {
      std::vector<fs::path> inside;
      for (const fs::directory_entry& entry : fs::directory_iterator(arg)) {
        if (entry.is_regular_file()) inside.push_back(entry.path());
      }
      std::sort(inside.begin(), inside.end());
      files.insert(files.end(), inside.begin(), inside.end());
    } else if (fs::is_regular_file(arg)) {
      files.emplace_back(arg);
    } else {
      std::fprintf(stderr, "clip_fuzz_replay: no such file or directory: %s\n", argv[i]);
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: clip_fuzz_replay [--require-well-formed] FILE_OR_DIRECTORY...\n");
    return 2;
  }

  std::size_t well_formed = 0;
  std::vector<fs::path> skipped;
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    if (!in.good() && !in.eof()) {
      std::fprintf(stderr, "clip_fuzz_replay: cannot read %s\n", file.c_str());
      return 2;
    }
    std::fprintf(stderr, "clip_fuzz_replay: %s\n", file.c_str());
    if (shadowgen::fuzz::run_clip_case(bytes)) {
      ++well_formed;
    } else {
      skipped.push_back(file);
    }
  }
  std::printf("clip_fuzz_replay: %zu input(s), %zu well formed\n", files.size(), well_formed);
  for (const fs::path& file : skipped) std::printf("  outside the contract: %s\n", file.c_str());
  return require_well_formed && !skipped.empty() ? 1 : 0;
}
