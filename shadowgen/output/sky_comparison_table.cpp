#include "shadowgen/output/sky_comparison_table.h"

#include <charconv>

#include "detail/csv_fields.h"
#include "detail/text_table.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/sky/sky_patches.h"
#include "shadowgen/sky/sky_subdivision.h"

namespace shadowgen {
namespace {

std::string scientific(double value) {
  if (value == 0.0) return "0";
  return number_text(value, std::chars_format::scientific, 2);
}

// The method as --methods spells it.
std::string method_spelling(const Method& method) {
  std::string out(method_name(method.kind));
  if (method.kind == MethodKind::kShadowMap) {
    out += ':';
    out += std::to_string(method.resolution);
    out += ":samples=";
  } else if (method.kind == MethodKind::kRays) {
    out += ':';
  }
  if (!method.exact()) out += std::to_string(method.samples);
  return out;
}

}  // namespace

std::string sky_comparison_table(const sky::SkyComparison& comparison, const Scene& scene) {
  std::string out = "sky view factors over " + std::to_string(scene.faces.size()) + " faces, " +
                    sky::subdivision_name(comparison.subdivisions) + " (" +
                    std::to_string(sky::reinhart_patches(comparison.subdivisions).size()) +
                    " patches), against the exact method\n";
  output::detail::TextTable table({false, true, true, true, true, true, false, false});
  table.add({"method", "seconds", "mean |error|", "max |error|", "mean rel.", "max rel.",
             "worst face", "pareto"});
  for (std::size_t t = 0; t < comparison.trials.size(); ++t) {
    const sky::SkyTrial& trial = comparison.trials[t];
    const sky::SkyErrors e = sky::sky_errors(comparison, t);
    table.add(
        {method_label(trial.method), number_text(trial.seconds, std::chars_format::general, 3),
         scientific(e.mean_error), scientific(e.max_error), scientific(e.mean_relative_error),
         scientific(e.max_relative_error),
         e.max_error > 0.0 ? one_line(scene.faces[e.worst_face].id) : "", trial.pareto ? "*" : ""});
  }
  table.append_to(out);
  return out;
}

std::string sky_comparison_csv(const sky::SkyComparison& comparison, const Scene& scene,
                               CsvIds ids) {
  std::string out =
      "method,samples,resolution,seconds,mean_error,max_error,mean_relative_error,"
      "max_relative_error,worst_face,pareto\n";
  for (std::size_t t = 0; t < comparison.trials.size(); ++t) {
    const sky::SkyTrial& trial = comparison.trials[t];
    const sky::SkyErrors e = sky::sky_errors(comparison, t);
    out += method_name(trial.method.kind);
    out += ',';
    if (!trial.method.exact()) out += std::to_string(trial.method.samples);
    out += ',';
    if (trial.method.kind == MethodKind::kShadowMap) {
      out += std::to_string(trial.method.resolution);
    }
    for (const double v :
         {trial.seconds, e.mean_error, e.max_error, e.mean_relative_error, e.max_relative_error}) {
      out += ',';
      output::detail::append_csv_number(out, v);
    }
    out += ',';
    if (e.max_error > 0.0) output::detail::append_csv_field(out, scene.faces[e.worst_face].id, ids);
    out += trial.pareto ? ",1\n" : ",0\n";
  }
  out += "\nface_id,area";
  for (const sky::SkyTrial& trial : comparison.trials) {
    out += ',';
    out += method_spelling(trial.method);
  }
  out += '\n';
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    output::detail::append_csv_field(out, scene.faces[f].id, ids);
    out += ',';
    output::detail::append_csv_number(out, comparison.area[f]);
    for (const sky::SkyTrial& trial : comparison.trials) {
      out += ',';
      output::detail::append_csv_number(out, trial.sky_view_factor[f]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace shadowgen
