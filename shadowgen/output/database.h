#pragma once

// The shadowed database, `shadowgen-shadowed/1` (JSON): the scene as read plus the lit
// detail polygons of every (face, light). Written and read back losslessly: every double
// is printed in the shortest form that reads back to the same value.
//
// Layout (keys in this order when written; a reader warns about keys it does not know):
//
//   {
//     "format": "shadowgen-shadowed/1",
//     "site": {"latitude_deg":51.48,"longitude_deg":0.0,     only where the scene has a
//              "elevation_m":45.0,"utc_offset_h":0.0,        site: every key, as the
//              "north_axis_deg":0.0},                        scene's "site" has them
//     "lights": [                               scene order, ids unique
//       {"id":"sun","type":"directional","direction":[x,y,z],"intensity":[r,g,b]},
//       {"id":"lamp","type":"point","position":[x,y,z],"intensity":[r,g,b],
//        "range":{"falloff_start":5.0,"end":20.0,"exponent":2.0}},   range optional
//       {"id":"day@2026-03-21T12:00","type":"directional",...,           a sun's instant
//        "sun":{"entry":"day","time":"2026-03-21T12:00","step_min":30,
//               "azimuth_deg":180.2,"elevation_deg":38.3}}
//     ],
//     "views": [                                scene order, ids unique
//       {"id":"main","eye":[x,y,z],"target":[x,y,z],"up":[x,y,z],"fov_deg":45.0}
//     ],
//     "sun_paths": [                            only with sun paths; their instants are
//       {"id":"day","step_min":30,              the lights whose sun's entry is the id
//        "from":"2026-03-21T00:00",             the entry's span
//        "to":"2026-03-21T23:59",
//        "instant_polygons":"dropped"}          or "kept": whether `lit` holds them
//     ],
//     "groups": [                               only with the scene's groups, in order
//       {"id":"garden","faces":["garden*","lawn/*"]}    face patterns, as the scene gives them
//     ],
//     "faces": [                                scene order, ids unique
//       {
//         "id": "wall",
//         "source_file": "scenes/room.json",    the file the face came from
//         "parts": [                            one polygon, or the triangles of a
//           POLYGON, ...                        non-planar one
//         ],
//         "lit": {                              by light id; a light whose lit region
//           "sun": [LIT, ...]                   on this face is empty is left out
//         },
//         "sun_hours": {                        with sun paths: by path id, every path
//           "day": {"lit_area": [a, ...],       per instant, in the path's order
//                   "part_lit_area": [[a, ...], ...],  per part, on a face of several
//                   "regions": [{"hours": 1.5, "polygons": [LIT, ...]}, ...]}
//         }                                     increasing hours, tiling the face
//       }
//     ]
//   }
//
//   POLYGON = {"outer":[[x,y,z],...],"holes":[[[x,y,z],...],...]}
//   LIT = POLYGON, with "part":k after "holes" on a face of several parts: the index of
//         the part whose plane it lies in (without the key, the nearest part's plane)
//
// A shard of a sun-path run (generate --instants K/N; ShadowedScene::shard) has
// "shard":{"index":K,"count":N} after "format", 1 <= K <= N. Its lit areas hold its own
// instants alone (shadows/sun_hours_tree.h says which), and its sums are the nodes of the
// path's tree it made, in place of "regions":
//           "nodes": [{"block":b,"level":l,"parts":[{"part":i,"counts":[
//                       {"count":c,"pieces":[{"outer":[[x,y],...],"holes":[...]}]}]}]}]
// the pieces in their part's exact plane chart (SunHoursPieces), increasing blocks. The
// lights that are no instant of a path are lit in shard 1 alone. Only `merge` reads it.
//
// All coordinates are the scene's, in 3D; a lit polygon lies in its face's plane and the
// lit polygons of one (face, light) cover exactly its lit region. Every loop has at least
// three vertices. Numbers are written with a '.' or an exponent ("28.0", "-0.0", "1e-300");
// readers take integers too. A light keeps only the keys of its type (a directional
// light's position is not stored). The writer puts one light, view or polygon per line.
// Reading, with the checks a database must pass: shadowgen/scene/database_reader.h.

#include <filesystem>
#include <string>

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

// Throws std::invalid_argument (naming the face or light) for what the format cannot
// hold: a non-finite number, a loop of fewer than three vertices, a face without parts,
// duplicate ids, or `lit` not shaped [face][light].
std::string database_json(const ShadowedScene& shadowed);

// Writes through a temporary file in the same folder and a rename: never a partial file.
// The text is streamed into it, never held whole.
void write_database(const ShadowedScene& shadowed, const std::filesystem::path& path);

}  // namespace shadowgen
