#include "shadowgen/view/view_comparison.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "shadowgen/view/camera.h"

namespace shadowgen {
namespace {

template <typename Work>
double seconds_of(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  const auto end = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(end - start).count();
}

}  // namespace

LitAgreement lit_agreement(const ShadowedScene& shadowed, const PixelSurfaces& surfaces,
                           const PixelLitWeights& exact, const PixelLitWeights& other) {
  LitAgreement result;
  const int w = surfaces.width, h = surfaces.height;
  const auto index = [w](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
  };
  for (std::size_t l = 0; l < exact.lights; ++l) {
    if (!shadowed.lit().kept(l)) continue;  // no lit polygons: 0 whatever the method
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = index(x, y);
        const PixelSurface& pixel = surfaces.pixels[i];
        if (!pixel.seen() || !pixel.front) continue;
        const bool lit = lit_state(exact.at(i, l));
        bool uniform = true;
        for (int dy = -1; dy <= 1 && uniform; ++dy) {
          for (int dx = -1; dx <= 1 && uniform; ++dx) {
            const std::size_t j = index(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1));
            uniform = surfaces.pixels[j].face == pixel.face && lit_state(exact.at(j, l)) == lit;
          }
        }
        if (!uniform) {
          ++result.boundary;
          continue;
        }
        ++result.compared;
        (lit ? result.lit : result.shadowed) += 1;
        if (lit != lit_state(other.at(i, l))) ++result.disagreeing;
      }
    }
  }
  return result;
}

ViewComparison compare_view_methods(const ShadowedScene& exact, const ViewSpec& view, int width,
                                    int height, std::span<const PixelShadowOptions> methods) {
  ViewComparison comparison;
  comparison.view = view.id;
  comparison.width = width;
  comparison.height = height;
  PixelSurfaces surfaces;
  comparison.surfaces_seconds = seconds_of([&] {
    surfaces = pixel_surfaces(exact.scene(), camera_from_view(view, false), width, height);
  });
  PixelLitWeights reference;
  const double exact_seconds = seconds_of([&] {
    reference = pixel_lit_weights(exact, surfaces, {PixelShadows::kExact, 0});
  });
  for (const PixelShadowOptions& method : methods) {
    ViewTrial trial;
    trial.method = std::string(pixel_shadows_name(method.method));
    if (method.method == PixelShadows::kExact) {
      trial.seconds = exact_seconds;
      trial.agreement = lit_agreement(exact, surfaces, reference, reference);
    } else {
      if (method.method == PixelShadows::kShadowMap || method.method == PixelShadows::kAngular) {
        trial.resolution = method.resolution;
      }
      PixelLitWeights weights;
      trial.seconds = seconds_of([&] { weights = pixel_lit_weights(exact, surfaces, method); });
      trial.agreement = lit_agreement(exact, surfaces, reference, weights);
    }
    comparison.trials.push_back(std::move(trial));
  }
  mark_pareto(comparison.trials, [](const ViewTrial& t) { return t.agreement.share(); });
  return comparison;
}

}  // namespace shadowgen
