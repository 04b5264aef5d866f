#pragma once

// Methods measured against one another on the user's own scene (`shadowgen compare`): each
// run in turn on the same scene, its time taken, its lit fractions compared with the exact
// method's, and the runs that no other beats on both time and error marked.

#include <functional>
#include <span>

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {

// Runs the exact method, then each of `methods` (an exact one among them is the first
// trial, not run again), with `options` (sun paths summed into lit areas alone: regions
// take no part in a lit fraction). Where `exact_shadowed` is not null, the exact run's
// shadowed scene is moved into it at the end (its lit polygons, the instants of sun paths
// without theirs: what `compare --view` measures the view methods against). `on_trial`,
// where given, is called with each trial's method before it runs, the exact one first
// (for progress; not timed). Throws what shadows_by_method throws.
MethodComparison compare_methods(const Scene& scene, std::span<const Method> methods,
                                 GenerateOptions options, ShadowedScene* exact_shadowed = nullptr,
                                 const std::function<void(const Method&)>& on_trial = {});

}  // namespace shadowgen
