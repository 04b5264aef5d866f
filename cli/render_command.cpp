#include <glm/vec3.hpp>
#include <string>

#include "commands.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/output/database.h"
#include "shadowgen/json/document.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/view/render.h"
#include "shadowgen/view/svg_writer.h"

namespace shadowgen::cli {
namespace {

glm::dvec3 vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

}  // namespace

void run_render(const RenderArgs& args) {
  const Document document = read_document(args.database);
  if (document.format == kSceneFormat) {
    throw InputError(args.database, "",
                     "is a scene; render takes a shadowed database (run shadowgen generate)");
  }
  if (document.format != kShadowedFormat) {
    throw InputError(args.database, "",
                     "\"format\" is \"" + document.format + "\", expected \"" +
                         std::string(kShadowedFormat) + "\"");
  }
  const ShadowedScene shadowed = parse_database(document.text, document.path);

  Camera camera;
  if (!args.view.empty()) {
    const ViewSpec* spec = nullptr;
    for (const ViewSpec& v : shadowed.scene.views) {
      if (v.id == args.view) spec = &v;
    }
    if (spec == nullptr) {
      throw InputError(args.database, "", "no view with id '" + args.view + "'");
    }
    camera = camera_from_view(*spec, args.ortho);
  } else {
    camera.eye = vec(args.eye.value_or(std::array<double, 3>{}));
    camera.target = vec(args.target);
    camera.up = vec(args.up);
    camera.fov_deg = args.fov_deg;
    camera.orthographic = args.ortho;
  }
  camera.pixels_per_unit = args.scale;

  RenderOptions options;
  options.width = args.width;
  options.height = args.height;
  Picture picture;
  try {
    picture = render(shadowed, camera, options);
  } catch (const std::invalid_argument& e) {
    // A camera the database's view or the arguments describe badly (eye == target).
    throw InputError(args.view.empty() ? std::string("--eye/--target") : args.database, "",
                     e.what());
  }
  write_svg(picture, args.svg);
}

}  // namespace shadowgen::cli
