#pragma once

// The `shadowgen` subcommands, once their arguments are parsed. They throw InputError for
// bad input and std::runtime_error when output cannot be written; main turns both into a
// message and an exit code.

#include <string>

namespace shadowgen::cli {

struct GenerateArgs {
  std::string scene;
  std::string output;
  bool strict = false;
  unsigned threads = 0;  // 0: one per hardware thread
  bool quiet = false;
};

struct ReportArgs {
  std::string input;  // a scene (generated first) or a shadowed database
  std::string format = "csv";
  std::string output;  // empty: standard output
  bool strict = false;
  unsigned threads = 0;
  bool quiet = false;
};

void run_generate(const GenerateArgs& args);
void run_report(const ReportArgs& args);

}  // namespace shadowgen::cli
