#include "shadowgen/output/method_table.h"

#include <charconv>

#include "detail/csv_fields.h"
#include "detail/text_table.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen {
namespace {

std::string scientific(double value) {
  if (value == 0.0) return "0";
  return number_text(value, std::chars_format::scientific, 2);
}

}  // namespace

std::string comparison_table(const MethodComparison& comparison, const Scene& scene,
                             const ViewComparison* view) {
  std::string out = "errors of lit fractions over " + std::to_string(comparison.pairs) +
                    " (face, light) pairs, against the exact method; " +
                    (comparison.threads == 0 ? std::string("one thread per core")
                                             : std::to_string(comparison.threads) + " thread(s)") +
                    "\n";
  output::detail::TextTable table({false, true, true, true, false, false, false});
  table.add(
      {"method", "seconds", "mean |error|", "max |error|", "worst face", "worst light", "pareto"});
  for (const MethodTrial& t : comparison.trials) {
    const bool worst = t.max_error > 0.0;
    table.add({method_label(t.method), number_text(t.seconds, std::chars_format::general, 3),
               scientific(t.mean_error), scientific(t.max_error),
               worst ? one_line(scene.faces[t.worst_face].id) : "",
               worst ? one_line(scene.lights[t.worst_light].id) : "", t.pareto ? "*" : ""});
  }
  table.append_to(out);
  if (view == nullptr) return out;
  out += "\nview " + one_line(view->view) + ", " + std::to_string(view->width) + "×" +
         std::to_string(view->height) +
         ": share of (pixel, light) pairs off boundaries whose lit state differs from exact "
         "(surfaces seen found in " +
         number_text(view->surfaces_seconds, std::chars_format::general, 3) + " s)\n";
  if (view->path_instants > 0) {
    out += "instants of sun paths drawn: " + std::to_string(view->instants.size()) + " of " +
           std::to_string(view->path_instants);
    for (std::size_t k = 0; k < view->instants.size(); ++k) {
      out += (k == 0 ? " (" : ", ") + one_line(view->instants[k]);
    }
    out += view->instants.empty() ? "\n" : ")\n";
  }
  output::detail::TextTable views({false, true, true, true, false});
  views.add({"view method", "seconds", "differing share", "pairs", "pareto"});
  for (const ViewTrial& t : view->trials) {
    views.add({view_trial_label(t), number_text(t.seconds, std::chars_format::general, 3),
               scientific(t.agreement.share()), std::to_string(t.agreement.compared),
               t.pareto ? "*" : ""});
  }
  views.append_to(out);
  return out;
}

std::string comparison_csv(const MethodComparison& comparison, const Scene& scene, CsvIds ids,
                           const ViewComparison* view) {
  std::string out =
      "method,samples,resolution,seconds,mean_error,max_error,worst_face,worst_light,pareto\n";
  for (const MethodTrial& t : comparison.trials) {
    out += method_name(t.method.kind);
    out += ',';
    if (!t.method.exact()) out += std::to_string(t.method.samples);
    out += ',';
    if (t.method.kind == MethodKind::kShadowMap) out += std::to_string(t.method.resolution);
    out += ',';
    output::detail::append_csv_number(out, t.seconds);
    out += ',';
    output::detail::append_csv_number(out, t.mean_error);
    out += ',';
    output::detail::append_csv_number(out, t.max_error);
    out += ',';
    if (t.max_error > 0.0) output::detail::append_csv_field(out, scene.faces[t.worst_face].id, ids);
    out += ',';
    if (t.max_error > 0.0)
      output::detail::append_csv_field(out, scene.lights[t.worst_light].id, ids);
    out += t.pareto ? ",1\n" : ",0\n";
  }
  if (view == nullptr) return out;
  out += "\nview_method,resolution,seconds,differing_share,pairs,pareto\n";
  for (const ViewTrial& t : view->trials) {
    out += t.method;
    out += ',';
    if (t.resolution > 0) out += std::to_string(t.resolution);
    out += ',';
    output::detail::append_csv_number(out, t.seconds);
    out += ',';
    output::detail::append_csv_number(out, t.agreement.share());
    out += ',';
    out += std::to_string(t.agreement.compared);
    out += t.pareto ? ",1\n" : ",0\n";
  }
  return out;
}

}  // namespace shadowgen
