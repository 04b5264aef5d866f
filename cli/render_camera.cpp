#include "cli/render_camera.h"

#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/number_options.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/view_limits.h"

namespace shadowgen::cli {
namespace {

// A triple the parser has checked (triple(), point()), or `fallback` when not given.
glm::dvec3 triple_or(const std::string& text, const glm::dvec3& fallback) {
  return text.empty() ? fallback : parse_triple(text).value_or(fallback);
}

}  // namespace

void add_camera_options(CLI::App& command, CameraArgs& args) {
  CLI::Option_group* camera =
      command.add_option_group("camera", "where to look from: exactly one of these");
  camera->add_option("--view", args.view, "id of one of the database's views");
  CLI::Option* eye =
      camera->add_option("--eye", args.eye, "eye position X,Y,Z (with --target)")->check(point());
  camera->require_option(1);
  CLI::Option* target =
      command.add_option("--target", args.target, "point looked at X,Y,Z (with --eye)")
          ->check(point());
  CLI::Option* up = command
                        .add_option("--up", args.up,
                                    "up direction X,Y,Z, not zero and not along the line of "
                                    "sight (default 0,0,1; a view straight down then has +y up)")
                        ->check(triple());
  CLI::Option* fov =
      command.add_option("--fov", args.fov_deg,
                         "full vertical field of view in degrees, at least 1e-06 (narrower, a "
                         "pixel would span little more than the rounding of the distance to "
                         "the target) and below 180 (default 45)");
  eye->needs(target);
  target->needs(eye);
  up->needs(eye);
  fov->needs(eye);
  fov->check(number_in(fov_range()));
  CLI::Option* ortho = command.add_flag("--ortho", args.ortho,
                                        "orthographic (parallel) projection along target - eye");
  command
      .add_option("--scale", args.scale,
                  "orthographic: pixels per scene unit, from 1e-100 (a pixel then spans half "
                  "the supported coordinate range) to 1e100 (the smallest face extent) "
                  "(default: fit the scene)")
      ->check(number_in(scale_range()))
      ->needs(ortho);
}

void check_up(const CameraArgs& args) {
  if (args.up.empty() || !args.view.empty()) return;
  const glm::dvec3 sight =
      triple_or(args.target, glm::dvec3(0.0)) - triple_or(args.eye, glm::dvec3(0.0));
  if (sight == glm::dvec3(0.0)) return;
  if (const std::optional<std::string> problem =
          up_problem(sight, triple_or(args.up, glm::dvec3(0.0)), "from --eye to --target")) {
    throw UsageError("--up " + args.up + ": " + *problem);
  }
}

Camera camera_for(const CameraArgs& args, const ShadowedScene& shadowed,
                  const std::string& database) {
  Camera camera;
  if (!args.view.empty()) {
    const ViewSpec* spec = nullptr;
    for (const ViewSpec& v : shadowed.scene().views) {
      if (v.id == args.view) spec = &v;
    }
    if (spec == nullptr) {
      throw InputError(database, "", "no view with id '" + args.view + "'");
    }
    camera = camera_from_view(*spec, args.ortho);
  } else {
    camera.eye = triple_or(args.eye, glm::dvec3(0.0));
    camera.target = triple_or(args.target, glm::dvec3(0.0));
    camera.up = triple_or(args.up, glm::dvec3(0.0, 0.0, 1.0));
    camera.fov_deg = args.fov_deg;
    camera.orthographic = args.ortho;
  }
  camera.pixels_per_unit = args.scale;
  return camera;
}

}  // namespace shadowgen::cli
