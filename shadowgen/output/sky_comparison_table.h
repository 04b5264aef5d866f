#pragma once

// Sky view factors by several methods (sky/sky_comparison.h, `compare --sky`) as text:
//
//   sky_comparison_table, for reading:
//     sky view factors over 3 faces, reinhart:2 (577 patches), against the exact method
//     method   seconds  mean |error|  max |error|  mean rel.  max rel.  worst face  pareto
//     exact      0.412             0            0          0         0              *
//     rays 64   0.0311      2.95e-03     4.17e-02   6.12e-03  9.30e-02  floor       *
//
//   sky_comparison_csv, the trials, a blank line, then the view factors per face:
//     method,samples,resolution,seconds,mean_error,max_error,mean_relative_error,
//       max_relative_error,worst_face,pareto          (one line)
//     rays,64,,0.0311,0.00295...,0.0417...,0.00612...,0.0930...,floor,1
//
//     face_id,area,exact,rays:64
//     floor,0.0001,0.4472...,0.4401...
//
// Errors are |SVF − exact SVF| (relative: divided by the exact SVF, over faces where it is
// positive); "pareto": no other row is as fast and as accurate by the mean error. The
// per-face columns are headed by each trial's method as --methods spells it
// (`shadow-map:R:samples=N`); numbers as the CSV report writes them; the worst face empty
// for a trial without error.

#include <string>

#include "shadowgen/model/scene.h"
#include "shadowgen/output/report.h"
#include "shadowgen/sky/sky_comparison.h"

namespace shadowgen {

std::string sky_comparison_table(const sky::SkyComparison& comparison, const Scene& scene);

std::string sky_comparison_csv(const sky::SkyComparison& comparison, const Scene& scene,
                               CsvIds ids);

}  // namespace shadowgen
