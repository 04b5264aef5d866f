#pragma once

// The entries a scene and a shadowed database share (docs/scene-format.md): ids, lights,
// views and polygons with holes, read with the same checks from either, so that a
// database is held to what a scene is. Each reader leaves the object's unknown keys to
// JsonObject::finish.

#include <string>
#include <unordered_map>

#include "hsr/polygon3.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::scene::detail {

// What a database holds that a scene may leave out: a scene's light may omit `intensity`
// and parts of `range`, a scene's view `up` and `fov_deg` (defaults in scene.h); a
// database written by shadowgen has them all, and one without them is damaged.
enum class Source { kScene, kDatabase };

// Ids unique within one namespace: "duplicate id 'x' (already used by polygon 'x')".
class IdRegistry {
 public:
  // `owner` says who holds `id`, for the message of a later clash. `at` is the id's value.
  void claim(const std::string& id, std::string owner, const JsonValue& at);
  // The same without a place to fail at: whether `id` was free (and is now `owner`'s).
  bool try_claim(const std::string& id, std::string owner);
  bool contains(const std::string& id) const { return owners_.count(id) > 0; }
  // Room for `more` ids besides those held, claimed without rehashing.
  void reserve_more(std::size_t more) { owners_.reserve(owners_.size() + more); }

 private:
  std::unordered_map<std::string, std::string> owners_;
};

// The entry's "id": a non-empty string.
std::string read_id(JsonObject& entry);

// The entry's id, claimed in `ids` for a `kind` ("light", "view"), and naming the entry in
// later messages: `lights[1] ('lamp')`.
std::string read_claimed_id(JsonObject& entry, IdRegistry& ids, const std::string& kind);

// A light's direction scaled by a power of two, which is exact, so that its largest
// component lies in [0.5, 1) (Light::direction). `v` is finite and not zero.
glm::dvec3 power_of_two_scaled(const glm::dvec3& v);

// lights[i]: its id claimed in `ids`; then named `light 'id'` in messages. In a scene, the
// direction of a directional light is scaled by a power of two into [0.5, 1)
// (Light::direction); a database's is kept as written.
Light read_light(const JsonValue& value, IdRegistry& ids, Source source);

// views[i], named `view 'id'` in messages.
ViewSpec read_view(const JsonValue& value, IdRegistry& ids, Source source);

// "outer" (a loop) and "holes" (optional, an array of loops), as given: the face checks
// are the caller's. Other keys are left for the caller to read or report.
hsr::Polygon3 read_polygon(JsonObject& object);

}  // namespace shadowgen::scene::detail
