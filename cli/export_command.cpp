// `shadowgen export`: the shadowed scene as a Wavefront OBJ and its MTL.

#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/output_by_extension.h"
#include "cli/run_progress.h"
#include "cli/sun_hours_options.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/obj_export.h"
#include "shadowgen/output/sun_hours_export.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kExportText{
    "export",
    "Write the shadowed scene as a Wavefront OBJ and its MTL (same stem, \".mtl\", next to "
    "the OBJ; spaces and other bytes OBJ names cannot hold escaped as %XX): every face split "
    "into the regions lit by the same set of lights, grouped by "
    "face id, one material per light set (\"shadow\", \"sun\", \"sun+lamp\"; shadow grey "
    "0.2, lit parts lighter); or, with --by-light, each face whole in shadow and over it "
    "one layer per light, its lit polygons (group \"<face>@<light>\", one material per "
    "light), which grows linearly with the lights where light sets do not; or, with "
    "--sun-hours, a sun path's sun-hours regions grouped by face and band of hours, one "
    "material per band. A scene is generated first; a shadowed database is read as it is."};

// The MTL goes next to the OBJ, named with the OBJ's stem and ".mtl"; the stem escaped as
// obj_name() escapes names ("my scene.obj" gets "my%20scene.mtl"), so that the OBJ's
// mtllib statement, which separates file names by spaces, names it as it is. Every face
// split by the set of lights reaching it, one material per set
// (shadowgen/output/obj_export.h).
struct ExportArgs {
  std::string input;                 // a scene (generated first) or a shadowed database
  std::vector<std::string> outputs;  // -o: the OBJ file, told by its extension
  std::string obj;                   // --obj: the OBJ file
  ReadingArgs reading;
  SunHoursArgs sun_hours;  // --sun-hours: that path's regions by band instead
  bool by_light = false;   // --by-light: a layer per light instead of light sets
};

void run_export(const ExportArgs& args) {
  for (const std::string& output : args.outputs) {
    if (output == "-") throw UsageError("-o -: an OBJ and its MTL are two files, not one stream");
  }
  std::vector<FormatOutput> formats{{"OBJ file", ".obj", "--obj", args.obj, ""}};
  assign_outputs(args.outputs, formats);
  const std::string& obj = formats[0].path;
  const std::string& named_by = formats[0].named_by;
  if (obj.empty()) throw UsageError("-o FILE.obj is required (--obj FILE names it too)");
  const std::filesystem::path obj_path = obj;
  const std::filesystem::path mtl_path =
      obj_path.parent_path() / (obj_name(obj_path.stem().string()) + ".mtl");
  if (mtl_path == obj_path || obj_path.filename().empty()) {
    throw InputError(obj, "",
                     "not a usable OBJ file name: the MTL file goes next to it, named with "
                     "the same stem and \".mtl\"");
  }

  if (obj == "-") throw UsageError("--obj -: an OBJ and its MTL are two files, not one stream");
  LoadOptions load = load_options(
      args.reading, Accept::kSceneOrDatabase,
      {{args.input}, {{named_by, obj_path.string()}, {named_by + "'s MTL", mtl_path.string()}}});
  // A sun-hours export writes a path's sums, not its instants' lit polygons; a scene
  // without that path is refused before its shadows are computed.
  load_to_draw(load, args.sun_hours, args.input);
  RunProgress progress(args.input, progress_stream(args.reading.quiet));
  progress.watch(load);
  const ShadowedScene shadowed = load_shadowed(args.input, load);
  std::optional<SunHoursMap> map;
  if (!args.sun_hours.path.empty()) map = sun_hours_map(shadowed, args.sun_hours, args.input);
  progress.stage(map             ? "splitting faces by bands of sun hours"
                 : args.by_light ? "laying out each light's lit polygons"
                                 : "splitting faces by light sets");
  ObjFiles files;
  try {
    files =
        map ? sun_hours_obj_export(shadowed, *map->path, map->bands, mtl_path.filename().string())
        : args.by_light ? obj_export_by_light(shadowed, mtl_path.filename().string())
                        : obj_export(shadowed, mtl_path.filename().string());
  } catch (const GenerationError& e) {
    throw GenerationError(args.input, e.face_id(), e.light_id(), e.problem());
  }
  // Both texts are complete before either file is touched, and written as one set: the
  // MTL first, the OBJ that names it last, so a failed run leaves both as they were.
  progress.stage("writing " + obj);
  write_files_atomically({{mtl_path, files.mtl}, {obj_path, files.obj}});
  progress.finish();
}

void add_export_options(CLI::App& command, ExportArgs& args) {
  add_input_option(command, args.input);
  add_outputs_option(command, args.outputs,
                     "FILE.obj: the OBJ file to write (replaced whole); the MTL goes next to it");
  command.add_option("--obj", args.obj, "OBJ file to write, as -o FILE.obj does");
  add_reading_options(command, args.reading, /*progress=*/true);
  // A sun-hours export writes one path whole: there is nothing for --lights to choose.
  CLI::Option* sun_hours = add_sun_hours_options(command, args.sun_hours, "write");
  sun_hours->excludes(command.get_option("--lights"));
  command
      .add_flag("--by-light", args.by_light,
                "each face whole in shadow, then one layer per light over it (its lit "
                "polygons), instead of the faces split by light sets")
      ->excludes(sun_hours);
}

}  // namespace

Command add_export_command(CLI::App& app) {
  return make_command<ExportArgs>(app, kExportText, add_export_options, run_export);
}

}  // namespace shadowgen::cli
