#pragma once

// The shadowed database's format in one home: its versions and the keys of its members,
// which the writer (shadowgen/output/database.h) and the reader (shadowgen/scene/
// database_reader.h) both spell from here. docs/scene-format.md ("Shadowed database")
// specifies them; lights, views and the site are written with the scene's own keys
// (shadowgen/scene/detail/json_entities.h).
//
// Layout (keys in this order when written; a reader warns about keys it does not know):
//
//   {
//     "format": "shadowgen-shadowed/2",
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
//         "vertex_rounding": r,                 a model's face only, where r > 0: its parts
//                                               are planar within 2r (Face::vertex_rounding)
//         "parts": [                            one polygon, or the triangles of a
//           POLYGON, ...                        non-planar one
//         ],
//         "numbers": [n, ...],                  /2: every coordinate of the face's lit
//         "vertices": [i, j, k, ...],           polygons and regions, each double once;
//                                               each vertex's x, y, z as indices into it
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
//   LIT, in /2 = [[v, ...], ...]: the outer loop, then the holes, each loop the indices
//         of its vertices in the face's "vertices"; on a face of several parts
//         {"part":k,"loops":[[v, ...], ...]}, k the index of the part whose plane it lies in
//   LIT, in /1 = POLYGON, with "part":k after "holes" on a face of several parts (without
//         the key, the nearest part's plane)
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
// three vertices. Numbers are written with a '.' or an exponent ("28.0", "-0.0", "1e-300"),
// each the shortest form that reads back to the same double; readers take integers too.
// A light keeps only the keys of its type (a directional light's position is not stored).

#include <optional>
#include <string_view>

namespace shadowgen::database {

// How a version writes the lit polygons and the sun-hours regions of a face.
enum class Layout {
  kInline,   // "shadowgen-shadowed/1": every polygon with its coordinates
  kIndexed,  // "shadowgen-shadowed/2": loops of indices into the face's shared vertices
};

inline constexpr std::string_view kInlineFormat = "shadowgen-shadowed/1";
inline constexpr std::string_view kIndexedFormat = "shadowgen-shadowed/2";
// What the writer writes.
inline constexpr std::string_view kWrittenFormat = kIndexedFormat;

// The layout a "format" value names; none for anything but a shadowed database's.
std::optional<Layout> layout_of(std::string_view format);

// Every member name of the format that is its own (the scene's entries keep the scene's).
namespace key {
// The top level, in the order written.
inline constexpr char kFormat[] = "format";
inline constexpr char kShard[] = "shard";
inline constexpr char kMethod[] = "method";
inline constexpr char kSite[] = "site";
inline constexpr char kLights[] = "lights";
inline constexpr char kViews[] = "views";
inline constexpr char kSunPaths[] = "sun_paths";
inline constexpr char kGroups[] = "groups";
inline constexpr char kFaces[] = "faces";
// "shard": {"index", "count"}; "method": {"name", "samples", "resolution"}.
inline constexpr char kShardIndex[] = "index";
inline constexpr char kShardCount[] = "count";
inline constexpr char kMethodName[] = "name";
inline constexpr char kSamples[] = "samples";
inline constexpr char kResolution[] = "resolution";
// A sun path's entry in "sun_paths" (and "id"): its values "kept" and "dropped".
inline constexpr char kId[] = "id";
inline constexpr char kStepMin[] = "step_min";
inline constexpr char kFrom[] = "from";
inline constexpr char kTo[] = "to";
inline constexpr char kInstantPolygons[] = "instant_polygons";
inline constexpr char kRegions[] = "regions";
inline constexpr char kKept[] = "kept";
inline constexpr char kDropped[] = "dropped";
// A face.
inline constexpr char kSourceFile[] = "source_file";
inline constexpr char kOrigin[] = "origin";
inline constexpr char kVertexRounding[] = "vertex_rounding";
inline constexpr char kParts[] = "parts";
inline constexpr char kNumbers[] = "numbers";
inline constexpr char kVertices[] = "vertices";
inline constexpr char kLit[] = "lit";
inline constexpr char kLitArea[] = "lit_area";  // a sampled method's, and a path's
inline constexpr char kSunHours[] = "sun_hours";
// A polygon: POLYGON's loops, and the part of a lit one; LIT's loops in /2.
inline constexpr char kOuter[] = "outer";
inline constexpr char kHoles[] = "holes";
inline constexpr char kPart[] = "part";
inline constexpr char kLoops[] = "loops";
// A face's sums over a path: "lit_area" above, then these.
inline constexpr char kPartLitArea[] = "part_lit_area";
inline constexpr char kHours[] = "hours";
inline constexpr char kPolygons[] = "polygons";
// A shard's sums: "nodes", and per node its parts' counts (a part's "part" above).
inline constexpr char kNodes[] = "nodes";
inline constexpr char kBlock[] = "block";
inline constexpr char kLevel[] = "level";
inline constexpr char kCounts[] = "counts";
inline constexpr char kCount[] = "count";
inline constexpr char kPieces[] = "pieces";
}  // namespace key

}  // namespace shadowgen::database
