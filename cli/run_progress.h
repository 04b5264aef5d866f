#pragma once

// The progress line of a subcommand's run (cli/progress.h) as every long-running
// subcommand shows it: the lights of the scene it generates, then its own stages. The line
// appears only once the input is read, so that reading warnings keep lines of their own,
// and is ended before anything else is printed.

#include <cstddef>
#include <functional>
#include <optional>
#include <ostream>
#include <string>

#include "cli/progress.h"
#include "shadowgen/pipeline/load_shadowed.h"
#include "shadowgen/shadowgen.h"

namespace shadowgen::cli {

// Where a run's progress goes: standard error where it is a terminal and the run is not
// `quiet`; nullptr (silence) otherwise.
std::ostream* progress_stream(bool quiet);

class RunProgress {
 public:
  // The progress of a run on `input` (as the user named it), drawn on `out`; silent where
  // `out` is nullptr.
  RunProgress(std::string input, std::ostream* out);

  // Shows what loading with `options` does: the generation of a scene, its lights counted
  // from the time it is read (a database read as it is shows nothing new). Chains
  // on_scene; each reading warning ends the open line first, so that it has a line of its
  // own.
  void watch(LoadOptions& options);
  // The same for the library's load.
  void watch(api::LoadSettings& settings);
  // The run's stage from now on ("splitting faces by light sets").
  void stage(const std::string& what);
  // Lights generated outside a load (compare's trials): `total` of them from now on; the
  // callback for GenerateOptions::on_light_done, empty where the progress is silent.
  std::function<void(std::size_t, const LightStats&)> lights(std::size_t total);
  // Ends the line (before output on the terminal, and at the end of the run).
  void finish();

 private:
  void show(const ProgressLine& line);

  std::string input_;
  std::ostream* out_;
  std::optional<ProgressDisplay> display_;
};

}  // namespace shadowgen::cli
