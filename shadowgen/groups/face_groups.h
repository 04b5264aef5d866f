#pragma once

// Groups of faces that reports sum over (docs/scene-format.md, "Groups"): a scene's
// `groups` (Scene::groups, kept in the database), or the rules `report --group-by` gives,
// resolved against the faces of a scene.
//
//   std::vector<FaceGroup> groups = scene_groups(scene);         // the scene's own
//   groups = groups_by(scene, {"garden*", "origin.group"});      // or the command line's
//
// A rule is one of:
// - `origin.KEY`, KEY one of format, object, group, semantic: one group per value of the
//   faces' FaceOrigin::KEY, in the order the faces first give it, named by the value (faces
//   without one are in none of them);
// - `scene.groups`: the scene's own groups (scene_groups);
// - a face pattern (shadowgen/groups/face_pattern.h): one group of the faces whose ids it
//   matches, named by the pattern as written. Any other rule beginning with `origin.` or
//   `scene.` is refused as a misspelt key; a pattern beginning so is written `origin\.`.
// A face may be in several groups, and is counted once in each.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "shadowgen/model/scene.h"

namespace shadowgen::groups {

struct FaceGroup {
  std::string id;
  std::vector<std::size_t> faces;  // indices into Scene::faces, increasing, at least one
};

// The faces whose ids `pattern` (a valid FacePattern) matches, in scene order.
std::vector<std::size_t> faces_matching(const Scene& scene, const std::string& pattern);

// The scene's groups, in order, each the faces any of its patterns matches. Throws
// InputError naming Scene::file and the group where a pattern matches no face
// ("group 'garden': the pattern 'gardn*' matches no face id"), or two groups share an id.
std::vector<FaceGroup> scene_groups(const Scene& scene);

// What is wrong with `rule` as a --group-by rule (an origin key not among the four, a
// pattern FacePattern refuses); nullopt when it is one. For the command line, before any
// work.
std::optional<std::string> group_rule_problem(std::string_view rule);

// The groups the rules give, in the order of the rules (an origin rule's groups in the
// order of their first faces). Throws std::invalid_argument where a rule has a problem
// (group_rule_problem) or a rule is given twice, and InputError naming Scene::file where a
// pattern matches no face, an origin rule finds no face with that origin key, scene.groups
// finds no group in the scene, or two groups
// come out with one id (a building and a pattern of that name).
std::vector<FaceGroup> groups_by(const Scene& scene, std::span<const std::string> rules);

}  // namespace shadowgen::groups
