// Replays fuzzer inputs without libFuzzer, so a corpus runs under CTest with any compiler:
//   clip_fuzz_replay   [--require-well-formed] FILE_OR_DIRECTORY...   (clip_fuzzer.cpp)
//   reader_fuzz_replay [--require-well-formed] FILE_OR_DIRECTORY...   (reader_fuzzer.cpp,
//                                          built with SHADOWGEN_REPLAY_READERS defined)
// A directory stands for the regular files directly inside it, in name order. A broken
// invariant traps inside the case (after printing the file name and the decoded input);
// --require-well-formed also fails when an input is one the case leaves out (outside
// clip()'s contract; for the readers, a scene naming a file outside the fuzzer's folder),
// which a seed corpus should never hold.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string_view>
#include <vector>

#ifdef SHADOWGEN_REPLAY_READERS
#include "tests/fuzz/reader_fuzz_case.h"
#else
#include "tests/fuzz/clip_fuzz_case.h"
#endif

namespace fs = std::filesystem;

namespace {
#ifdef SHADOWGEN_REPLAY_READERS
constexpr const char* kName = "reader_fuzz_replay";
bool run_case(std::span<const std::uint8_t> bytes) {
  return shadowgen::fuzz::run_reader_case(bytes);
}
#else
constexpr const char* kName = "clip_fuzz_replay";
bool run_case(std::span<const std::uint8_t> bytes) { return shadowgen::fuzz::run_clip_case(bytes); }
#endif
}  // namespace

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
      std::fprintf(stderr, "%s: no such file or directory: %s\n", kName, argv[i]);
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: %s [--require-well-formed] FILE_OR_DIRECTORY...\n", kName);
    return 2;
  }

  std::size_t well_formed = 0;
  std::vector<fs::path> skipped;
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    if (!in.good() && !in.eof()) {
      std::fprintf(stderr, "%s: cannot read %s\n", kName, file.c_str());
      return 2;
    }
    std::fprintf(stderr, "%s: %s\n", kName, file.c_str());
    if (run_case(bytes)) {
      ++well_formed;
    } else {
      skipped.push_back(file);
    }
  }
  std::printf("%s: %zu input(s), %zu well formed\n", kName, files.size(), well_formed);
  for (const fs::path& file : skipped)
    std::printf("  left out (outside the contract): %s\n", file.c_str());
  return require_well_formed && !skipped.empty() ? 1 : 0;
}
