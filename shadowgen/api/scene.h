#pragma once

// A scene, read from a file or made from plain data, before its shadows are generated
// (generate, in shadowgen/api/shadows.h), and the groups of faces reports sum over.
//
//   shadowgen::api::Scene scene = shadowgen::api::read_scene("courtyard.json");
//   for (const std::string& id : scene.light_ids()) std::cout << id << '\n';
//
// Every function here throws InputError naming the file (and the face) for bad input.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "shadowgen/api/scene_data.h"

namespace shadowgen::api {

// How a scene is read.
struct ReadSettings {
  // What is otherwise a warning is an error: a polygon that is not planar (else split into
  // triangles), a key the format does not define.
  bool strict = false;
  // Every reading warning on its own line (otherwise a kind that many faces of one mesh
  // draw is one line: how many, the first ids).
  bool verbose = false;
  // When not empty, only these lights, as if the input held no other; a sun path's id
  // names all its instants. An id the input has no light of is an InputError.
  std::vector<std::string> lights = {};
  // Each reading warning, one line naming the file; dropped when empty.
  std::function<void(const std::string& warning)> on_warning = {};
};

// A scene as read and checked: faces, lights (a sun path is one light per instant with the
// sun up, `<path id>@<YYYY-MM-DDTHH:MM>`), views and groups. Cheap to copy (shared,
// immutable).
class Scene {
 public:
  struct Impl;  // the library's own
  explicit Scene(std::shared_ptr<const Impl> impl);

  // The file it was read from as messages name it ("-" for standard input), or
  // SceneData::name.
  const std::string& file() const;
  // Every file it was read from: the scene, its mesh files, its weather file.
  std::vector<std::string> files() const;
  std::vector<std::string> face_ids() const;   // in scene order (polygons, then meshes)
  std::vector<std::string> light_ids() const;  // in scene order
  std::vector<std::string> sun_path_ids() const;
  std::vector<std::string> view_ids() const;
  const Impl& impl() const { return *impl_; }

 private:
  std::shared_ptr<const Impl> impl_;
};

// The scene file at `path` (docs/scene-format.md), its mesh and model files read relative
// to it; "-" reads standard input.
Scene read_scene(const std::string& path, const ReadSettings& settings = {});

// The scene `data` holds, checked as a file holding it would be (messages name data.name).
Scene make_scene(const SceneData& data, const ReadSettings& settings = {});

// A set of faces that reports sum over.
struct Group {
  std::string id = {};
  std::vector<std::size_t> faces = {};  // indices into the scene's faces, increasing
};

// The groups `rules` give (face patterns such as "garden*"; "origin.group",
// "origin.object", "origin.semantic" or "origin.format" for one group per value of the
// faces' origins; "scene.groups" for the scene's own), or with no rules the scene's own
// groups. A rule that matches no face is an InputError.
std::vector<Group> groups(const Scene& scene, const std::vector<std::string>& rules = {});

}  // namespace shadowgen::api
