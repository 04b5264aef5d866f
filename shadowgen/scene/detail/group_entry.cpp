#include "detail/group_entry.h"

#include <optional>
#include <string>

#include "detail/json_entities.h"
#include "shadowgen/groups/face_pattern.h"

namespace shadowgen::scene::detail {
namespace {

bool matches_some(const groups::FacePattern& pattern, const std::vector<Face>& faces) {
  for (const Face& face : faces) {
    if (pattern.matches(face.id)) return true;
  }
  return false;
}

}  // namespace

std::vector<FaceGroupSpec> read_groups(const JsonValue& value, const std::vector<Face>& faces) {
  const JsonArray list = value.array();
  std::vector<FaceGroupSpec> out;
  IdRegistry ids;
  for (std::size_t i = 0; i < list.size(); ++i) {
    JsonObject entry = list.at(i).object();
    FaceGroupSpec group;
    group.id = read_claimed_id(entry, ids, "group");
    const JsonValue patterns_value = entry.get("faces");
    const JsonArray patterns = patterns_value.array();
    if (patterns.empty()) patterns_value.fail("expected at least one face pattern");
    for (std::size_t k = 0; k < patterns.size(); ++k) {
      const JsonValue at = patterns.at(k);
      std::string text = at.string();
      if (const std::optional<std::string> why = groups::FacePattern::problem(text)) at.fail(*why);
      if (!matches_some(groups::FacePattern(text), faces)) {
        at.fail("the pattern '" + text + "' matches no face id");
      }
      group.patterns.push_back(std::move(text));
    }
    entry.finish();
    out.push_back(std::move(group));
  }
  return out;
}

}  // namespace shadowgen::scene::detail
