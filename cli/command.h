#pragma once

// What the subcommands of `shadowgen` share, each defined once: the shape of a subcommand,
// the reading options (--strict, --threads, --quiet) and -o/--output, and the error for
// arguments that parse but do not fit together. main.cpp wires the subcommands
// (generate_command.cpp, report_command.cpp, export_command.cpp, render_command.cpp,
// sun_command.cpp, merge_command.cpp, compare_command.cpp, view_command.cpp)
// and turns their errors into exit codes.

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/run_files.h"
#include "shadowgen/pipeline/load_shadowed.h"
#include "shadowgen/shadowgen.h"

namespace shadowgen::cli {

// Arguments that parse but do not fit together (exit code 2, as for a parse error).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A subcommand: its parser, and what runs it once the arguments are parsed. The run
// throws InputError for bad input, GenerationError where shadows cannot be computed,
// std::runtime_error where output cannot be written, and UsageError.
struct Command {
  CLI::App* parser = nullptr;
  std::function<void()> run;
};

// A subcommand's name and its help text, stated at the top of the file that defines it.
struct CommandText {
  const char* name;
  const char* help;
};

// The subcommand `text` on `app`: `add_options` declares its options on arguments kept
// alive with the run, and `run` runs it on them once they are parsed.
template <class Args>
Command make_command(CLI::App& app, const CommandText& text, void (*add_options)(CLI::App&, Args&),
                     void (*run)(const Args&)) {
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(text.name, text.help);
  add_options(*command, *args);
  return {command, [args, run] { run(*args); }};
}

Command add_generate_command(CLI::App& app);
Command add_report_command(CLI::App& app);
Command add_export_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_sun_command(CLI::App& app);
Command add_merge_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_view_command(CLI::App& app);

// How an input is read and its shadows generated.
struct ReadingArgs {
  bool strict = false;
  unsigned threads = 0;             // 0: one per hardware thread
  bool quiet = false;               // no reading warnings (and no progress line)
  bool verbose = false;             // every reading warning on its own line (ReadOptions::verbose)
  std::vector<std::string> lights;  // --lights: only these (LoadOptions::lights)
};

// --strict, --threads, --lights, --verbose and -q/--quiet on `command`; `progress`: the subcommand
// shows a progress line, which --quiet also silences; without `generates` (a subcommand that
// computes no shadow), no --threads.
void add_reading_options(CLI::App& command, ReadingArgs& args, bool progress = false,
                         bool generates = true);

// How lit areas are found (--method, --samples, --resolution; LoadOptions::method).
struct MethodArgs {
  std::string name = "exact";
  int samples = kDefaultSamples;
  int resolution = kDefaultResolution;
  CLI::Option* samples_option = nullptr;
  CLI::Option* resolution_option = nullptr;

  // The method asked for; a UsageError where --samples or --resolution comes with a
  // method that takes none.
  Method method() const;
  // The same, set in `settings` (the library's GenerateSettings).
  void apply(api::GenerateSettings& settings) const;
};

// --method, --samples and --resolution on `command`.
void add_method_options(CLI::App& command, MethodArgs& args);

// --lights on `command`: the ids of the only lights a run takes (LoadOptions::lights);
// `others` says what becomes of the others ("a scene's other lights are not generated").
void add_lights_option(CLI::App& command, std::vector<std::string>& ids, const std::string& others);

// The required positional "input" on `command`: a scene or a shadowed database.
void add_input_option(CLI::App& command, std::string& path);

// -o/--output on `command`, described as naming `what`.
CLI::Option* add_output_option(CLI::App& command, std::string& path, const std::string& what);

// The loading options these arguments ask for: reading warnings on stderr unless quiet.
// `files`: what the run reads and writes, checked before the load (guard_outputs), so
// that no output is an input, the files a scene names included, and no two outputs are
// one file.
LoadOptions load_options(const ReadingArgs& args, Accept accept, const RunFiles& files = {});

// The same for the library's load (shadowgen/shadowgen.h): a scene or a database, `files`
// checked as load_options checks them.
api::LoadSettings load_settings(const ReadingArgs& args, const RunFiles& files = {});

// How the library reads a scene for these arguments: reading warnings on stderr unless quiet.
api::ReadSettings read_settings(const ReadingArgs& args);

}  // namespace shadowgen::cli
