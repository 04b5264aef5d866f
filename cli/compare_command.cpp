// `shadowgen compare`: the methods run on the user's own scene, each one's time and error
// against the exact method, the Pareto-optimal ones marked.

#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/method_table.h"
#include "shadowgen/pipeline/method_comparison.h"
#include "shadowgen/view/method_plot.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kCompareText{
    "compare",
    "Run the methods on a scene (or a database's scene), one after another, and print each one's "
    "time and the error "
    "of its lit fractions against the exact method's (mean and largest over every face and "
    "light), marking those no other method beats on both time and error (Pareto-optimal). "
    "--plot draws error against time."};

// The default trials: three sample counts of each sampled method.
constexpr const char* kDefaultMethods[] = {"rays:16",
                                           "rays:64",
                                           "rays:256",
                                           "shadow-map:16:512",
                                           "shadow-map:64:1024",
                                           "shadow-map:256:2048"};

struct CompareArgs {
  std::string input;  // a scene
  std::vector<std::string> methods{std::begin(kDefaultMethods), std::end(kDefaultMethods)};
  std::string format = "table";  // table or csv
  bool csv_safe = false;
  std::string output;  // empty: standard output
  std::string plot;    // an SVG file, or none
  ReadingArgs reading;
};

// A count from 1 to `max` in `text`, or nullopt.
std::optional<int> count(const std::string& text, int max) {
  if (text.empty() || text.size() > 9 ||
      text.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  const int value = std::stoi(text);
  if (value < 1 || value > max) return std::nullopt;
  return value;
}

// NAME[:SAMPLES[:RESOLUTION]]: "exact", "rays:64", "shadow-map:64:1024". Throws UsageError.
Method parse_method(const std::string& text) {
  std::vector<std::string> fields{""};
  for (const char c : text) {
    if (c == ':') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  const std::optional<MethodKind> kind = method_kind(fields[0]);
  const std::size_t most = kind == MethodKind::kExact ? 1 : kind == MethodKind::kRays ? 2 : 3;
  const auto refuse = [&text] {
    throw UsageError("--methods " + text +
                     ": expected exact, rays[:SAMPLES] or shadow-map[:SAMPLES[:RESOLUTION]], "
                     "samples from 1 to " +
                     std::to_string(kMaxSamples) + ", resolution from 1 to " +
                     std::to_string(kMaxResolution));
  };
  if (!kind || fields.size() > most) refuse();
  Method method{*kind};
  if (method.exact()) return method;
  method.samples = kDefaultSamples;
  if (fields.size() > 1) {
    const std::optional<int> samples = count(fields[1], kMaxSamples);
    if (!samples) refuse();
    method.samples = *samples;
  }
  if (method.kind == MethodKind::kShadowMap) {
    method.resolution = kDefaultResolution;
    if (fields.size() > 2) {
      const std::optional<int> resolution = count(fields[2], kMaxResolution);
      if (!resolution) refuse();
      method.resolution = *resolution;
    }
  }
  return method;
}

void run_compare(const CompareArgs& args) {
  std::vector<Method> methods;
  for (const std::string& text : args.methods) methods.push_back(parse_method(text));
  std::vector<OutputFile> outputs;
  if (!args.output.empty()) {
    refuse_input_as_output("-o", args.output, args.input);
    outputs.push_back({"-o", args.output});
  }
  if (!args.plot.empty()) {
    refuse_input_as_output("--plot", args.plot, args.input);
    outputs.push_back({"--plot", args.plot});
  }
  const Scene scene = load_scene(
      args.input, load_options(args.reading, Accept::kSceneOrDatabase, std::move(outputs)));
  GenerateOptions options;
  options.threads = args.reading.threads;
  MethodComparison comparison;
  try {
    comparison = compare_methods(scene, methods, options);
  } catch (const GenerationError& e) {
    throw GenerationError(args.input, e.face_id(), e.light_id(), e.problem());
  }
  const std::string text =
      args.format == "csv"
          ? comparison_csv(comparison, scene,
                           args.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact)
          : comparison_table(comparison, scene);
  if (!args.plot.empty()) write_comparison_svg(comparison, args.plot);
  if (args.output.empty()) {
    std::cout << text << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write the comparison to standard output");
  } else {
    write_file_atomically(args.output, text);
  }
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
                  "shadow-map[:SAMPLES[:RESOLUTION]] (samples per face; texels a side of each "
                  "depth map); the exact method always runs first, as the reference (default: "
                  "rays:16,rays:64,rays:256,shadow-map:16:512,shadow-map:64:1024,"
                  "shadow-map:256:2048)")
      ->delimiter(',');
  command.add_option("--format", args.format, "table (default, for reading) or csv")
      ->check(CLI::IsMember({"table", "csv"}));
  command.add_flag("--csv-safe", args.csv_safe,
                   "CSV: put ' before an id that begins with =, +, -, @, a tab or a carriage "
                   "return, which spreadsheets would run as a formula");
  command.add_option("--plot", args.plot,
                     "SVG file to draw: mean error against time, log-log, the Pareto-optimal "
                     "methods joined");
  add_output_option(command, args.output,
                    "file to write the table to (replaced whole); default: standard output");
  add_reading_options(command, args.reading);
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  return make_command<CompareArgs>(app, kCompareText, add_compare_options, run_compare);
}

}  // namespace shadowgen::cli
