#pragma once

// A comparison of methods (shadowgen/pipeline/method_comparison.h) as an SVG plot, readable
// without the table: each trial a point at (seconds, mean |error| of lit fractions) on
// log-log axes, labelled with its method, a line up to its largest error; the trials no
// other beats on both (Pareto-optimal) filled and joined by a line; the exact method,
// whose error is 0 and has no place on a log axis, on a strip of its own below the
// axis, at its time. With a comparison of view methods (`compare --view`), a second panel
// below: each view method at (seconds, share of (pixel, light) pairs differing from
// exact), the same way.

#include <filesystem>
#include <string>

#include "shadowgen/model/method.h"

namespace shadowgen {

std::string comparison_svg(const MethodComparison& comparison,
                           const ViewComparison* view = nullptr);

// Writes through a temporary file and a rename (shadowgen/output/atomic_file.h).
void write_comparison_svg(const MethodComparison& comparison, const std::filesystem::path& path,
                          const ViewComparison* view = nullptr);

}  // namespace shadowgen
