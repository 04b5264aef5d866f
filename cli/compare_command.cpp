// `shadowgen compare`: the methods run on the user's own scene, each one's time and error
// against the exact method, the Pareto-optimal ones marked.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/run_progress.h"
#include "cli/sky_option.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/method_table.h"
#include "shadowgen/output/sky_comparison_table.h"
#include "shadowgen/pipeline/light_choice.h"
#include "shadowgen/pipeline/method_comparison.h"
#include "shadowgen/pipeline/sky_method_comparison.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/sky/sky_patches.h"
#include "shadowgen/view/method_plot.h"
#include "shadowgen/view/pixel_shadows.h"
#include "shadowgen/view/view_comparison.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kCompareText{
    "compare",
    "Run the methods on a scene (or a database's scene), one after another, and print each one's "
    "time and the error "
    "of its lit fractions against the exact method's (mean and largest over every face and "
    "light), marking those no other method beats on both time and error (Pareto-optimal). "
    "--plot draws error against time. --view ID also draws the scene from its view ID "
    "pixel by pixel with the view methods (as render --png --shadows does) and prints each "
    "one's time and the share of (pixel, light) pairs, off region boundaries, whose lit state "
    "differs from the exact method's. --sky compares every face's sky view factor instead."};

// The default trials: three sample counts of each sampled method.
constexpr const char* kDefaultMethods[] = {"rays:16",
                                           "rays:64",
                                           "rays:256",
                                           "shadow-map:512:samples=16",
                                           "shadow-map:1024:samples=64",
                                           "shadow-map:2048:samples=256"};

// The default view methods of --view.
constexpr const char* kDefaultViewMethods[] = {
    "shadow-map:1024", "shadow-map:2048", "shadow-map:4096", "volumes", "stencil", "angular"};

struct CompareArgs {
  std::string input;  // a scene
  std::vector<std::string> methods{std::begin(kDefaultMethods), std::end(kDefaultMethods)};
  std::string format = "table";  // table or csv
  bool csv_safe = false;
  std::string output;  // empty: standard output
  std::string plot;    // an SVG file, or none
  std::string view;    // a view id of the scene, or none
  int width = 400, height = 300;
  std::vector<std::string> view_methods{std::begin(kDefaultViewMethods),
                                        std::end(kDefaultViewMethods)};
  std::size_t view_instants = 4;  // instants drawn of each sun path
  int sky_subdivisions = 1;       // --sky: compare sky view factors over Reinhart MF:N
  bool sky_given = false;
  ReadingArgs reading;
};

// The largest side of a picture --view draws, and the most instants of a path it draws.
constexpr int kLargestComparedPictureSide = 1 << 14;
constexpr int kMostViewInstants = 1 << 20;

// A count from 1 to `max` in `text`, or nullopt.
std::optional<int> count(const std::string& text, int max) {
  const std::optional<std::int64_t> value = whole_number_within(text, 1, max);
  if (!value) return std::nullopt;
  return static_cast<int>(*value);
}

// A method of --methods: exact, rays[:SAMPLES] or shadow-map[:RESOLUTION][:samples=N]
// (samples= may be written for rays too): the number after shadow-map is the depth maps'
// resolution in texels, as in --view-methods and --resolution. Throws UsageError. The
// spelling before, shadow-map:SAMPLES:RESOLUTION, is refused saying the new one; where
// shadow-map is followed by a bare number alone, which once meant samples, `on_warning`
// is told that it now means texels.
Method parse_method(const std::string& text,
                    const std::function<void(const std::string&)>& on_warning) {
  std::vector<std::string> fields{""};
  for (const char c : text) {
    if (c == ':') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  const std::optional<MethodKind> kind = method_kind(fields[0]);
  const auto refuse = [&text] {
    throw UsageError("--methods " + text +
                     ": expected exact, rays[:SAMPLES] or shadow-map[:RESOLUTION][:samples=N], "
                     "samples from 1 to " +
                     std::to_string(kMaxSamples) + ", resolution (texels a side) from 1 to " +
                     std::to_string(kMaxResolution));
  };
  if (!kind) refuse();
  Method method{*kind};
  if (method.exact()) {
    if (fields.size() > 1) refuse();
    return method;
  }
  const bool map = method.kind == MethodKind::kShadowMap;
  std::optional<int> samples;
  std::vector<std::string> bare;  // the fields without a name
  for (std::size_t k = 1; k < fields.size(); ++k) {
    if (fields[k].rfind("samples=", 0) != 0) {
      bare.push_back(fields[k]);
    } else if (samples || !(samples = count(fields[k].substr(8), kMaxSamples))) {
      refuse();
    }
  }
  if (map && bare.size() == 2 && !samples) {
    throw UsageError("--methods " + text +
                     ": shadow-map:SAMPLES:RESOLUTION is written shadow-map:" + bare[1] +
                     ":samples=" + bare[0] +
                     " (the number after shadow-map is the depth maps' resolution in texels, as "
                     "in --view-methods)");
  }
  std::optional<int> number;
  if (bare.size() > 1 || (!map && !bare.empty() && samples)) refuse();
  if (!bare.empty() && !(number = count(bare[0], map ? kMaxResolution : kMaxSamples))) refuse();
  if (!map) {
    method.samples = samples.value_or(number.value_or(kDefaultSamples));
    return method;
  }
  method.samples = samples.value_or(kDefaultSamples);
  method.resolution = number.value_or(kDefaultResolution);
  if (number && !samples && on_warning) {
    on_warning("--methods " + text + ": " + bare[0] +
               " is the depth maps' resolution in texels, as in --view-methods (it was once the "
               "points per face, now written shadow-map:RESOLUTION:samples=N)");
  }
  return method;
}

// A view method of --view-methods: exact, volumes, stencil, stencil-silhouettes,
// shadow-map[:RESOLUTION] or angular[:ROWS].
// Throws UsageError.
PixelShadowOptions parse_view_method(const std::string& text) {
  const std::size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  PixelShadowOptions options;
  // The methods --view-methods takes, by name.
  constexpr PixelShadows kTaken[] = {
      PixelShadows::kExact,   PixelShadows::kShadowMap,          PixelShadows::kVolumes,
      PixelShadows::kStencil, PixelShadows::kStencilSilhouettes, PixelShadows::kAngular};
  bool known = false;
  for (const PixelShadows method : kTaken) {
    if (pixel_shadows_name(method) == name) {
      options.method = method;
      known = true;
    }
  }
  std::optional<int> resolution = kDefaultResolution;
  if (colon != std::string::npos) resolution = count(text.substr(colon + 1), kMaxResolution);
  if (!known || !resolution ||
      (colon != std::string::npos && options.method != PixelShadows::kShadowMap &&
       options.method != PixelShadows::kAngular)) {
    throw UsageError("--view-methods " + text +
                     ": expected exact, volumes, stencil, stencil-silhouettes, "
                     "shadow-map[:RESOLUTION] or angular[:ROWS], resolution from 1 to " +
                     std::to_string(kMaxResolution));
  }
  options.resolution = *resolution;
  return options;
}

// The scene's view `id`. Throws InputError naming `file` and the views there are.
const ViewSpec& view_named(const Scene& scene, const std::string& id, const std::string& file) {
  std::string known;
  for (const ViewSpec& view : scene.views) {
    if (view.id == id) return view;
    known += (known.empty() ? "'" : ", '") + one_line(view.id) + "'";
  }
  throw InputError(file, "",
                   "has no view '" + one_line(id) + "' (" +
                       (known.empty() ? std::string("it has no views") : "its views: " + known) +
                       ")");
}

void write_comparison(const CompareArgs& args, const std::string& text) {
  if (args.output.empty()) {
    std::cout << text << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write the comparison to standard output");
  } else {
    write_file_atomically(args.output, text);
  }
}

void run_compare(const CompareArgs& args) {
  std::vector<Method> methods;
  const std::function<void(const std::string&)> warn =
      args.reading.quiet ? std::function<void(const std::string&)>()
                         : [](const std::string& warning) {
                             std::cerr << "shadowgen: warning: " << warning << '\n';
                           };
  for (const std::string& text : args.methods) methods.push_back(parse_method(text, warn));
  std::vector<PixelShadowOptions> view_methods;
  if (!args.view.empty()) {
    for (const std::string& text : args.view_methods) {
      view_methods.push_back(parse_view_method(text));
    }
  }
  RunFiles files{{args.input}, {}};
  if (!args.output.empty()) files.writes.push_back({"-o", args.output});
  if (!args.plot.empty()) files.writes.push_back({"--plot", args.plot});
  LoadOptions load = load_options(args.reading, Accept::kSceneOrDatabase, files);
  RunProgress progress(args.input, progress_stream(args.reading.quiet));
  progress.watch(load);  // its warnings; load_scene generates nothing
  const Scene scene = load_scene(args.input, load);
  // A view the scene does not have is refused before any work.
  const ViewSpec* view = args.view.empty() ? nullptr : &view_named(scene, args.view, args.input);
  GenerateOptions options;
  options.threads = args.reading.threads;
  // The exact trial's lights, then each sampled trial by name.
  options.on_light_done = progress.lights(
      args.sky_given ? sky::reinhart_patches(args.sky_subdivisions).size() : scene.lights.size());
  std::size_t trials = 1;
  for (const Method& method : methods) trials += method.exact() ? 0 : 1;
  std::size_t trial = 0;
  const auto on_trial = [&](const Method& method) {
    if (++trial == 1) return;  // the exact one: its lights are counted
    progress.stage("trial " + std::to_string(trial) + "/" + std::to_string(trials) + ", " +
                   method_label(method));
  };
  if (args.sky_given) {
    sky::SkyComparison sky_comparison;
    try {
      sky_comparison =
          compare_sky_methods(scene, args.sky_subdivisions, methods, options, on_trial);
    } catch (const GenerationError& e) {
      throw GenerationError(args.input, e.face_id(), e.light_id(), e.problem());
    }
    progress.finish();
    write_comparison(
        args, args.format == "csv"
                  ? sky_comparison_csv(sky_comparison, scene,
                                       args.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact)
                  : sky_comparison_table(sky_comparison, scene));
    return;
  }
  MethodComparison comparison;
  ShadowedScene exact;
  try {
    comparison = compare_methods(scene, methods, options, view ? &exact : nullptr, on_trial);
  } catch (const GenerationError& e) {
    throw GenerationError(args.input, e.face_id(), e.light_id(), e.problem());
  }
  std::optional<ViewComparison> view_comparison;
  if (view != nullptr) {
    // The comparison's exact run sums sun paths' instants into lit areas, which no view
    // method can be measured against: a few instants of each path are generated again with
    // their lit polygons, and drawn.
    const auto path_instants = static_cast<std::size_t>(
        std::count_if(scene.lights.begin(), scene.lights.end(), in_sun_path));
    ShadowedScene with_instants;
    std::vector<std::string> instants;
    progress.stage("view " + one_line(view->id) + ": the view methods");
    if (path_instants > 0) {
      Scene drawn = scene;
      instants = keep_spread_instants(drawn, args.view_instants);
      GenerateOptions instant_options = options;
      instant_options.on_light_done = nullptr;
      instant_options.keep_instant_polygons = true;
      instant_options.sun_hours_regions = false;
      try {
        with_instants = generate_shadows(drawn, instant_options).shadowed;
      } catch (const GenerationError& e) {
        throw GenerationError(args.input, e.face_id(), e.light_id(), e.problem());
      }
    }
    try {
      view_comparison = compare_view_methods(path_instants > 0 ? with_instants : exact, *view,
                                             args.width, args.height, view_methods);
    } catch (const std::invalid_argument& e) {
      // A view the scene describes badly (eye == target).
      throw InputError(args.input, "", "view '" + one_line(view->id) + "': " + e.what());
    }
    view_comparison->path_instants = path_instants;
    view_comparison->instants = std::move(instants);
  }
  progress.finish();
  const ViewComparison* shown = view_comparison ? &*view_comparison : nullptr;
  const std::string text =
      args.format == "csv"
          ? comparison_csv(comparison, scene,
                           args.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact, shown)
          : comparison_table(comparison, scene, shown);
  if (!args.plot.empty()) write_comparison_svg(comparison, args.plot, shown);
  write_comparison(args, text);
}

void add_compare_options(CLI::App& command, CompareArgs& args) {
  command
      .add_option("input", args.input,
                  "scene (shadowgen-scene/1), or a shadowed database whose scene is taken (its "
                  "faces and lights; its lit polygons are not used)")
      ->required();
  command
      .add_option("--methods", args.methods,
                  "the methods to run, comma-separated: exact, rays[:SAMPLES], "
                  "shadow-map[:RESOLUTION][:samples=N] (SAMPLES, N: points per face, default " +
                      std::to_string(kDefaultSamples) +
                      "; RESOLUTION: texels a side of each depth map, as in --view-methods, "
                      "default " +
                      std::to_string(kDefaultResolution) +
                      "); the exact method always runs first, as the reference (default: "
                      "rays:16,rays:64,rays:256,shadow-map:512:samples=16,"
                      "shadow-map:1024:samples=64,shadow-map:2048:samples=256)")
      ->delimiter(',');
  command.add_option("--format", args.format, "table (default, for reading) or csv")
      ->check(CLI::IsMember({"table", "csv"}));
  command.add_flag("--csv-safe", args.csv_safe,
                   "CSV: put ' before an id that begins with =, +, -, @, a tab or a carriage "
                   "return, which spreadsheets would run as a formula");
  CLI::Option* plot =
      command.add_option("--plot", args.plot,
                         "SVG file to draw: mean error against time, log-log, the Pareto-optimal "
                         "methods joined");
  CLI::Option* view =
      command.add_option("--view", args.view,
                         "id of one of the scene's views: also draw the scene from it pixel by "
                         "pixel with each of --view-methods, and print each one's time and "
                         "the share of (pixel, light) pairs off region boundaries whose lit "
                         "state differs from the exact method's");
  command.add_option("--width", args.width, "with --view: picture width in pixels (default 400)")
      ->check(whole_number_in(1, kLargestComparedPictureSide))
      ->needs(view);
  command
      .add_option("--height", args.height, "with --view: picture height in pixels (default 300)")
      ->check(whole_number_in(1, kLargestComparedPictureSide))
      ->needs(view);
  command
      .add_option("--view-methods", args.view_methods,
                  "with --view: the view methods to measure, comma-separated: exact, "
                  "shadow-map[:RESOLUTION] (texels a side of each depth map, default " +
                      std::to_string(kDefaultResolution) +
                      "), volumes, stencil, stencil-silhouettes (Heidmann's volumes from "
                      "silhouette edges only: closed models), angular[:ROWS] (rows of the "
                      "angular span table) (default: shadow-map:1024,shadow-map:2048,"
                      "shadow-map:4096,volumes,stencil,angular)")
      ->delimiter(',')
      ->needs(view);
  command
      .add_option("--view-instants", args.view_instants,
                  "with --view, for a scene with sun paths: how many instants of each path to "
                  "draw and compare, spread evenly over it (default 4; 0: none); the per-face "
                  "comparison takes every instant")
      ->check(whole_number_in(0, kMostViewInstants))
      ->needs(view);
  CLI::Option* sky = add_sky_option(
      command, args.sky_subdivisions, args.sky_given,
      "compare every face's sky view factor instead (report --format sky's), over the "
      "patches of tregenza (145) or reinhart:N (144 N² + 1, N from 1 to 64), each a light: "
      "the exact value, then each method's from its estimated lit areas (rays: a shadow ray "
      "from each sample point towards each patch's centre), with the error of each and, in "
      "CSV, every face's values");
  sky->excludes(view);
  sky->excludes(plot);
  add_output_option(command, args.output,
                    "file to write the table to (replaced whole); default: standard output");
  add_reading_options(command, args.reading, /*progress=*/true);
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  return make_command<CompareArgs>(app, kCompareText, add_compare_options, run_compare);
}

}  // namespace shadowgen::cli
