#pragma once

// The viewer page `shadowgen view DB -o DIR` writes: a static folder that a browser opens
// from the file system, with no network:
//
//   DIR/index.html   the page: the view, the legend with a toggle per group and per light,
//                    the north arrow, the hover box (web/viewer/index.html)
//   DIR/viewer.js    the page's script bundled with three.js, its OrbitControls and
//                    GLTFLoader into one classic script (web/viewer/viewer.js, bundled by
//                    esbuild at build time)
//   DIR/model.js     the shadowed scene (viewer_model.h)
//
// index.html and viewer.js are the page's assets, made by the build and copied from where
// the executable finds them (viewer_assets_folder); model.js is written for each database.

#include <filesystem>
#include <string_view>

namespace shadowgen {

// The names of the page's assets, copied as they are.
inline constexpr std::string_view kViewerAssets[] = {"viewer.js", "index.html"};

// Where the page's assets are: $SHADOWGEN_VIEWER_ASSETS where set; else `viewer/` beside
// the running executable (where the build puts them); else `../share/shadowgen/viewer`
// from it (where an installation puts them). Throws std::runtime_error, saying where it
// looked and how the assets are made, when none of these holds both assets.
std::filesystem::path viewer_assets_folder();

// Writes the page into `dir`, made if missing (its parent must exist): the assets from
// `assets`, then model.js holding `model_script`, each file through a temporary file and a
// rename (shadowgen/output/atomic_file.h). Other files in `dir` are left alone. Throws
// std::runtime_error naming the path that cannot be read or written.
void write_viewer_page(const std::filesystem::path& dir, const std::filesystem::path& assets,
                       std::string_view model_script);

}  // namespace shadowgen
