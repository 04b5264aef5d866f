#include "shadowgen/api/shadows.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "detail/handles.h"
#include "detail/on_threads.h"
#include "detail/translated.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/method.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/model/parallel_release.h"
#include "shadowgen/output/report.h"
#include "shadowgen/output/sun_hours_report.h"
#include "shadowgen/pipeline/load_shadowed.h"
#include "shadowgen/pipeline/method_run.h"
#include "shadowgen/shadowgen.h"

namespace shadowgen::api {
namespace {

// The method `settings` ask for; std::invalid_argument for a number out of its range.
shadowgen::Method method_of(const GenerateSettings& settings) {
  shadowgen::Method method;
  if (settings.method == Method::kExact) return method;
  if (settings.samples < 1 || settings.samples > kMaxSamples) {
    throw std::invalid_argument("samples must be from 1 to " + std::to_string(kMaxSamples));
  }
  method.kind = settings.method == Method::kRays ? MethodKind::kRays : MethodKind::kShadowMap;
  method.samples = settings.samples;
  if (method.kind == MethodKind::kShadowMap) {
    if (settings.resolution < 1 || settings.resolution > kMaxResolution) {
      throw std::invalid_argument("resolution must be from 1 to " + std::to_string(kMaxResolution));
    }
    method.resolution = settings.resolution;
  }
  return method;
}

GenerateOptions generate_options(const GenerateSettings& settings) {
  GenerateOptions options;
  options.threads = settings.threads;
  options.sun_hours_regions = settings.sun_hours_regions;
  options.keep_instant_polygons = settings.keep_instant_polygons;
  if (settings.shard) options.shard = ShardPlace{settings.shard->index, settings.shard->count};
  if (settings.on_light_done) {
    options.on_light_done = [then = settings.on_light_done](std::size_t light,
                                                            const LightStats& stats) {
      then({light, stats.faces_considered, stats.lit_polygons, stats.seconds});
    };
  }
  return options;
}

PolygonData polygon_data(const hsr::Polygon3& polygon) {
  const auto points_of = [](const hsr::Loop3& loop) {
    Loop points;
    for (const auto& p : loop) points.push_back({p.x, p.y, p.z});
    return points;
  };
  PolygonData data{points_of(polygon.outer), {}};
  for (const hsr::Loop3& hole : polygon.holes) data.holes.push_back(points_of(hole));
  return data;
}

}  // namespace

Shadows::Shadows(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Scene Shadows::scene() const {
  std::shared_ptr<const shadowgen::Scene> scene(impl_->shadowed, &impl_->shadowed->scene());
  return Scene(std::make_shared<const Scene::Impl>(Scene::Impl{std::move(scene)}));
}

bool Shadows::exact() const { return detail::model(*this).is_exact(); }

std::string Shadows::method() const { return method_label(detail::model(*this).method()); }

std::vector<LitArea> Shadows::lit_areas() const {
  const ShadowedScene& shadowed = detail::model(*this);
  std::vector<LitArea> rows;
  const std::vector<ReportRow> report =
      detail::on_threads(*this, [&] { return report_rows(shadowed); });
  for (const ReportRow& row : report) {
    rows.push_back({row.face, row.light, shadowed.scene().faces[row.face].id,
                    shadowed.scene().lights[row.light].id, row.area, row.lit_area,
                    row.lit_fraction});
  }
  return rows;
}

std::vector<PolygonData> Shadows::lit_polygons(std::size_t face, std::size_t light) const {
  const ShadowedScene& shadowed = detail::model(*this);
  if (face >= shadowed.scene().faces.size() || light >= shadowed.scene().lights.size()) {
    throw std::out_of_range("lit_polygons: face or light index out of range");
  }
  if (shadowed.estimate() || !shadowed.lit().kept(light)) {
    detail::translated([&] {
      throw shadowgen::InputError(shadowed.scene().file, "",
                                  "light '" + one_line(shadowed.scene().lights[light].id) +
                                      "': no lit polygons kept (a sampled method's estimate, or "
                                      "a sun path's instant summed into sun hours)");
    });
  }
  std::vector<PolygonData> polygons;
  for (const LitPolygon& lit : shadowed.lit().at(face, light)) {
    polygons.push_back(polygon_data(lit.polygon));
  }
  return polygons;
}

std::vector<SunHours> Shadows::sun_hours(const std::vector<double>& thresholds) const {
  return detail::on_threads(*this, [&] {
    const ShadowedScene& shadowed = detail::model(*this);
    std::vector<SunHours> rows;
    for (SunHoursRow& row : sun_hours_rows(shadowed, thresholds)) {
      rows.push_back({row.face, shadowed.scene().faces[row.face].id,
                      shadowed.sun_paths[row.path].id, row.area, row.mean_hours, row.min_hours,
                      row.max_hours, std::move(row.area_at_least)});
    }
    return rows;
  });
}

Shadows generate(const Scene& scene, const GenerateSettings& settings) {
  return detail::translated([&] {
    const shadowgen::Scene& model = detail::model(scene);
    try {
      return detail::shadows_handle(
          shadows_by_method(model, method_run(method_of(settings), generate_options(settings)))
              .shadowed,
          settings.threads);
    } catch (const shadowgen::GenerationError& e) {
      throw shadowgen::GenerationError(model.file, e.face_id(), e.light_id(), e.problem());
    }
  });
}

Shadows load(const std::string& path, const LoadSettings& settings) {
  return detail::translated([&] {
    LoadOptions options;
    options.strict = settings.read.strict;
    options.verbose = settings.read.verbose;
    options.lights = settings.read.lights;
    options.on_warning = settings.read.on_warning;
    options.generate = generate_options(settings.generate);
    options.method = method_of(settings.generate);
    if (settings.on_scene) {
      options.on_scene = [&settings](const shadowgen::Scene& scene) {
        settings.on_scene(detail::scene_view(scene));
      };
    }
    return detail::shadows_handle(load_shadowed(path, options), options.generate.threads);
  });
}

const char* version() { return SHADOWGEN_VERSION; }

namespace detail {

Shadows shadows_handle(ShadowedScene shadowed, unsigned threads) {
  // Freed on the threads it was made with, face by face (model/parallel_release.h): where
  // the arena cannot be had, the destructor frees it all on the calling thread.
  std::shared_ptr<const ShadowedScene> owned(
      new ShadowedScene(std::move(shadowed)), [threads](const ShadowedScene* held) {
        auto* owned_scene = const_cast<ShadowedScene*>(held);  // made non-const just above
        try {
          tbb::task_arena arena = arena_of(threads);
          arena.execute([owned_scene] { release_faces_in_parallel(*owned_scene); });
        } catch (...) {
        }
        delete owned_scene;
      });
  return Shadows(std::make_shared<const Shadows::Impl>(Shadows::Impl{std::move(owned), threads}));
}

}  // namespace detail

}  // namespace shadowgen::api
