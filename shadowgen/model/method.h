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

// A view method's lit states against the exact method's over the pixels of a picture
// (shadowgen/view/view_comparison.h counts them): a pixel is lit for a light where its
// weight is at least 1/2. Pairs on a region boundary are left out: a pixel seen from the
// front whose 3 × 3 neighbourhood (clamped at the picture's edge) is not uniform in the
// face seen or in exact's lit state for that light.
struct LitAgreement {
  std::size_t compared = 0;           // (pixel, light) pairs off boundaries
  std::size_t disagreeing = 0;        // of those, the ones whose lit state differs
  std::size_t boundary = 0;           // pairs left out, on boundaries
  std::size_t lit = 0, shadowed = 0;  // exact's, among those compared

  // disagreeing / compared; 0 where nothing is compared.
  double share() const {
    return compared ? static_cast<double>(disagreeing) / static_cast<double>(compared) : 0.0;
  }
};

// One view method (shadowgen/view/pixel_shadows.h) measured against the exact one from a
// view of the scene (`compare --view`).
struct ViewTrial {
  std::string method;    // "exact", "shadow-map", "volumes" or "stencil"
  int resolution = 0;    // shadow-map: texels a side of each depth map; angular: rows; else 0
  double seconds = 0.0;  // wall time of its lit weights (the surfaces seen found before all)
  LitAgreement agreement;
  // No other view trial is at least as fast and agrees at least as often (by share), and
  // better in one of the two.
  bool pareto = false;
};

struct ViewComparison {
  std::string view;               // the id of the scene's view
  int width = 0, height = 0;      // pixels
  double surfaces_seconds = 0.0;  // wall time of finding the surfaces seen, once for all
  std::vector<ViewTrial> trials;  // in the order given
  // Where the scene has sun paths: how many instants they have, and the ids of those drawn
  // (the others are not compared).
  std::size_t path_instants = 0;
  std::vector<std::string> instants;
};

// "shadow-map @ 1024", "volumes": a view trial's name in tables.
std::string view_trial_label(const ViewTrial& trial);

// Sets `pareto` on each of `trials` that no other beats: at least as fast and at least as
// good by `error(trial)`, and better in one of the two.
template <typename Trial, typename Error>
void mark_pareto(std::vector<Trial>& trials, Error error) {
  for (Trial& t : trials) {
    t.pareto = true;
    for (const Trial& other : trials) {
      const bool no_worse = other.seconds <= t.seconds && error(other) <= error(t);
      const bool better = other.seconds < t.seconds || error(other) < error(t);
      if (&other != &t && no_worse && better) {
        t.pareto = false;
        break;
      }
    }
  }
}

// "exact", "rays", "shadow-map".
std::string_view method_name(MethodKind kind);
// The kind named `name`; nullopt for any other text.
std::optional<MethodKind> method_kind(std::string_view name);

}  // namespace shadowgen
