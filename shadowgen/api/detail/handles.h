#pragma once

// What the public handles hold: the library's own scene and shadowed scene, shared and
// immutable, so that a copy of a handle is a pointer's copy.

#include <memory>

#include "shadowgen/api/scene.h"
#include "shadowgen/api/shadows.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::api {

struct Scene::Impl {
  std::shared_ptr<const shadowgen::Scene> scene;
};

struct Shadows::Impl {
  std::shared_ptr<const ShadowedScene> shadowed;
  unsigned threads = 0;  // GenerateSettings::threads of the generation or load
};

}  // namespace shadowgen::api

namespace shadowgen::api::detail {

// A handle owning `scene`.
Scene scene_handle(shadowgen::Scene scene);
// A handle that only refers to `scene`, which must outlive it (LoadSettings::on_scene).
Scene scene_view(const shadowgen::Scene& scene);
Shadows shadows_handle(ShadowedScene shadowed, unsigned threads);

inline const shadowgen::Scene& model(const Scene& scene) { return *scene.impl().scene; }
inline const ShadowedScene& model(const Shadows& shadows) { return *shadows.impl().shadowed; }

}  // namespace shadowgen::api::detail
