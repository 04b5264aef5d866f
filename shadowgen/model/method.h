#pragma once

// How lit areas are found (docs/scene-format.md, "Methods"): `exact`, the lit regions
// themselves, or a sampled estimate of their areas. A run records its method, and a
// database names it, so that an estimate is never taken for the exact answer.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowgen {

enum class MethodKind {
  kExact,      // lit detail polygons (Atherton, Weiler and Greenberg)
  kRays,       // stratified points per face, a shadow ray from each (Embree)
  kShadowMap,  // stratified points per face, looked up in a depth map from the light
};

struct Method {
  MethodKind kind = MethodKind::kExact;
  // kRays and kShadowMap: sample points per face (stratified over its area).
  int samples = 0;
  // kShadowMap: texels along each side of a light view's depth map.
  int resolution = 0;

  bool exact() const { return kind == MethodKind::kExact; }
  friend bool operator==(const Method&, const Method&) = default;
};

inline constexpr int kDefaultSamples = 256;
inline constexpr int kDefaultResolution = 2048;
inline constexpr int kMaxSamples = 1 << 20;     // per face
inline constexpr int kMaxResolution = 1 << 15;  // texels per side

// "exact", "rays 64", "shadow-map 64 @ 2048": a method's name in tables and plots.
std::string method_label(const Method& method);

// One method measured against the exact one on a scene (shadowgen/pipeline/
// method_comparison.h makes them; reports and plots show them).
struct MethodTrial {
  Method method;
  double seconds = 0.0;  // wall time of its shadows (the scene read once, before all)
  // Over every (face, light) of a face with area, instants of sun paths included:
  // |lit fraction − the exact method's|, its mean and its largest, and where that is.
  double mean_error = 0.0;
  double max_error = 0.0;
  std::size_t worst_face = 0, worst_light = 0;
  // No other trial is at least as fast and at least as accurate (by mean error), and
  // better in one of the two.
  bool pareto = false;
};

struct MethodComparison {
  std::vector<MethodTrial> trials;  // exact first, then `methods` in the order given
  std::size_t pairs = 0;            // the (face, light) pairs the errors are taken over
  unsigned threads = 0;             // as options.threads (0: one per hardware thread)
};

// "exact", "rays", "shadow-map".
std::string_view method_name(MethodKind kind);
// The kind named `name`; nullopt for any other text.
std::optional<MethodKind> method_kind(std::string_view name);

}  // namespace shadowgen
