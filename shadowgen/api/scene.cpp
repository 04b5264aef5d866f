#include "shadowgen/api/scene.h"

#include <utility>

#include "detail/handles.h"
#include "detail/scene_json.h"
#include "detail/translated.h"
#include "shadowgen/groups/face_groups.h"
#include "shadowgen/pipeline/light_choice.h"
#include "shadowgen/scene/scene_reader.h"

namespace shadowgen::api {
namespace {

shadowgen::ReadOptions read_options(const ReadSettings& settings) {
  shadowgen::ReadOptions read;
  read.strict = settings.strict;
  read.verbose = settings.verbose;
  return read;
}

// The scene read, its warnings passed on and its lights kept as `settings` ask.
Scene prepared(ReadResult read, const std::string& file, const ReadSettings& settings) {
  if (settings.on_warning) {
    for (const std::string& warning : read.warnings) settings.on_warning(warning);
  }
  keep_lights(read.scene, settings.lights, file);
  return detail::scene_handle(std::move(read.scene));
}

// The ids of `items` (faces, lights, sun paths, views), in order.
template <class Items>
std::vector<std::string> ids_of(const Items& items) {
  std::vector<std::string> ids;
  for (const auto& item : items) ids.push_back(item.id);
  return ids;
}

}  // namespace

Scene::Scene(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

const std::string& Scene::file() const { return detail::model(*this).file; }

std::vector<std::string> Scene::files() const { return detail::model(*this).files; }

std::vector<std::string> Scene::face_ids() const { return ids_of(detail::model(*this).faces); }

std::vector<std::string> Scene::light_ids() const { return ids_of(detail::model(*this).lights); }

std::vector<std::string> Scene::sun_path_ids() const {
  return ids_of(detail::model(*this).sun_paths);
}

std::vector<std::string> Scene::view_ids() const { return ids_of(detail::model(*this).views); }

Scene read_scene(const std::string& path, const ReadSettings& settings) {
  return detail::translated([&] {
    return prepared(shadowgen::read_scene(path, read_options(settings)), path, settings);
  });
}

Scene make_scene(const SceneData& data, const ReadSettings& settings) {
  return detail::translated([&] {
    return prepared(parse_scene(detail::scene_json(data), data.name, read_options(settings)),
                    data.name, settings);
  });
}

std::vector<Group> groups(const Scene& scene, const std::vector<std::string>& rules) {
  return detail::translated([&] {
    const shadowgen::Scene& model = detail::model(scene);
    std::vector<Group> groups;
    for (groups::FaceGroup& group :
         rules.empty() ? groups::scene_groups(model) : groups::groups_by(model, rules)) {
      groups.push_back({std::move(group.id), std::move(group.faces)});
    }
    return groups;
  });
}

namespace detail {

Scene scene_handle(shadowgen::Scene scene) {
  auto owned = std::make_shared<const shadowgen::Scene>(std::move(scene));
  return Scene(std::make_shared<const Scene::Impl>(Scene::Impl{std::move(owned)}));
}

Scene scene_view(const shadowgen::Scene& scene) {
  // The aliasing constructor with no owner: a pointer that keeps nothing alive.
  std::shared_ptr<const shadowgen::Scene> view(std::shared_ptr<const shadowgen::Scene>(), &scene);
  return Scene(std::make_shared<const Scene::Impl>(Scene::Impl{std::move(view)}));
}

}  // namespace detail

}  // namespace shadowgen::api
