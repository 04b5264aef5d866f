#pragma once

// The `shadowgen` subcommands, once their arguments are parsed. They throw InputError for
// bad input, std::runtime_error when output cannot be written and UsageError for arguments
// that parse but do not fit together; main turns these into a message and an exit code.

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadowgen::cli {

// Arguments that parse but do not fit together (exit code 2, as for a parse error).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Several scenes are processed in turn, each read, generated and written (atomically)
// before the next is read. Where the databases go (generate_outputs): with one scene,
// `output` is the database file; with several, `output` is a folder (made when missing)
// and scene DIR/NAME.json gives OUTPUT/NAME.shadowed.json. A bad scene stops the run with
// its error: the databases of the scenes before it stay written, none is written for it
// or for the scenes after it.
struct GenerateArgs {
  std::vector<std::string> scenes;
  std::string output;
  bool strict = false;
  unsigned threads = 0;  // 0: one per hardware thread
  bool quiet = false;    // no warnings, no progress line
};

// The database path of each scene, in order, by the rule above. Checked before any work:
// throws UsageError when, with several scenes, two of them would be written to the same
// file, a database would replace one of the scenes, or `output` exists and is not a
// folder.
std::vector<std::filesystem::path> generate_outputs(const std::vector<std::string>& scenes,
                                                    const std::string& output);

struct ReportArgs {
  std::string input;           // a scene (generated first) or a shadowed database
  std::string format = "csv";  // csv, json or table
  std::string output;          // empty: standard output
  std::size_t top = 10;        // table: most shadowed faces listed per light
  bool strict = false;
  unsigned threads = 0;
  bool quiet = false;
};

// A picture of a shadowed database (never a scene: no shadow pass runs) from the
// database's view `view` or from eye/target/up/fov, as SVG.
struct RenderArgs {
  std::string database;
  std::string view;                          // a view id of the database, or empty
  std::optional<std::array<double, 3>> eye;  // given with target when view is empty
  std::array<double, 3> target{0.0, 0.0, 0.0};
  std::array<double, 3> up{0.0, 0.0, 1.0};
  double fov_deg = 45.0;
  bool ortho = false;
  double scale = 0.0;  // orthographic pixels per scene unit; 0 fits the scene
  std::string svg;
  int width = 800;
  int height = 600;
};

// The shadowed scene as a Wavefront OBJ with its MTL next to it (same stem, ".mtl"): every
// face split by the set of lights reaching it, one material per set (shadowgen/obj_export.h).
struct ExportArgs {
  std::string input;  // a scene (generated first) or a shadowed database
  std::string obj;    // OBJ file to write; the MTL goes next to it
  bool strict = false;
  unsigned threads = 0;
  bool quiet = false;
};

void run_generate(const GenerateArgs& args);
void run_report(const ReportArgs& args);
void run_export(const ExportArgs& args);
void run_render(const RenderArgs& args);

}  // namespace shadowgen::cli
