// `shadowgen export`: the shadowed scene as a Wavefront OBJ and its MTL, or as glTF 2.0.

#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli/command.h"
#include "cli/output_by_extension.h"
#include "cli/run_progress.h"
#include "cli/sun_hours_options.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/gltf_export.h"
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
    "material per band. A file ending \".glb\" (binary) or \".gltf\" (JSON, its buffer "
    "embedded) gets the same regions (light sets, or with --sun-hours bands) as glTF 2.0: "
    "one material per light set or band, +z up turned to glTF's +y up, face ids and areas "
    "in extras (docs/scene-format.md, \"glTF export\"); -o may name an OBJ and a glTF "
    "file at once. A scene is generated first; a shadowed database is read as it is."};

// The MTL goes next to the OBJ, named with the OBJ's stem and ".mtl"; the stem escaped as
// obj_name() escapes names ("my scene.obj" gets "my%20scene.mtl"), so that the OBJ's
// mtllib statement, which separates file names by spaces, names it as it is. Every face
// split by the set of lights reaching it, one material per set
// (shadowgen/output/obj_export.h).
struct ExportArgs {
  std::string input;                 // a scene (generated first) or a shadowed database
  std::vector<std::string> outputs;  // -o: the OBJ and glTF files, told by their extension
  std::string obj;                   // --obj: the OBJ file
  std::string gltf;                  // --gltf: the glTF file, binary or JSON by extension
  ReadingArgs reading;
  SunHoursArgs sun_hours;  // --sun-hours: that path's regions by band instead
  bool by_light = false;   // --by-light: a layer per light instead of light sets
};

// The files to write: the OBJ, the binary glTF and the JSON glTF, each where named.
std::vector<FormatOutput> export_outputs(const ExportArgs& args) {
  for (const std::string& output : args.outputs) {
    if (output == "-") throw UsageError("-o -: an OBJ and its MTL are two files, not one stream");
  }
  const std::optional<GltfForm> form = gltf_form_of(args.gltf);
  if (!args.gltf.empty() && !form) {
    throw UsageError("--gltf " + args.gltf +
                     ": a glTF file's name ends in \".glb\" (binary) or \".gltf\" (JSON)");
  }
  const auto gltf_as = [&](GltfForm f) { return form == f ? args.gltf : std::string(); };
  std::vector<FormatOutput> formats{
      {"OBJ file", ".obj", "--obj", args.obj, ""},
      {"binary glTF file", ".glb", "--gltf", gltf_as(GltfForm::kBinary), "", true},
      {"glTF file", ".gltf", "--gltf", gltf_as(GltfForm::kText), ""}};
  assign_outputs(args.outputs, formats);
  if (formats[0].path.empty() && formats[1].path.empty() && formats[2].path.empty()) {
    throw UsageError(
        "-o FILE.obj, FILE.glb or FILE.gltf is required (--obj FILE and --gltf FILE name them "
        "too)");
  }
  if (args.by_light && !(formats[1].path.empty() && formats[2].path.empty())) {
    throw UsageError(
        "--by-light writes OBJ layers; a glTF file takes the light sets or "
        "--sun-hours");
  }
  return formats;
}

void run_export(const ExportArgs& args) {
  const std::vector<FormatOutput> formats = export_outputs(args);
  const std::string& obj = formats[0].path;
  std::vector<OutputFile> writes;
  std::filesystem::path mtl_path;
  if (!obj.empty()) {
    if (obj == "-") throw UsageError("--obj -: an OBJ and its MTL are two files, not one stream");
    const std::filesystem::path obj_path = obj;
    // A gzip OBJ (x.obj.gz) names a plain x.mtl: `gzip -d x.obj.gz` gives the pair.
    const std::filesystem::path plain = gzip_named(obj_path) ? obj_path.stem() : obj_path;
    mtl_path = obj_path.parent_path() / (obj_name(plain.stem().string()) + ".mtl");
    if (mtl_path == obj_path || obj_path.filename().empty()) {
      throw InputError(obj, "",
                       "not a usable OBJ file name: the MTL file goes next to it, named with "
                       "the same stem and \".mtl\"");
    }
    writes.push_back({formats[0].named_by, obj});
    writes.push_back({formats[0].named_by + "'s MTL", mtl_path.string()});
  }
  for (std::size_t f = 1; f < formats.size(); ++f) {
    if (!formats[f].path.empty()) writes.push_back({formats[f].named_by, formats[f].path});
  }

  LoadOptions load = load_options(args.reading, Accept::kSceneOrDatabase, {{args.input}, writes});
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
  // Every file's text is complete before any file is touched, and all are written as one
  // set: the MTL before the OBJ that names it, so a failed run leaves them as they were.
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  try {
    if (!obj.empty()) {
      const std::string mtl_name = mtl_path.filename().string();
      ObjFiles texts = map ? sun_hours_obj_export(shadowed, *map->path, map->bands, mtl_name)
                       : args.by_light ? obj_export_by_light(shadowed, mtl_name)
                                       : obj_export(shadowed, mtl_name);
      files.emplace_back(mtl_path, std::move(texts.mtl));
      files.emplace_back(obj, std::move(texts.obj));
    }
    for (const GltfForm form : {GltfForm::kBinary, GltfForm::kText}) {
      const std::string& path = formats[form == GltfForm::kBinary ? 1 : 2].path;
      if (path.empty()) continue;
      files.emplace_back(path, map ? sun_hours_gltf_export(shadowed, *map->path, map->bands, form)
                                   : gltf_export(shadowed, form));
    }
  } catch (const GenerationError& e) {
    throw GenerationError(args.input, e.face_id(), e.light_id(), e.problem());
  }
  std::vector<OutputText> texts;
  for (const auto& [path, text] : files) texts.push_back({path, text});
  progress.stage("writing " + files.back().first.string());
  write_files_atomically(texts);
  progress.finish();
}

void add_export_options(CLI::App& command, ExportArgs& args) {
  add_input_option(command, args.input);
  add_outputs_option(command, args.outputs,
                     "FILE.obj: the OBJ file to write (replaced whole), the MTL next to it; "
                     "FILE.glb or FILE.gltf: a glTF file (binary, or JSON)");
  command.add_option("--obj", args.obj, "OBJ file to write, as -o FILE.obj does");
  command.add_option("--gltf", args.gltf, "glTF file to write, as -o FILE.glb or FILE.gltf does");
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
