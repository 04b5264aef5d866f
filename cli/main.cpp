// shadowgen: exact object-space polygon shadows (Atherton, Weiler and Greenberg 1978).
// Only argument parsing and wiring live here and in the *_command.cpp files; the work is
// in the shadowgen library.
//
// Exit codes: 0 success; 1 bad input or output that could not be written; 2 a usage
// error; 3 shadows that could not be computed exactly (an internal limit, not the input's
// fault). On 1 and 3, one line "shadowgen: <message>" on stderr, naming the file, and the
// face and light where there are ones, and no partial output file left behind.

#include <CLI/CLI.hpp>
#include <exception>
#include <functional>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/out_of_memory.h"
#include "clipper/clip.h"
#include "hsr/hidden_surface.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/shadowgen.h"
#include "shadowgen/shadows/generate.h"

namespace {

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;
constexpr int kExitNotComputed = 3;

int fail(const std::exception& e, int code) {
  std::cerr << "shadowgen: " << e.what() << '\n';
  return code;
}

// The inputs the subcommand was given: its positional "input", generate's "scene" files
// or render's "database", joined by ", ".
std::string inputs_of(const CLI::App& parser) {
  std::string names;
  for (const char* name : {"input", "scene", "database"}) {
    const CLI::Option* option = parser.get_option_no_throw(name);
    if (option == nullptr) continue;
    for (const std::string& file : option->results()) names += (names.empty() ? "" : ", ") + file;
  }
  return names;
}

// Runs a parsed subcommand; its errors become one line and an exit code.
int run(const shadowgen::cli::Command& command) {
  try {
    command.run();
  } catch (const std::bad_alloc&) {
    // out_of_memory.h keeps the unwinding to here from ending the program.
    std::cerr << "shadowgen: " << shadowgen::one_line(inputs_of(*command.parser)) << ": "
              << shadowgen::kOutOfMemoryProblem << '\n';
    return kExitBadInput;
  } catch (const shadowgen::cli::UsageError& e) {
    std::cerr << "shadowgen: " << e.what() << "\nRun with --help for more information.\n";
    return kExitUsage;
  } catch (const shadowgen::GenerationError& e) {
    return fail(e, kExitNotComputed);
  } catch (const shadowgen::api::GenerationError& e) {
    return fail(e, kExitNotComputed);
  } catch (const shadowgen::clipper::SnapRoundingError& e) {
    // From a clip outside shadow generation (light regions, hidden-surface removal from
    // the eye), which does not yet name the face.
    return fail(e, kExitNotComputed);
  } catch (const shadowgen::hsr::PolygonClipError& e) {
    return fail(e, kExitNotComputed);
  } catch (const std::exception& e) {
    // InputError's message already names the file and the face; I/O errors name the path.
    return fail(e, kExitBadInput);
  }
  return 0;
}

// Where parsing failed for want of a subcommand: the word given in its place, or none,
// said with the subcommands there are (CLI11 says only "A subcommand is required").
std::optional<std::string> subcommand_problem(const CLI::App& app, const CLI::ParseError& e) {
  if (dynamic_cast<const CLI::RequiredError*>(&e) == nullptr || app.get_subcommands().size() > 0) {
    return std::nullopt;
  }
  std::string names;
  for (const CLI::App* command : app.get_subcommands({})) {
    names += (names.empty() ? "" : ", ") + command->get_name();
  }
  const std::vector<std::string> words = app.remaining();
  if (words.empty()) return "a subcommand is required: " + names;
  if (words.front().rfind('-', 0) == 0) {
    return shadowgen::one_line(words.front()) +
           ": not an option of shadowgen; a subcommand comes first: " + names;
  }
  return shadowgen::one_line(words.front()) +
         ": not a subcommand of shadowgen (its subcommands: " + names + ")";
}

}  // namespace

int main(int argc, char** argv) {
  shadowgen::cli::set_aside_memory_for_unwinding(64u << 20);
  // From the start, so that a closed pipe or the file size limit fails a write with a
  // message, and a signal at any time leaves no temporary file (atomic_file.h).
  shadowgen::install_temporary_file_cleanup();
  CLI::App app{"shadowgen: exact polygon shadows (Atherton, Weiler and Greenberg 1978)",
               "shadowgen"};
  app.set_version_flag("--version", std::string("shadowgen ") + SHADOWGEN_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 bad input or unwritable output, 2 usage error, 3 shadows "
      "that could not be computed exactly.");
  const shadowgen::cli::Command commands[] = {
      shadowgen::cli::add_generate_command(app), shadowgen::cli::add_report_command(app),
      shadowgen::cli::add_export_command(app),   shadowgen::cli::add_render_command(app),
      shadowgen::cli::add_sun_command(app),      shadowgen::cli::add_merge_command(app),
      shadowgen::cli::add_compare_command(app),  shadowgen::cli::add_view_command(app)};

  // Parse errors read as the other errors do: "shadowgen: " and one line, then the hint.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "shadowgen: " + std::string(e.what()) + "\nRun with --help for more information.\n";
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (const std::optional<std::string> problem = subcommand_problem(app, e)) {
      std::cerr << "shadowgen: " << *problem << "\nRun with --help for more information.\n";
      return kExitUsage;
    }
    const int code = app.exit(e);  // prints the help, the version or the error
    return code == 0 ? 0 : kExitUsage;
  }
  for (const shadowgen::cli::Command& command : commands) {
    if (app.got_subcommand(command.parser)) return run(command);
  }
  return kExitUsage;  // not reached: exactly one subcommand is required
}
