#include "shadowgen/groups/face_groups.h"

#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "shadowgen/groups/face_pattern.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::groups {
namespace {

constexpr std::string_view kOriginPrefix = "origin.";
constexpr std::string_view kScenePrefix = "scene.";
constexpr std::string_view kSceneGroups = "scene.groups";

// The origin keys a rule may name, with what each gives of a face's origin.
struct OriginKey {
  std::string_view name;
  std::string FaceOrigin::*member;
  std::string_view what;  // for messages: "an origin group"
};
constexpr OriginKey kOriginKeys[] = {
    {"format", &FaceOrigin::format, "a source format"},
    {"object", &FaceOrigin::object, "an origin object"},
    {"group", &FaceOrigin::group, "an origin group"},
    {"semantic", &FaceOrigin::semantic, "a semantic type"},
};

const OriginKey* origin_key(std::string_view rule) {
  if (!rule.starts_with(kOriginPrefix)) return nullptr;
  const std::string_view key = rule.substr(kOriginPrefix.size());
  for (const OriginKey& known : kOriginKeys) {
    if (known.name == key) return &known;
  }
  return nullptr;
}

// One group per value of `key`, in the order of the faces that first give it.
std::vector<FaceGroup> origin_groups(const Scene& scene, const OriginKey& key,
                                     std::string_view rule) {
  std::vector<FaceGroup> out;
  std::unordered_map<std::string_view, std::size_t> index;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const std::string& value = scene.faces[f].origin.*key.member;
    if (value.empty()) continue;
    const auto [it, added] = index.emplace(value, out.size());
    if (added) out.push_back({value, {}});
    out[it->second].faces.push_back(f);
  }
  if (out.empty()) {
    throw InputError(scene.file, "",
                     "--group-by " + std::string(rule) + ": no face has " + std::string(key.what) +
                         " (faces read from EnergyPlus, CityJSON and glTF models have origins)");
  }
  return out;
}

// The faces any of `patterns` matches, each once, in scene order.
std::vector<std::size_t> union_of(std::vector<std::vector<std::size_t>> sets, std::size_t faces) {
  std::vector<char> in(faces, 0);
  for (const std::vector<std::size_t>& set : sets) {
    for (const std::size_t f : set) in[f] = 1;
  }
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < faces; ++f) {
    if (in[f]) out.push_back(f);
  }
  return out;
}

// Each group's id once: "group 'garden' is given twice".
void check_unique(const Scene& scene, const std::vector<FaceGroup>& groups, std::string_view how) {
  std::unordered_set<std::string_view> seen;
  for (const FaceGroup& group : groups) {
    if (!seen.insert(group.id).second) {
      throw InputError(scene.file, "",
                       "group '" + group.id + "' is given twice" + std::string(how));
    }
  }
}

}  // namespace

std::vector<std::size_t> faces_matching(const Scene& scene, const std::string& pattern) {
  const FacePattern compiled(pattern);
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    if (compiled.matches(scene.faces[f].id)) out.push_back(f);
  }
  return out;
}

std::vector<FaceGroup> scene_groups(const Scene& scene) {
  std::vector<FaceGroup> out;
  for (const FaceGroupSpec& spec : scene.groups) {
    std::vector<std::vector<std::size_t>> sets;
    for (const std::string& pattern : spec.patterns) {
      sets.push_back(faces_matching(scene, pattern));
      if (sets.back().empty()) {
        throw InputError(
            scene.file, "",
            "group '" + spec.id + "': the pattern '" + pattern + "' matches no face id");
      }
    }
    if (sets.empty()) throw InputError(scene.file, "", "group '" + spec.id + "' has no pattern");
    out.push_back({spec.id, union_of(std::move(sets), scene.faces.size())});
  }
  check_unique(scene, out, " in the scene's groups");
  return out;
}

std::optional<std::string> group_rule_problem(std::string_view rule) {
  std::string quoted = "'";
  quoted.append(rule).append("': ");
  if (rule.starts_with(kOriginPrefix) && origin_key(rule) == nullptr) {
    return quoted.append(
        "the origin keys are origin.format, origin.object, origin.group and origin.semantic "
        "(a face pattern beginning with 'origin.' is written 'origin\\.')");
  }
  if (rule.starts_with(kScenePrefix) && rule != kSceneGroups) {
    return quoted.append(
        "the scene's groups are scene.groups (a face pattern beginning with 'scene.' is written "
        "'scene\\.')");
  }
  if (const std::optional<std::string> why = FacePattern::problem(rule)) {
    return quoted.append(*why);
  }
  return std::nullopt;
}

std::vector<FaceGroup> groups_by(const Scene& scene, std::span<const std::string> rules) {
  std::vector<FaceGroup> out;
  std::unordered_set<std::string_view> given;
  for (const std::string& rule : rules) {
    if (const std::optional<std::string> why = group_rule_problem(rule)) {
      throw std::invalid_argument("--group-by " + *why);
    }
    if (!given.insert(rule).second) {
      throw std::invalid_argument("--group-by names '" + rule + "' twice");
    }
    if (rule == kSceneGroups) {
      if (scene.groups.empty()) {
        throw InputError(scene.file, "",
                         "--group-by scene.groups: the input has no groups (a scene's "
                         "\"groups\" key, kept in its database)");
      }
      for (FaceGroup& group : scene_groups(scene)) out.push_back(std::move(group));
      continue;
    }
    if (const OriginKey* key = origin_key(rule)) {
      for (FaceGroup& group : origin_groups(scene, *key, rule)) out.push_back(std::move(group));
      continue;
    }
    std::vector<std::size_t> faces = faces_matching(scene, rule);
    if (faces.empty()) {
      throw InputError(scene.file, "", "--group-by: the pattern '" + rule + "' matches no face id");
    }
    out.push_back({rule, std::move(faces)});
  }
  check_unique(scene, out, " by --group-by's rules");
  return out;
}

}  // namespace shadowgen::groups
