#include "detail/referenced_file.h"

#include <optional>
#include <system_error>

#include "shadowgen/json/document.h"

namespace shadowgen::scene::detail {

std::filesystem::path referenced_file(const JsonValue& value,
                                      const std::filesystem::path& scene_path,
                                      const std::string& what) {
  const std::string name = value.string();
  if (name.empty()) value.fail("the file name is empty");
  const std::filesystem::path path = (scene_path.parent_path() / name).lexically_normal();
  const std::string looked_for = " (looked for '" + path.string() + "')";
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    value.fail(what + " '" + name + "' not found" + looked_for);
  }
  if (const std::optional<std::string> why = unreadable_input(path)) {
    value.fail(what + " '" + name + "' " + *why + looked_for);
  }
  return path;
}

}  // namespace shadowgen::scene::detail
