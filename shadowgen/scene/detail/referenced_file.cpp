#include "detail/referenced_file.h"

#include <system_error>

namespace shadowgen::detail {

std::filesystem::path referenced_file(const JsonValue& value,
                                      const std::filesystem::path& scene_path,
                                      const std::string& what) {
  const std::string name = value.string();
  if (name.empty()) value.fail("the file name is empty");
  const std::filesystem::path path = (scene_path.parent_path() / name).lexically_normal();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    value.fail(what + " '" + name + "' not found (looked for '" + path.string() + "')");
  }
  return path;
}

}  // namespace shadowgen::detail
