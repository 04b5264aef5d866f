#include "shadowgen/viewer/viewer_page.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "shadowgen/output/atomic_file.h"

namespace shadowgen {
namespace {

bool holds_assets(const std::filesystem::path& folder) {
  std::error_code error;
  for (const std::string_view asset : kViewerAssets) {
    if (!std::filesystem::is_regular_file(folder / asset, error)) return false;
  }
  return true;
}

std::string read_asset(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || !text) throw std::runtime_error("cannot read '" + path.string() + "'");
  return std::move(text).str();
}

}  // namespace

std::filesystem::path viewer_assets_folder() {
  if (const char* set = std::getenv("SHADOWGEN_VIEWER_ASSETS"); set != nullptr && *set != '\0') {
    if (!holds_assets(set)) {
      throw std::runtime_error(std::string("SHADOWGEN_VIEWER_ASSETS: '") + set +
                               "' does not hold the viewer page's index.html and viewer.js");
    }
    return set;
  }
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path beside = executable.parent_path() / "viewer";
    if (holds_assets(beside)) return beside;
    const std::filesystem::path installed =
        executable.parent_path().parent_path() / "share" / "shadowgen" / "viewer";
    if (holds_assets(installed)) return installed;
  }
  throw std::runtime_error(
      "the viewer page's index.html and viewer.js are not beside the executable (viewer/) nor "
      "in ../share/shadowgen/viewer: the build makes them from web/ when node and the npm "
      "packages are installed (web/install.sh); SHADOWGEN_VIEWER_ASSETS may name their folder");
}

void write_viewer_page(const std::filesystem::path& dir, const std::filesystem::path& assets,
                       std::string_view model_script) {
  std::error_code error;
  if (std::filesystem::exists(dir, error) && !std::filesystem::is_directory(dir, error)) {
    throw std::runtime_error("cannot write the viewer page into '" + dir.string() +
                             "': not a folder");
  }
  std::filesystem::create_directory(dir, error);
  if (error) {
    throw std::runtime_error("cannot write the viewer page into '" + dir.string() +
                             "': " + error.message());
  }
  // Every text is read before any file is written; index.html, which loads the others, is
  // renamed into place last.
  const std::string script = read_asset(assets / "viewer.js");
  const std::string page = read_asset(assets / "index.html");
  write_files_atomically(
      {{dir / "viewer.js", script}, {dir / "model.js", model_script}, {dir / "index.html", page}});
}

}  // namespace shadowgen
