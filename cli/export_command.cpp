#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "commands.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/database.h"
#include "shadowgen/json/document.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/obj_export.h"
#include "shadowgen/scene/scene_reader.h"

namespace shadowgen::cli {
namespace {

// A scene is generated first (as `report` does); a shadowed database is read as it is.
ShadowedScene load_shadowed(const ExportArgs& args) {
  const Document document = read_document(args.input);
  if (document.format == kShadowedFormat) return parse_database(document.text, document.path);
  if (document.format != kSceneFormat) {
    throw InputError(args.input, "",
                     "\"format\" is \"" + document.format + "\", expected \"" +
                         std::string(kSceneFormat) + "\" or \"" + std::string(kShadowedFormat) +
                         "\"");
  }
  ReadOptions read_options;
  read_options.strict = args.strict;
  ReadResult read = parse_scene(document.text, document.path, read_options);
  if (!args.quiet) {
    for (const std::string& warning : read.warnings) {
      std::cerr << "shadowgen: warning: " << warning << '\n';
    }
  }
  GenerateOptions options;
  options.threads = args.threads;
  return generate_shadows(read.scene, options).shadowed;
}

}  // namespace

void run_export(const ExportArgs& args) {
  const std::filesystem::path obj_path = args.obj;
  std::filesystem::path mtl_path = obj_path;
  mtl_path.replace_extension(".mtl");
  if (mtl_path == obj_path || obj_path.filename().empty()) {
    throw InputError(args.obj, "",
                     "not a usable OBJ file name: the MTL file goes next to it, named with "
                     "the same stem and \".mtl\"");
  }

  const ShadowedScene shadowed = load_shadowed(args);
  ObjFiles files;
  try {
    files = obj_export(shadowed, mtl_path.filename().string());
  } catch (const std::runtime_error& e) {
    throw InputError(args.input, "", e.what());
  }

  // Both texts are complete before either file is touched. The MTL goes first (the OBJ
  // names it); should the OBJ then fail, the new MTL is removed again, so a failed run
  // leaves neither behind.
  write_file_atomically(mtl_path, files.mtl);
  try {
    write_file_atomically(obj_path, files.obj);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(mtl_path, ignored);
    throw;
  }
}

}  // namespace shadowgen::cli
