#pragma once

// Reading a shadowed database, `shadowgen-shadowed/1` (its layout: shadowgen/output/
// database.h), as strictly as a scene (docs/scene-format.md, "Reading rules"):
//
//   - the JSON rules of every input: paths in messages, unknown keys a warning naming the
//     key probably meant (an error under ReadOptions::strict), a key given twice an error;
//   - lights and views with the scene's checks (a zero direction, a range ending before it
//     starts, eye on target... are errors, not surprises for whoever reads the database);
//   - every face part with the checks a scene's face gets (shadowgen/scene/detail/
//     face_builder.h, strict): loops of 3 vertices or more, simple, holes inside, planar;
//     a part without area is kept, as the scene reader keeps it;
//   - the lit polygons of each (face, light) in the plane of their part, inside it, not
//     overlapping, their area not above the face's, all within stated rounding
//     (shadowgen/scene/detail/lit_checks.h);
//   - each sun path's instants (the lights whose sun names it) of its step, each at a
//     time on one of the path's steps from its "from" to its "to", after the one before
//     it; a path may have none (the sun down at every step).
//
// Every problem is an InputError naming the file, the face (when one is to blame), the
// JSON path and what is wrong.

#include <filesystem>
#include <string>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/scene/read_options.h"

namespace shadowgen {

// `path` names the file in messages. Warnings ("file: path: what" lines) are appended to
// `warnings`. read_database reads a file as it parses it, its faces one by one, so that
// it holds the shadowed scene and one face's document, never the whole text or document
// ("-": standard input, held whole). The members may come in any order: where one that
// the faces depend on (the format, shard, method, lights, views, sun paths) comes after
// "faces", the faces are read in a second parse, in the same memory.
ShadowedScene parse_database(const std::string& json_text, const std::filesystem::path& path,
                             const ReadOptions& options, std::vector<std::string>& warnings);
ShadowedScene read_database(const std::filesystem::path& path, const ReadOptions& options,
                            std::vector<std::string>& warnings);

// The same with the default options, the warnings dropped.
ShadowedScene parse_database(const std::string& json_text, const std::filesystem::path& path);
ShadowedScene read_database(const std::filesystem::path& path);

}  // namespace shadowgen
