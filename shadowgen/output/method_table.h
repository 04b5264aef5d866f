#pragma once

// A comparison of methods on one scene (shadowgen/pipeline/method_comparison.h) as text:
//
//   comparison_table, for reading:
//     method              seconds  mean |error|  max |error|  worst face  worst light  pareto
//     exact                 0.412             0            0                            *
//     rays 64              0.0311      2.95e-03     4.17e-02  lawn        sun          *
//   (errors are of lit fractions; "pareto": no other row is as fast and as accurate);
//
//   comparison_csv, one row per trial:
//     method,samples,resolution,seconds,mean_error,max_error,worst_face,worst_light,pareto
//     rays,64,,0.0311,0.00295...,0.0417...,lawn,sun,1
//   samples and resolution empty where the method takes none, the worst face and light
//   empty for a trial without error, numbers as the CSV report writes them.
//
// With `view` (compare --view), a second block follows the first: in the table, after a
// blank line, "view ID, W×H: ..." and one row per view trial (method, seconds, the share
// of (pixel, light) pairs off boundaries whose lit state differs from exact's, the pairs
// compared, the Pareto mark); in CSV, after one blank line,
//     view_method,resolution,seconds,differing_share,pairs,pareto
//     shadow-map,1024,0.0412,0.00131...,18230,1
//   resolution empty where the method takes none.

#include <string>

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/output/report.h"

namespace shadowgen {

std::string comparison_table(const MethodComparison& comparison, const Scene& scene,
                             const ViewComparison* view = nullptr);

std::string comparison_csv(const MethodComparison& comparison, const Scene& scene, CsvIds ids,
                           const ViewComparison* view = nullptr);

}  // namespace shadowgen
