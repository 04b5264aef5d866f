#pragma once

// The camera of `shadowgen render`: one of the database's views (--view) or an eye, a
// target, an up direction and a field of view given on the command line, in perspective
// or orthographic (--ortho, --scale); the options named, described and checked in one
// place, and the camera they describe.

#include <CLI/CLI.hpp>
#include <string>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/view/camera.h"

namespace shadowgen::cli {

struct CameraArgs {
  std::string view;             // a view id of the database, or empty
  std::string eye, target, up;  // X,Y,Z (point(), point(), triple()), or empty
  double fov_deg = 45.0;
  bool ortho = false;
  double scale = 0.0;  // orthographic pixels per scene unit; 0 fits the scene
};

// Adds the camera's options to `command`: exactly one of --view and --eye, the rest with
// --eye (--target, --up, --fov) or with --ortho (--scale), each range checked.
void add_camera_options(CLI::App& command, CameraArgs& args);

// A UsageError naming --up where it is given and fixes no roll: zero, or along the line
// of sight from --eye to --target (shadowgen/model/view_limits.h, as the readers check a
// view's 'up'). An eye equal to the target is the camera's error.
void check_up(const CameraArgs& args);

// The camera `args` describe: the view of `shadowed` it names (an InputError naming
// `database` where it has none of that id), or the eye, target, up and field of view.
Camera camera_for(const CameraArgs& args, const ShadowedScene& shadowed,
                  const std::string& database);

}  // namespace shadowgen::cli
