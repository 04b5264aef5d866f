#pragma once

// The files a run reads and writes, checked against each other in one place for every
// subcommand: a run never writes over a file it reads (its input, a merge's shards,
// --weather, a scene's mesh and weather files), and never names one file for two of its
// outputs (one would be lost). Both are usage errors, found before any shadow is
// generated and before anything is written.

#include <string>
#include <vector>

#include "shadowgen/pipeline/load_shadowed.h"
#include "shadowgen/shadowgen.h"

namespace shadowgen::cli {

// A file a run writes, and the option that names it ("-o", "--plot", "--obj's MTL").
struct OutputFile {
  std::string option;
  std::string path;
};

// What a run reads and writes. `reads` holds the files known before anything is read (the
// input or inputs, --weather); the files a scene names are added once it is read.
struct RunFiles {
  std::vector<std::string> reads;
  std::vector<OutputFile> writes;
};

// Throws UsageError when two of `writes` are one file (same_output: the same path, a
// symbolic or hard link, "-" and /dev/stdout) or one of them is one of `reads` (same_file,
// through a link, a hard link or another spelling):
//   "OPTION PATH and OTHER PATH name the same file; one would be lost"
//   "OPTION PATH: is the input FILE; it would be replaced"
void refuse_unsafe_outputs(const std::vector<OutputFile>& writes,
                           const std::vector<std::string>& reads);

// refuse_unsafe_outputs on `files` now, and on `files.writes` against Scene::files once a
// scene is read (LoadOptions::on_scene, before any shadow is generated; an on_scene set
// before runs after the check).
void guard_outputs(LoadOptions& options, const RunFiles& files);

// The same for the library's load (api::LoadSettings::on_scene, Scene::files).
void guard_outputs(api::LoadSettings& settings, const RunFiles& files);

}  // namespace shadowgen::cli
