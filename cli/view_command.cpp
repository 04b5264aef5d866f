// `shadowgen view`: the shadowed scene as a static page a browser opens from the file
// system (shadowgen/viewer/viewer_page.h).

#include <filesystem>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/run_progress.h"
#include "cli/sun_hours_options.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/viewer/viewer_model.h"
#include "shadowgen/viewer/viewer_page.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kViewText{
    "view",
    "Write a page that shows the shadowed scene in 3D in a browser, opened from the file "
    "system with no network: DIR/index.html, with its script (three.js bundled in) and the "
    "model (DIR/viewer.js, DIR/model.js). Every face split into the regions lit by the same "
    "set of lights, coloured as export's materials; or, with --sun-hours, a sun path's "
    "bands of sun hours. The page has orbit controls, a legend whose boxes hide and show "
    "each light set or band (and switch lights off), a north arrow, and shows the face "
    "under the pointer: its id, area and lit area per light (or mean sun hours). A scene "
    "is generated first; a shadowed database is read as it is."};

struct ViewArgs {
  std::string input;  // a scene (generated first) or a shadowed database
  std::string dir;    // the page's folder
  ReadingArgs reading;
  SunHoursArgs sun_hours;
};

void run_view(const ViewArgs& args) {
  const std::filesystem::path dir = args.dir;
  if (args.dir == "-") throw UsageError("-o -: a page is a folder of files, not one stream");
  // Found before any work, so that a build without the page's assets fails at once.
  const std::filesystem::path assets = viewer_assets_folder();
  LoadOptions load = load_options(args.reading, Accept::kSceneOrDatabase,
                                  {{args.input},
                                   {{"-o", (dir / "index.html").string()},
                                    {"-o", (dir / "viewer.js").string()},
                                    {"-o", (dir / "model.js").string()}}});
  load_to_draw(load, args.sun_hours, args.input);
  RunProgress progress(args.input, progress_stream(args.reading.quiet));
  progress.watch(load);
  const ShadowedScene shadowed = load_shadowed(args.input, load);
  std::optional<SunHoursMap> map;
  if (!args.sun_hours.path.empty()) map = sun_hours_map(shadowed, args.sun_hours, args.input);
  progress.stage(map ? "splitting faces by bands of sun hours" : "splitting faces by light sets");
  ViewerModel model;
  try {
    model = map ? viewer_model(shadowed, *map->path, map->bands) : viewer_model(shadowed);
  } catch (const GenerationError& e) {
    throw GenerationError(args.input, e.face_id(), e.light_id(), e.problem());
  }
  progress.stage("writing " + args.dir);
  write_viewer_page(dir, assets, viewer_model_script(model));
  progress.finish();
}

void add_view_options(CLI::App& command, ViewArgs& args) {
  add_input_option(command, args.input);
  add_output_option(command, args.dir,
                    "folder of the page (made if missing; its index.html, viewer.js and "
                    "model.js replaced)")
      ->required();
  add_reading_options(command, args.reading, /*progress=*/true);
  CLI::Option* sun_hours = add_sun_hours_options(command, args.sun_hours, "show");
  sun_hours->excludes(command.get_option("--lights"));
}

}  // namespace

Command add_view_command(CLI::App& app) {
  return make_command<ViewArgs>(app, kViewText, add_view_options, run_view);
}

}  // namespace shadowgen::cli
