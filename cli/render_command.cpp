// `shadowgen render`: a picture of a shadowed database, as SVG and/or PNG.

#include <algorithm>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/output_by_extension.h"
#include "cli/radiation_options.h"
#include "cli/render_camera.h"
#include "cli/run_progress.h"
#include "cli/sun_hours_options.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/view_limits.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/radiation_report.h"
#include "shadowgen/sky/sky_exposure.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/picture_raster.h"
#include "shadowgen/view/pixel_shadows.h"
#include "shadowgen/view/png_writer.h"
#include "shadowgen/view/radiation_map.h"
#include "shadowgen/view/raster_render.h"
#include "shadowgen/view/render.h"
#include "shadowgen/view/sun_hours_map.h"
#include "shadowgen/view/svg_writer.h"
#include "shadowgen/weather/epw_reader.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kRenderText{
    "render",
    "Draw the shadowed database from a viewpoint as SVG (-o FILE.svg): hidden surfaces removed "
    "from the "
    "eye, each visible face split by the lights reaching it, flat shaded; or, with "
    "--by-light, each visible face in shadow with one layer per light over it, what that "
    "light reaches in its share of the shading, which a browser adds up (it grows linearly "
    "with the lights where light sets do not); or, with --sun-hours, split by a sun path's "
    "sun hours, coloured by band, with a legend (as SVG, PNG or both); or, with --radiation, each "
    "face whole coloured by its total irradiation over a sun path in kWh/m² (as report --format "
    "radiation gives it, from --weather), banded, with a legend. Pieces of one colour are "
    "one path where they touch; faces or model objects are outlined; a north arrow (where the "
    "database has a site) and, in orthographic views, a scale bar mark the map. Reads "
    "only the database; no shadows are recomputed (with --radiation, the sky's patches' lit areas "
    "are computed, as the report computes them, and the weather file read). A PNG picture (-o "
    "FILE.png) is the lit picture "
    "drawn pixel by pixel, instead or as well, its shadows found by --shadows: the database's "
    "(exact), shadow maps "
    "or shadow volumes."};

// A picture of a shadowed database (never a scene: no shadow pass runs) from the
// database's view `view` or from eye/target/up/fov.
struct RenderArgs {
  std::string database;
  CameraArgs camera;                 // --view or --eye/--target/--up/--fov, --ortho, --scale
  std::vector<std::string> outputs;  // -o: an SVG or a PNG file each, by extension
  std::string svg;                   // --svg, or the -o file ending in .svg
  std::string png;                   // --png, or the -o file ending in .png
  std::string svg_option = "--svg";  // the option that named each, for messages
  std::string png_option = "--png";
  std::string shadows = "exact";  // --png: how the pixels' shadows are found
  int resolution = kDefaultResolution;
  const CLI::Option* resolution_option = nullptr;
  int width = 800;
  int height = 600;
  std::vector<std::string> lights;   // --lights: only these are drawn
  SunHoursArgs sun_hours;            // --sun-hours: a sun-hours map of that path instead
  std::string radiation;             // --radiation: a radiation map of that path instead
  RadiationArgs radiation_args;      // its --weather, --albedo and --sky
  bool by_light = false;             // --by-light: the SVG in layers by light
  bool pieces = false;               // --pieces: one SVG path per piece, not per colour
  bool full_precision = false;       // --full-precision: exact coordinates, not 1/1000 px
  bool quiet = false;                // --quiet: no reading warnings, no progress line
  const CLI::App* parser = nullptr;  // the subcommand, whose options say what was given
};

// The --png picture's view method (shadowgen/view/pixel_shadows.h). The names --shadows
// accepts are checked by the parser.
PixelShadowOptions pixel_shadows_of(const RenderArgs& args) {
  PixelShadowOptions options;
  options.method = pixel_shadows_named(args.shadows).value_or(PixelShadows::kExact);
  if (options.method != PixelShadows::kShadowMap && options.method != PixelShadows::kAngular &&
      args.resolution_option != nullptr && args.resolution_option->count() > 0) {
    throw UsageError("--resolution applies only to --shadows shadow-map and angular");
  }
  options.resolution = args.resolution;
  return options;
}

// The --png picture, its shadows found by the method --shadows names.
RgbImage raster_picture(const RenderArgs& args, const ShadowedScene& shadowed, const Camera& camera,
                        const RenderOptions& options) {
  RasterOptions raster;
  raster.picture = options;
  raster.shadows = pixel_shadows_of(args);
  return render_raster(shadowed, camera, raster);
}

// The --png file's bytes. A picture too large for the memory the process may use is
// said of the PNG file and its size (the input is not to blame).
std::string png_picture(const RenderArgs& args, const ShadowedScene& shadowed, const Camera& camera,
                        const RenderOptions& options) {
  try {
    return png_bytes(raster_picture(args, shadowed, camera, options));
  } catch (const std::bad_alloc&) {
    throw InputError(args.png, "",
                     "out of memory: a picture of " + std::to_string(args.width) + " × " +
                         std::to_string(args.height) +
                         " pixels needs more memory than the process may use");
  }
}

// `given` with its -o files taken as the SVG or PNG file by their extension; the usage
// errors of options that need one of the two pictures.
RenderArgs with_outputs(const RenderArgs& given) {
  RenderArgs args = given;
  std::vector<FormatOutput> formats{{"SVG picture", ".svg", "--svg", args.svg, ""},
                                    {"PNG picture", ".png", "--png", args.png, "", true}};
  assign_outputs(args.outputs, formats);
  args.svg = formats[0].path;
  args.svg_option = formats[0].named_by;
  args.png = formats[1].path;
  args.png_option = formats[1].named_by;
  if (args.svg.empty() && args.png.empty()) {
    throw UsageError(
        "-o FILE.svg or -o FILE.png is required (or both; --svg and --png name them too)");
  }
  if (args.png.empty()) {
    for (const char* option : {"--shadows", "--resolution"}) {
      if (args.parser->get_option(option)->count() > 0) {
        throw UsageError(std::string(option) +
                         " applies only to the PNG picture (-o FILE.png or --png)");
      }
    }
  }
  if (args.by_light && args.svg.empty()) {
    throw UsageError("--by-light draws the SVG picture in layers: it needs -o FILE.svg (or --svg)");
  }
  if (args.pieces && args.svg.empty()) {
    throw UsageError(
        "--pieces draws the SVG picture one path per piece: it needs -o FILE.svg (or "
        "--svg)");
  }
  if (args.full_precision && args.svg.empty()) {
    throw UsageError(
        "--full-precision writes the SVG picture's coordinates exactly: it needs -o FILE.svg "
        "(or --svg)");
  }
  // A map's pixels are its pieces' (picture_raster.h): no view method.
  if (!args.sun_hours.path.empty() || !args.radiation.empty()) {
    for (const char* option : {"--shadows", "--resolution"}) {
      if (args.parser->get_option(option)->count() > 0) {
        throw UsageError(std::string(option) + " applies only to the lit picture: a " +
                         (args.radiation.empty() ? "sun-hours" : "radiation") +
                         " map's pixels are its pieces'");
      }
    }
  }
  return args;
}

// Each face's total irradiation over the --radiation path in kWh/m²: the radiation
// report's total_wh_per_area (radiation_rows, as `report --format radiation` computes it)
// / 1000. The path is checked before the sky's patches are generated.
std::vector<double> radiation_per_face(const RenderArgs& args, const ShadowedScene& shadowed,
                                       RunProgress& progress) {
  const SunPathHours& path = sun_path_named(shadowed, args.radiation, args.database);
  const auto path_index = static_cast<std::size_t>(&path - shadowed.sun_paths.data());
  const Weather weather = weather::read_epw(args.radiation_args.weather);
  progress.stage("generating the sky's patches");
  sky::SkyOptions sky_options;
  sky_options.subdivisions = args.radiation_args.sky_subdivisions;
  const sky::SkyExposure exposure = sky::sky_exposure(shadowed.scene(), sky_options);
  RadiationOptions options;
  options.albedo = args.radiation_args.albedo;
  std::vector<std::string> warnings;  // after the progress line
  options.on_warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
  std::vector<double> values(shadowed.scene().faces.size(), 0.0);
  for (const RadiationRow& row : radiation_rows(shadowed, exposure, weather, options)) {
    if (row.path == path_index && row.area > 0.0)
      values[row.face] = row.total_wh() / row.area / 1000.0;
  }
  if (!args.quiet) {
    for (const std::string& warning : warnings) {
      std::cerr << "shadowgen: warning: " << args.database << ": " << warning << '\n';
    }
  }
  return values;
}

void run_render(const RenderArgs& given) {
  const RenderArgs args = with_outputs(given);
  if (!args.png.empty()) pixel_shadows_of(args);  // its usage errors before any work
  check_up(args.camera);
  LoadOptions load;
  load.accept = Accept::kDatabase;
  load.lights = args.lights;
  // A sun-hours map draws a path's sums, not its instants' lit polygons.
  load.generate.keep_instant_polygons = args.sun_hours.path.empty() && args.radiation.empty();
  load.draws = true;
  if (!args.quiet) {
    load.on_warning = [](const std::string& warning) {
      std::cerr << "shadowgen: warning: " << warning << '\n';
    };
  }
  RunFiles run_files{{args.database}, {}};
  if (!args.radiation_args.weather.empty()) run_files.reads.push_back(args.radiation_args.weather);
  if (!args.svg.empty()) run_files.writes.push_back({args.svg_option, args.svg});
  if (!args.png.empty()) run_files.writes.push_back({args.png_option, args.png});
  guard_outputs(load, run_files);
  RunProgress progress(args.database, progress_stream(args.quiet));
  progress.watch(load);
  const ShadowedScene shadowed = load_shadowed(args.database, load);
  std::optional<SunHoursMap> map;
  if (!args.sun_hours.path.empty()) map = sun_hours_map(shadowed, args.sun_hours, args.database);
  std::vector<double> radiation;
  if (!args.radiation.empty()) radiation = radiation_per_face(args, shadowed, progress);
  const Camera camera = camera_for(args.camera, shadowed, args.database);
  RenderOptions options;
  options.width = args.width;
  options.height = args.height;
  std::string svg, png;
  try {
    if (!args.radiation.empty()) {
      progress.stage("drawing the radiation map");
      const double most = radiation.empty() ? 0.0 : *std::ranges::max_element(radiation);
      const Picture picture = render_radiation(
          shadowed, radiation, radiation_bands(args.radiation, most), camera, options);
      if (!args.svg.empty())
        svg = svg_document(picture, {.pieces = args.pieces, .full_precision = args.full_precision});
      if (!args.png.empty()) png = png_bytes(rasterize_picture(picture));
    } else if (map) {
      // One map, as SVG and as its pixels (picture_raster.h).
      progress.stage("drawing the sun-hours map");
      const Picture picture = render_sun_hours(shadowed, *map->path, map->bands, camera, options);
      if (!args.svg.empty())
        svg = svg_document(picture, {.pieces = args.pieces, .full_precision = args.full_precision});
      if (!args.png.empty()) png = png_bytes(rasterize_picture(picture));
    } else {
      if (!args.svg.empty()) {
        progress.stage("drawing " + args.svg);
        const Picture picture = args.by_light ? render_by_light(shadowed, camera, options)
                                              : render(shadowed, camera, options);
        svg = svg_document(picture, {.pieces = args.pieces, .full_precision = args.full_precision});
      }
      if (!args.png.empty()) {
        progress.stage("drawing " + args.png);
        png = png_picture(args, shadowed, camera, options);
      }
    }
  } catch (const std::invalid_argument& e) {
    // A camera the database's view or the arguments describe badly (eye == target): the
    // camera does not know which of them it came from.
    throw InputError(args.camera.view.empty() ? std::string("--eye/--target") : args.database, "",
                     e.what());
  }
  // Both pictures are made before either is written, and then written as one.
  std::vector<OutputText> files;
  if (!args.svg.empty()) files.push_back({args.svg, svg});
  if (!args.png.empty()) files.push_back({args.png, png});
  progress.stage("writing");
  write_files_atomically(files);
  progress.finish();
}

void add_render_options(CLI::App& command, RenderArgs& args) {
  command.add_option("database", args.database, "shadowed database (shadowgen-shadowed/2 or /1)")
      ->required();
  add_camera_options(command, args.camera);
  args.parser = &command;
  add_outputs_option(command, args.outputs,
                     "picture to write, by its extension: FILE.svg (the SVG picture) or FILE.png "
                     "(the lit picture pixel by pixel, each pixel sampled at its centre); once "
                     "for each, or twice for both");
  command.add_option("--png", args.png, "PNG file to write, as -o FILE.png does");
  command.add_option("--svg", args.svg, "SVG file to write, as -o FILE.svg does");
  // The view methods --png takes (shadowgen/view/pixel_shadows.h).
  command
      .add_option("--shadows", args.shadows,
                  "with a PNG picture: how each pixel's shadows are found: exact (default; the "
                  "database's lit polygons), shadow-map (depth maps from each light), volumes "
                  "(Bergeron's shadow volumes counted along each eye ray), stencil "
                  "(Heidmann's shadow volumes in the stencil buffer of OpenGL, run on the CPU "
                  "by Mesa; one volume per polygon), stencil-silhouettes (the same with the "
                  "paper's volumes from silhouette edges only: closed models, edges matched by "
                  "identical coordinates; an open model's shadows go missing) or angular "
                  "(Thakur, Cheng and Miura's ridge-edge loops and angular span table; closed "
                  "objects)")
      ->check(CLI::IsMember(
          {"exact", "shadow-map", "volumes", "stencil", "stencil-silhouettes", "angular"}));
  args.resolution_option =
      command
          .add_option(
              "--resolution", args.resolution,
              "with a PNG picture and --shadows shadow-map: texels along each side of a depth map; "
              "with --shadows angular: rows of the angular span table (default " +
                  std::to_string(kDefaultResolution) + ")")
          ->check(whole_number_in(1, kMaxResolution));
  // As large as libpng writes, for --svg too: one range for both pictures.
  command.add_option("--width", args.width, "picture width in pixels (default 800)")
      ->check(whole_number_in(1, kLargestPictureSide));
  command.add_option("--height", args.height, "picture height in pixels (default 600)")
      ->check(whole_number_in(1, kLargestPictureSide));
  add_lights_option(command, args.lights, "the database's other lights are not drawn");
  command.add_flag("-q,--quiet", args.quiet, "do not print reading warnings or the progress line");
  // A sun-hours map draws one path whole: there is nothing for --lights to choose.
  CLI::Option* sun_hours = add_sun_hours_options(command, args.sun_hours, "draw");
  sun_hours->excludes(command.get_option("--lights"));
  CLI::Option* radiation =
      command
          .add_option("--radiation", args.radiation,
                      "draw a radiation map of the sun path PATH_ID instead: each visible face "
                      "whole in the colour of its total irradiation over the path in kWh/m² "
                      "(direct + diffuse + ground, as report --format radiation computes it, from "
                      "--weather), banded, with a legend")
          ->option_text("PATH_ID")
          ->excludes(sun_hours)
          ->excludes(command.get_option("--lights"));
  const RadiationOptionSet radiation_options = add_radiation_options(
      command, args.radiation_args,
      {.weather = "with --radiation (required: a database keeps no weather file)",
       .albedo = "with --radiation",
       .sky = "with --radiation"});
  radiation->needs(radiation_options.weather);
  for (CLI::Option* option :
       {radiation_options.weather, radiation_options.albedo, radiation_options.sky}) {
    option->needs(radiation);
  }
  command
      .add_flag("--by-light", args.by_light,
                "with an SVG picture: each visible face in shadow, then one layer per light over "
                "it (what the light reaches, in its share of the shading), instead of the faces "
                "split by light sets")
      ->excludes(sun_hours)
      ->excludes(radiation);
  command.add_flag("--pieces", args.pieces,
                   "with an SVG picture: one path per piece, with its face id (data-face) and its "
                   "light set or hours, instead of one path per colour (the faces then named by "
                   "the outlines)");
  command.add_flag("--full-precision", args.full_precision,
                   "with an SVG picture: every coordinate of the paths per colour and the "
                   "outlines as the double it is (the shortest decimal that reads back to it), "
                   "instead of to 1/1000 of a pixel; one path per piece always has them so");
}

}  // namespace

Command add_render_command(CLI::App& app) {
  return make_command<RenderArgs>(app, kRenderText, add_render_options, run_render);
}

}  // namespace shadowgen::cli
