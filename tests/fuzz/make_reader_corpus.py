#!/usr/bin/env python3
"""Writes the reader fuzzer's seed corpus, tests/fuzz/corpus/readers/.

Each seed is one fuzzer input (reader_fuzzer.cpp): a header byte that selects the reader
(0 scene, 1 OBJ, 2 STL, 3 OFF, 4 PLY, 5 database; +6 for --strict, +12 to generate the
shadows of a tiny scene), then the content. A scene seed may carry one file after a NUL
byte: its name, a NUL byte, its bytes.

This script writes the seeds it can make on its own, named <kind>-<what>:
  - the example scenes (examples/scenes/*.json, chairs.json with its OBJ attached) and
    their mesh (examples/scenes/models/*);
  - every clipper regression (tests/clipper/regressions/*.wkt) as a scene: the subject
    under the clip and a sun straight above, shadows asked for;
  - small meshes of every format, well formed or not (ASCII and binary STL and PLY);
  - model files of other tools through a scene: an EnergyPlus IDF and epJSON, CityJSON
    and CityJSONSeq, glTF and binary glTF, and more of glTF (strips, fans, sparse and
    strided accessors, quantized positions, a mirrored node, a cut .glb, a node cycle);
  - databases: a few written here (sun paths among them: instants at one time, out of
    order or off the path's steps, a path with no instant, members after "faces"), a
    polar night's scene, databases in the indexed layout (shadowgen-shadowed/2: shared
    vertices, a face of two parts, regions, an index out of its table), and, with
    --shadowgen BIN, the databases BIN generates from examples/scenes/courtyard.json and
    garden.json (its sun path's regions) and shards 1 of 1 and 2 of 2 of a small sun path.
The seeds named <kind>-test-* and <kind>-cli-* hold the malformed inputs of the tables in
tests/shadowgen/scene/scene_reader_test.cpp and tests/cli/malformed_cli_test.cpp (each
scene with the mesh file it names attached); they were dumped from those tables once and
are kept as they are (this script leaves them alone), as are the seeds named <kind>-fuzz-*,
inputs the fuzzer found that once broke an invariant.

    make_reader_corpus.py [--shadowgen BIN]   write the seeds (other files are left alone)
    make_reader_corpus.py --check             exit 1 if a seed it writes is missing or
                                              differs (the database from BIN is not checked)
"""

import argparse
import base64
import json
import pathlib
import struct
import subprocess
import sys
import tempfile

SCENE, OBJ, STL, OFF, PLY, DATABASE = range(6)
STRICT = 6
GENERATE = 12

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "fuzz" / "corpus" / "readers"


def seed(kind, content, attachment=None):
    data = bytes([kind]) + (content.encode() if isinstance(content, str) else content)
    if attachment is not None:
        name, body = attachment
        data += b"\0" + name.encode() + b"\0" + (body.encode() if isinstance(body, str) else body)
    return data


def binary_stl(triangles, header=b"solid binary"):
    out = header.ljust(80, b" ") + struct.pack("<I", len(triangles))
    for t in triangles:
        out += struct.pack("<3f", 0, 0, 1) + struct.pack("<9f", *t) + b"\0\0"
    return out


def binary_ply(vertices, faces):
    head = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n"
        f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n"
    ).encode()
    body = b"".join(struct.pack("<3f", *v) for v in vertices)
    for f in faces:
        body += struct.pack("<B", len(f)) + struct.pack(f"<{len(f)}i", *f)
    return head + body


CUBE_OBJ = """# a unit cube, outward faces
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
"""

ASCII_STL = """solid thing
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 1 0 0
      vertex 0 1 0
    endloop
  endfacet
  FACET NORMAL 0 -1 0
    OUTER LOOP
      VERTEX 0 0 0
      VERTEX 1 0 0
      VERTEX 0 0 1.1
    ENDLOOP
  ENDFACET
endsolid thing
"""

ASCII_PLY = """ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 3
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
0 0 1
3 0 0 1
3 0 1 2
4 0 1 2 3
"""

DB_HEAD = """{"format": "shadowgen-shadowed/1", "views": [],
 "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1],
             "intensity": [1, 1, 1]}],
 "faces": ["""
DB_GOOD_FACE = """{"id": "good", "source_file": "s.json",
   "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}], "lit": {}}"""


def parse_wkt(text):
    """POLYGON or MULTIPOLYGON text as a list of polygons, each a list of rings (outer
    first), each a list of (x, y) strings, the closing repeat of the first point dropped."""
    text = text.strip()
    kind, _, body = text.partition("(")
    body = "(" + body
    depth, items, current = 0, [], []
    stack = [items]
    token = ""
    for c in body:
        if c == "(":
            new = []
            stack[-1].append(new)
            stack.append(new)
        elif c in ",)":
            if token.strip():
                stack[-1].append(tuple(token.split()))
            token = ""
            if c == ")":
                stack.pop()
        else:
            token += c
    geometry = items[0]
    polygons = geometry if kind.strip().upper() == "MULTIPOLYGON" else [geometry]
    return [[ring[:-1] if ring[0] == ring[-1] else ring for ring in polygon]
            for polygon in polygons]


def clip_regression_scene(path):
    """A clipper regression (tests/clipper/regressions/*.wkt: a subject and a clip) as a
    scene: the subject's polygons at z = 0 under the clip's at z = 1, and a sun straight
    above, so that the clip's shadow on the subject is that very clip."""
    geometries = [line for line in path.read_text().splitlines()
                  if line.strip() and not line.startswith("#")]
    faces = []
    for name, z, geometry in (("s", "0", geometries[0]), ("c", "1", geometries[1])):
        for i, polygon in enumerate(parse_wkt(geometry)):
            rings = []
            for k, ring in enumerate(polygon):
                twice_area = sum(float(a[0]) * float(b[1]) - float(b[0]) * float(a[1])
                                 for a, b in zip(ring, ring[1:] + ring[:1]))
                if (twice_area < 0) == (k == 0):  # outer counter-clockwise from above
                    ring = ring[::-1]
                rings.append("[" + ",".join(f"[{x},{y},{z}]" for x, y in ring) + "]")
            face = f'{{"id": "{name}{i}", "outer": {rings[0]}'
            if len(rings) > 1:
                face += ', "holes": [' + ", ".join(rings[1:]) + "]"
            faces.append(face + "}")
    return ('{"format": "shadowgen-scene/1",\n "polygons": [\n  ' + ",\n  ".join(faces) +
            '],\n "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]}\n')


def db_faces(face):
    return DB_HEAD + DB_GOOD_FACE + "," + face + "]}"


def seeds():
    out = {}
    # The examples.
    for scene in sorted((ROOT / "examples" / "scenes").glob("*.json")):
        text = scene.read_text()
        attachment = None
        if scene.name == "chairs.json":
            attachment = ("models/chair.obj", (ROOT / "examples/scenes/models/chair.obj").read_bytes())
        kind = SCENE + GENERATE if scene.stem == "courtyard" else SCENE
        out[f"scene-example-{scene.stem}"] = seed(kind, text, attachment)
    for model in sorted((ROOT / "examples" / "scenes" / "models").iterdir()):
        kind = {".obj": OBJ, ".stl": STL, ".off": OFF, ".ply": PLY}[model.suffix.lower()]
        out[f"{model.suffix[1:].lower()}-example-{model.stem}"] = seed(kind, model.read_bytes())

    # The clipper's regressions, as scenes whose shadows are those clips.
    for regression in sorted((ROOT / "tests" / "clipper" / "regressions").glob("*.wkt")):
        out[f"scene-clip-regression-{regression.stem}"] = seed(
            SCENE + GENERATE, clip_regression_scene(regression))

    # A scene with every kind of entry (the spec's example), its mesh attached.
    out["scene-spec-example"] = seed(SCENE + GENERATE, """{
  "format": "shadowgen-scene/1",
  "comment": "unknown keys are extensions",
  "polygons": [
    { "id": "wall", "outer": [[0,0,0],[10,0,0],[10,0,3],[0,0,3]],
      "holes": [ [[2,0,1],[2,0,2],[4,0,2],[4,0,1]] ] }
  ],
  "meshes": [
    { "id": "box", "file": "models/box.obj",
      "transform": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]] }
  ],
  "lights": [
    { "id": "sun",  "type": "directional", "direction": [-0.3, 0.2, -1.0] },
    { "id": "lamp", "type": "point", "position": [4, 5, 2.5], "intensity": [1, 0.5, 0.25],
      "range": { "falloff_start": 5.0, "end": 20.0, "exponent": 2 } }
  ],
  "views": [
    { "id": "main", "eye": [20, -15, 10], "target": [5, 5, 0], "up": [0, 0, 1], "fov_deg": 45 }
  ]
}""", ("models/box.obj", CUBE_OBJ))
    # Holes that share edges with their outer loop and each other: a door at the foot of a
    # wall, windows side by side, a window across a whole wall (its two coplanar parts).
    out["scene-holes-sharing-edges"] = seed(SCENE + GENERATE, """{"format": "shadowgen-scene/1",
 "polygons": [
  {"id": "front", "outer": [[0,0,0],[10,0,0],[10,0,3],[0,0,3]],
   "holes": [[[4,0,0],[5,0,0],[5,0,2],[4,0,2]], [[1,0,1],[2.5,0,1],[2.5,0,2],[1,0,2]],
             [[2.5,0,1],[3.5,0,1],[3.5,0,2],[2.5,0,2]], [[7,0,2],[9,0,2],[9,0,3],[7,0,3]]]},
  {"id": "back", "outer": [[0,1.5,0],[10,1.5,0],[10,1.5,3],[0,1.51,3]],
   "holes": [[[0,1.5,1],[10,1.5,1],[10,1.5,2],[0,1.5,2]]]},
  {"id": "ground", "outer": [[-2,-6,0],[12,-6,0],[12,6,0],[-2,6,0]]}],
 "lights": [{"id": "sun", "type": "directional", "direction": [0.375, 0.75, -0.625]},
            {"id": "lamp", "type": "point", "position": [5, -4, 2.5]}]}""")
    # Every mesh format through a scene, with a projective transform.
    for ext, body in (("obj", CUBE_OBJ), ("stl", ASCII_STL), ("ply", ASCII_PLY),
                      ("off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")):
        out[f"scene-mesh-{ext}-projective"] = seed(SCENE + GENERATE, """{"format": "shadowgen-scene/1",
 "polygons": [{"id": "ground", "outer": [[-5,-5,-1],[5,-5,-1],[5,5,-1],[-5,5,-1]]}],
 "meshes": [{"id": "m", "file": "m.%s",
             "transform": [[2,0,0,1],[0,2,0,0],[0,0,2,0],[0,0,0.1,1]]}],
 "lights": [{"id": "sun", "type": "directional", "direction": [0.2, 0.1, -1]}]}""" % ext,
                                                     (f"m.{ext}", body))
    out["scene-strict-non-planar"] = seed(SCENE + STRICT, """{"format": "shadowgen-scene/1",
 "polygons": [{"id": "bent", "outer": [[0,0,0],[1,0,0],[1,1,0.5],[0,1,0]]}], "lights": []}""")
    out["scene-non-planar-split"] = seed(SCENE + GENERATE, """{"format": "shadowgen-scene/1",
 "polygons": [{"id": "bent", "outer": [[0,0,0],[1,0,0],[1,1,0.5],[0,1,0]]},
              {"id": "floor", "outer": [[-2,-2,-1],[3,-2,-1],[3,3,-1],[-2,3,-1]],
               "holes": [[[0,0,-1],[0,1,-1],[1,1,-1],[1,0,-1]]]}],
 "lights": [{"id": "sun", "type": "directional", "direction": [0.3, 0.2, -1]},
            {"id": "lamp", "type": "point", "position": [0.5, 0.5, 2]}]}""")
    # A ground near the origin under an occluder with one vertex 1e14 away: the sun's view
    # once lost the ground's precision to the far vertex (a fuzzer finding).
    out["scene-far-vertex-elsewhere"] = seed(SCENE + GENERATE, """{"format": "shadowgen-scene/1",
 "polygons": [{"id": "ground", "outer": [[-8,-3,0],[-6,-8,0],[4,-8,0],[-5,-4,0]]},
              {"id": "spike", "outer": [[-7,-7,1],[-5,-4,1],[-899.9,9.8e13,1]]}],
 "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -0.5]}]}""")
    out["scene-extreme-coordinates"] = seed(SCENE, """{"format": "shadowgen-scene/1",
 "polygons": [{"id": "far", "outer": [[1e60,0,0],[1.0000000000000002e60,0,0],[1e60,1e50,0]]},
              {"id": "tiny", "outer": [[0,0,1e-300],[1e-100,0,1e-300],[0,1e-100,1e-300]]},
              {"id": "big", "outer": [[-1e70,-1e70,-5],[1e70,-1e70,-5],[1e70,1e70,-5]]}],
 "lights": [{"id": "sun", "type": "directional", "direction": [1e-300, 0, -1e-300]}],
 "views": [{"id": "v", "eye": [0, 0, 1e100], "target": [0, 0, 0], "up": [0, 1, 0],
            "fov_deg": 1e-10}]}""")

    # Meshes, one per format and a few broken ones.
    out["obj-cube"] = seed(OBJ + GENERATE, CUBE_OBJ)
    out["obj-negative-indices-and-slashes"] = seed(OBJ, """v 0 0 0
v 1 0 0 1
v 1 1 0
v 0 1 0
vt 0 0
vn 0 0 1
o thing
g group
s off
usemtl stone
f -4/1/1 -3//1 -2/1 -1
f 1 2 3 \\
4
l 1 2
""")
    out["obj-degenerate-and-pinched"] = seed(OBJ, "v 0 0 0\nv 2 0 0\nv 1 1 0\nv 2 2 0\nv 0 2 0\n"
                                               "f 1 2 3 4 5 3\nf 1 1 2\nf 1 2 2\n")
    out["obj-huge-coordinate"] = seed(OBJ, "v 1 2 1e999\nv 0 0 0\nv 1 0 0\nf 1 2 3\n")
    out["obj-exponents"] = seed(OBJ, "v 1e-320 0 0\nv 1e300 0 0\nv 0 -0x1p3 1.5E+2\nf 1 2 3\n")
    out["stl-ascii"] = seed(STL + GENERATE, ASCII_STL)
    out["stl-binary"] = seed(STL, binary_stl([(0, 0, 0, 1, 0, 0, 0, 1, 0),
                                              (0, 0, 0, 0, 0, 0, 1, 1, 1),
                                              (0, 0, 0, 0.5, 0, 0, 0.25, 0, 0)]))
    out["stl-binary-count-too-large"] = seed(STL, binary_stl([(0, 0, 0, 1, 0, 0, 0, 1, 0)])[:80]
                                             + struct.pack("<I", 1000)
                                             + binary_stl([(0, 0, 0, 1, 0, 0, 0, 1, 0)])[84:])
    out["stl-ascii-truncated"] = seed(STL, ASCII_STL[:120])
    out["off-square"] = seed(OFF + GENERATE, "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    out["off-tenth"] = seed(OFF, "OFF\n3 1 0\n0.1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    out["off-comments-and-colours"] = seed(OFF, "OFF # comment\n# a comment line\n\n4 2 5\n"
                                                "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                                                "3 0 1 2 255 0 0\n3 0 2 3 0.5 0.5 0.5 1\n")
    out["off-header-announces-more"] = seed(OFF, "OFF\n100 50 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    out["off-index-out-of-range"] = seed(OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
    out["ply-ascii"] = seed(PLY, ASCII_PLY)
    out["ply-binary"] = seed(PLY + GENERATE, binary_ply([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)],
                                             [(0, 1, 2), (0, 2, 3)]))
    out["ply-ascii-truncated"] = seed(PLY, ASCII_PLY[: ASCII_PLY.index("end_header") + 30])
    out["ply-double-coordinates"] = seed(PLY, """ply
format ascii 1.0
comment doubles and an extra property
element vertex 3
property double x
property double y
property double z
property uchar red
element face 1
property list uchar uint vertex_indices
end_header
0 0 0 255
1e30 0 0 0
0 1 0 7
3 0 1 2
""")

    # Databases.
    out["database-empty"] = seed(DATABASE, '{"format": "shadowgen-shadowed/1", "lights": [], '
                                           '"views": [], "faces": []}')
    out["database-lit"] = seed(DATABASE, """{"format": "shadowgen-shadowed/1",
 "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1], "intensity": [1, 1, 1]},
            {"id": "lamp", "type": "point", "position": [0, 0, 4], "intensity": [1, 0.5, 0],
             "range": {"falloff_start": 1, "end": 20, "exponent": 2}}],
 "views": [{"id": "main", "eye": [5, -5, 5], "target": [0, 0, 0], "up": [0, 0, 1], "fov_deg": 45}],
 "faces": [{"id": "floor", "source_file": "s.json",
   "parts": [{"outer": [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]],
              "holes": [[[1, 1, 0], [1, 2, 0], [2, 2, 0], [2, 1, 0]]]}],
   "lit": {"sun": [{"outer": [[0, 0, 0], [4, 0, 0], [4, 2, 0], [0, 2, 0]], "holes": [], "part": 0}],
           "lamp": [{"outer": [[0, 0, 0], [4, 0, 0], [4, 4, 0]], "holes": []}]},
   "colour": "ignored"}]}""")
    out["database-truncated"] = seed(DATABASE, "{")
    out["database-scene-format"] = seed(DATABASE, '{"format": "shadowgen-scene/1"}')
    out["database-bad-vertex"] = seed(DATABASE, db_faces("""{"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1]], "holes": []}], "lit": {}}"""))
    out["database-overflow"] = seed(DATABASE, db_faces("""{"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 1e400]], "holes": []}], "lit": {}}"""))
    out["database-unknown-light"] = seed(DATABASE, db_faces("""{"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}],
      "lit": {"moon": []}}"""))
    out["database-short-hole"] = seed(DATABASE, db_faces("""{"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}],
      "lit": {"sun": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": [[[0, 0, 0]]]}]}}"""))
    out["database-duplicate-face"] = seed(DATABASE, db_faces(DB_GOOD_FACE))
    # The indexed layout (shadowgen-shadowed/2): lit polygons and regions as loops of
    # indices into the face's shared vertices, a face of two parts naming each polygon's.
    out["database-indexed-lit"] = seed(DATABASE, """{"format": "shadowgen-shadowed/2",
 "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1], "intensity": [1, 1, 1]}],
 "views": [],
 "faces": [{"id": "floor", "source_file": "s.json",
   "parts": [{"outer": [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]], "holes": []}],
   "numbers": [0.0, 4.0, 2.0, -0.0], "vertices": [0,0,0, 1,0,0, 1,2,0, 0,2,3],
   "lit": {"sun": [[[0, 1, 2, 3]]]}},
  {"id": "bent", "source_file": "s.json",
   "parts": [{"outer": [[0, 0, 1], [1, 0, 1], [0, 1, 1.5]], "holes": []},
             {"outer": [[1, 0, 1], [1, 1, 1], [0, 1, 1.5]], "holes": []}],
   "numbers": [1.0, 0.0, 1.5], "vertices": [0,1,0, 0,0,0, 1,0,2],
   "lit": {"sun": [{"part": 1, "loops": [[0, 1, 2]]}]}}]}""")
    out["database-indexed-bad-index"] = seed(DATABASE, db_faces("""{"id": "w", "source_file": "s.json",
      "parts": [{"outer": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": []}],
      "numbers": [0.0, 1.0], "vertices": [0,0,0, 1,0,0, 0,1,0],
      "lit": {"sun": [[[0, 1, 3]]]}}""").replace("shadowgen-shadowed/1", "shadowgen-shadowed/2"))
    out["database-range-without-exponent"] = seed(DATABASE, """{"format": "shadowgen-shadowed/1",
 "views": [], "faces": [], "lights": [{"id": "lamp", "type": "point", "position": [0, 0, 1],
 "intensity": [1, 1, 1], "range": {"falloff_start": 1, "end": 2}}]}""")
    return out


def gltf_buffer(*pieces):
    """One buffer of `pieces` (bytes), each 4-byte aligned; their (offset, length)."""
    data, spans = b"", []
    for piece in pieces:
        data += b"\0" * (-len(data) % 4)
        spans.append((len(data), len(piece)))
        data += piece
    return data, spans


def gltf_json(members, data, spans, accessors, uri=None):
    """A glTF 2.0 document: `members` (scenes, nodes, meshes), one buffer of `data` (with
    `uri`, or none for a .glb's BIN chunk), a buffer view per span, the accessors."""
    buffer = {"byteLength": len(data)}
    if uri is not None:
        buffer["uri"] = uri
    document = {"asset": {"version": "2.0"}, **members, "buffers": [buffer],
                "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in spans],
                "accessors": accessors}
    return json.dumps(document)


def vec3_accessor(view, count, component=5126, **more):
    return {"bufferView": view, "componentType": component, "count": count, "type": "VEC3", **more}


def gltf_seeds():
    """glTF models through a scene (docs/gltf.md): a .glb of a ground and a tile placed by a
    rotated, mirrored node hierarchy; an embedded .gltf of strips, fans, a sparse and a
    strided accessor; quantized positions; and broken ones (cut short, a node cycle)."""
    scene = """{"format": "shadowgen-scene/1",
 "meshes": [{"id": "m", "file": "%s"}],
 "lights": [{"id": "sun", "type": "directional", "direction": [-0.3, 0.2, -1]},
            {"id": "lamp", "type": "point", "position": [0.5, 0.5, 3]}]}"""
    out = {}
    quad = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    ground = struct.pack("<12f", -2, 0, 2, 2, 0, 2, 2, 0, -2, -2, 0, -2)
    tile = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 0, -1, 0, 0, -1)
    data, spans = gltf_buffer(ground, tile, quad)
    accessors = [vec3_accessor(0, 4), vec3_accessor(1, 4),
                 {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]
    house = {"scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
             "nodes": [{"name": "ground", "mesh": 0},
                       {"name": "tile", "mesh": 1, "translation": [-1, 1, 1]},
                       {"name": "frame", "rotation": [0, 0.7071067811865476, 0, 0.7071067811865476],
                        "children": [3]},
                       {"name": "tile", "mesh": 1, "translation": [1, 0.5, 0], "scale": [-1, 1, 1]}],
             "meshes": [{"name": "plane", "primitives": [{"attributes": {"POSITION": 0}, "indices": 2}]},
                        {"name": "tile", "primitives": [{"attributes": {"POSITION": 1}, "indices": 2}]}]}
    whole = glb(gltf_json(house, data, spans, accessors), data)
    out["scene-gltf-glb-house"] = seed(SCENE + GENERATE, scene % "m.glb", ("m.glb", whole))
    out["scene-gltf-glb-cut-short"] = seed(SCENE, scene % "m.glb", ("m.glb", whole[:len(whole) - 20]))

    strip = struct.pack("<15f", 0, 1, 0, 0, 0, 0, 1, 1, 0, 1, 0, 0, 2, 1, 0)
    interleaved = struct.pack("<24f", 0, 0, 0, 0, 0, 1, 7, 7, 7, 0, 0, 1, 0, 1, 0, 0, 0, 1,
                              9, 9, 9, 0, 0, 1)
    data, spans = gltf_buffer(strip, interleaved, struct.pack("<2H", 1, 0), struct.pack("<3f", 1, 0, 0))
    spans_json = [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in spans]
    spans_json[1]["byteStride"] = 24
    accessors = [vec3_accessor(0, 5), vec3_accessor(1, 4, sparse={
        "count": 1, "indices": {"bufferView": 2, "componentType": 5123}, "values": {"bufferView": 3}})]
    members = {"scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "matrix": [
                   0, 0, 2, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0.5, 0.5, 0.5, 1]}],
               "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 5},
                                          {"attributes": {"POSITION": 0}, "mode": 6},
                                          {"attributes": {"POSITION": 1}, "mode": 5}]}]}
    document = json.loads(gltf_json(members, data, [], accessors,
                                    "data:application/octet-stream;base64," +
                                    base64.b64encode(data).decode()))
    document["bufferViews"] = spans_json
    out["scene-gltf-embedded-strips"] = seed(SCENE + GENERATE, scene % "m.gltf",
                                             ("m.gltf", json.dumps(document)))

    data, spans = gltf_buffer(struct.pack("<9H", 0, 0, 0, 65535, 0, 0, 0, 65535, 0))
    members = {"extensionsUsed": ["KHR_mesh_quantization"],
               "extensionsRequired": ["KHR_mesh_quantization"],
               "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "scale": [2, 2, 2]}],
               "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}]}
    text = gltf_json(members, data, spans, [vec3_accessor(0, 3, 5123, normalized=True)],
                     "data:application/gltf-buffer;base64," + base64.b64encode(data).decode())
    out["scene-gltf-quantized"] = seed(SCENE + GENERATE, scene % "m.gltf", ("m.gltf", text))

    data, spans = gltf_buffer(tile)
    members = {"scenes": [{"nodes": [0]}], "nodes": [{"children": [1]}, {"children": [0], "mesh": 0}],
               "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}]}
    text = gltf_json(members, data, spans, [vec3_accessor(0, 3)],
                     "data:application/octet-stream;base64," + base64.b64encode(data).decode())
    out["scene-gltf-node-cycle"] = seed(SCENE, scene % "m.gltf", ("m.gltf", text))

    # What the reader passes over: a skin, an animation, morph targets, a camera, a light,
    # a material with a texture whose image lies in a buffer view (not a picture).
    data, spans = gltf_buffer(struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0), b"\x89PNG junk",
                              struct.pack("<2f", 0, 1), struct.pack("<8f", 0, 0, 0, 1, 0, 0.7071, 0, 0.7071),
                              struct.pack("<16f", 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1))
    members = {
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_unlit"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}},
        "scene": 0, "scenes": [{"nodes": [0, 2]}],
        "nodes": [{"name": "body", "mesh": 0, "skin": 0, "children": [1]},
                  {"name": "joint", "rotation": [0, 0, 0, 1]},
                  {"name": "eye", "camera": 0, "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}],
        "skins": [{"joints": [1], "inverseBindMatrices": 3}],
        "animations": [{"channels": [{"sampler": 0, "target": {"node": 1, "path": "rotation"}}],
                        "samplers": [{"input": 1, "output": 2}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
                       "extensions": {"KHR_materials_unlit": {}}}],
        "textures": [{"source": 0}],
        "images": [{"bufferView": 1, "mimeType": "image/png"}, {"uri": "missing.png"}],
        "meshes": [{"name": "m", "weights": [0.5], "primitives": [
            {"attributes": {"POSITION": 0}, "material": 0, "targets": [{"POSITION": 0}]}]}]}
    accessors = [vec3_accessor(0, 3),
                 {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR"},
                 {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC4"},
                 {"bufferView": 4, "componentType": 5126, "count": 1, "type": "MAT4"}]
    out["scene-gltf-glb-passed-over"] = seed(
        SCENE + GENERATE, scene % "m.glb", ("m.glb", glb(gltf_json(members, data, spans, accessors), data)))
    return out


def sun_path_db(times=("10:00", "11:00", "12:00", "13:00"), order=None, method=False, shard=False):
    """A database of face "g" (4 x 1) and sun path "p" summed into lit areas alone
    (generate --areas-only), its instants p@0, p@1, ... at `times` on 21 March 2026 (none:
    the sun down at every step), the path's span 10:00 to 13:00 every 30 minutes. `method`
    makes it a rays run's, `shard` shard 1 of 1; `order` lists the members in the order
    to write them (JSON objects are unordered)."""
    lights = [{"id": f"p@{k}", "type": "directional", "direction": [0.0, 0.5, -0.5],
               "intensity": [1.0, 1.0, 1.0],
               "sun": {"entry": "p", "time": f"2026-03-21T{t}", "step_min": 30,
                       "azimuth_deg": 180.0, "elevation_deg": 30.0}}
              for k, t in enumerate(times)]
    face = {"id": "g", "source_file": "s.json",
            "parts": [{"outer": [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [4.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
                       "holes": []}]}
    if method:
        face["lit_area"] = {}
    else:
        face["lit"] = {}
    face["sun_hours"] = {"p": {"lit_area": [3.0, 3.0, 2.0, 1.0][:len(times)]}}
    members = {"format": "shadowgen-shadowed/1"}
    if shard:
        members["shard"] = {"index": 1, "count": 1}
    if method:
        members["method"] = {"name": "rays", "samples": 64}
    members.update({
        "lights": lights, "views": [],
        "sun_paths": [{"id": "p", "step_min": 30, "from": "2026-03-21T10:00",
                       "to": "2026-03-21T13:00", "instant_polygons": "dropped",
                       "regions": "dropped"}],
        "faces": [face]})
    if order is not None:
        members = {key: members[key] for key in order if key in members}
    return seed(DATABASE, json.dumps(members, indent=1))


# A tiny yard at Tromsø (69.65 N) on 21 December, hourly: the sun is down at every step (a
# polar night, a path with no instant); its shadows asked for.
POLAR_NIGHT_SCENE = """{"format": "shadowgen-scene/1",
 "polygons": [{"id": "yard", "outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]]},
              {"id": "wall", "outer": [[0,-0.5,0],[4,-0.5,0],[4,-0.5,2],[0,-0.5,2]]}],
 "site": {"latitude_deg": 69.65, "longitude_deg": 18.96, "utc_offset_h": 1},
 "lights": [{"id": "dec21", "type": "sun", "from": "2026-12-21T00:00", "to": "2026-12-21T23:00",
             "step_min": 60},
            {"id": "lamp", "type": "point", "position": [2, 2, 3]}]}
"""


# sun_path_db's face with its sun-hours regions kept, in the indexed layout: four strips
# 1 x 1 lit at none, three (two strips) and four of the instants, sharing their sides.
INDEXED_REGIONS_DB = """{"format": "shadowgen-shadowed/2",
 "lights": [{"id": "p@0", "type": "directional", "direction": [0.0, 0.5, -0.5], "intensity": [1.0, 1.0, 1.0],
             "sun": {"entry": "p", "time": "2026-03-21T10:00", "step_min": 30, "azimuth_deg": 180.0, "elevation_deg": 30.0}},
            {"id": "p@1", "type": "directional", "direction": [0.0, 0.5, -0.5], "intensity": [1.0, 1.0, 1.0],
             "sun": {"entry": "p", "time": "2026-03-21T11:00", "step_min": 30, "azimuth_deg": 180.0, "elevation_deg": 30.0}},
            {"id": "p@2", "type": "directional", "direction": [0.0, 0.5, -0.5], "intensity": [1.0, 1.0, 1.0],
             "sun": {"entry": "p", "time": "2026-03-21T12:00", "step_min": 30, "azimuth_deg": 180.0, "elevation_deg": 30.0}},
            {"id": "p@3", "type": "directional", "direction": [0.0, 0.5, -0.5], "intensity": [1.0, 1.0, 1.0],
             "sun": {"entry": "p", "time": "2026-03-21T13:00", "step_min": 30, "azimuth_deg": 180.0, "elevation_deg": 30.0}}],
 "views": [],
 "sun_paths": [{"id": "p", "step_min": 30, "from": "2026-03-21T10:00", "to": "2026-03-21T13:00",
                "instant_polygons": "dropped"}],
 "faces": [{"id": "g", "source_file": "s.json",
   "parts": [{"outer": [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [4.0, 1.0, 0.0], [0.0, 1.0, 0.0]], "holes": []}],
   "numbers": [0.0, 1.0, 2.0, 3.0, 4.0],
   "vertices": [0,0,0, 1,0,0, 1,1,0, 0,1,0, 2,0,0, 2,1,0, 3,0,0, 3,1,0, 4,0,0, 4,1,0],
   "lit": {},
   "sun_hours": {"p": {"lit_area": [3.0, 3.0, 3.0, 1.0],
     "regions": [{"hours": 0.0, "polygons": [[[0, 1, 2, 3]]]},
                 {"hours": 1.5, "polygons": [[[1, 4, 5, 2]], [[4, 6, 7, 5]]]},
                 {"hours": 2.0, "polygons": [[[6, 8, 9, 7]]]}]}}}]}"""


def sun_path_seeds():
    """Databases with sun paths: valid, their instants at one time, out of order or off the
    path's steps, a path with no instant, and members after "faces"."""
    late = ["format", "views", "faces", "lights", "sun_paths", "method", "shard"]
    return {
        "database-sun-path": sun_path_db(),
        "database-sun-path-instants-repeated": sun_path_db(times=("10:00", "11:00", "11:00", "13:00")),
        "database-sun-path-instants-out-of-order":
            sun_path_db(times=("10:00", "12:30", "12:00", "13:00")),
        "database-sun-path-instant-off-step": sun_path_db(times=("10:00", "11:10", "12:00", "13:00")),
        "database-sun-path-polar-night": sun_path_db(times=()),
        "database-lights-after-faces": sun_path_db(order=late),
        "database-method-after-faces": sun_path_db(method=True, order=late),
        "database-shard-after-faces": sun_path_db(shard=True, order=late),
        "database-indexed-sun-path-regions": seed(DATABASE, INDEXED_REGIONS_DB),
        "scene-sun-path-polar-night": seed(SCENE + GENERATE, POLAR_NIGHT_SCENE),
    }


# Model files of other tools, written from their specifications: an EnergyPlus IDF and
# epJSON (Input Output Reference), CityJSON 2.0 and CityJSONSeq, glTF 2.0 (.gltf with a
# data URI buffer, .glb). Each through a scene with a sun at noon, shadows asked for.
IDF = """!- A room with a window, written for the fuzzer from the Input Output Reference.
Version,23.2;
Site:Location,Delft,52.0,4.36,1,0;
Building,House,30,Suburbs,0.04,0.4,FullExterior,25,6;
GlobalGeometryRules,UpperLeftCorner,Counterclockwise,Relative;
Zone,Room,10,5,0,0,  !- relative north 10, origin (5, 0, 0)
  1,1,autocalculate,autocalculate;
BuildingSurface:Detailed,Wall South,Wall,Ext,Room,,Outdoors,,SunExposed,WindExposed,
  autocalculate,4,0,0,3,0,0,0,10,0,0,10,0,3;
BuildingSurface:Detailed,Roof,Roof,Ext,Room,,Outdoors,,SunExposed,WindExposed,
  autocalculate,4,0,6,3,0,0,3,10,0,3,10,6,3;
FenestrationSurface:Detailed,Window South,Window,Glz,Wall South,,autocalculate,,1,4,
  2,0,2,2,0,1,4,0,1,4,0,2;
Wall:Exterior,Wall East,Ext,Room,,90,90,10,0,0,6,3;
Shading:Overhang,Ledge,Window South,0.2,90,0.4,0.4,0.5;
Shading:Site:Detailed,Fence,,4,-2,-3,2,-2,-3,0,12,-3,0,12,-3,2;
"""

EPJSON = """{"Version": {"Version 1": {"version_identifier": "23.2"}},
 "Site:Location": {"Delft": {"latitude": 52.0, "longitude": 4.36, "time_zone": 1, "elevation": 0}},
 "GlobalGeometryRules": {"GlobalGeometryRules 1": {"starting_vertex_position": "UpperLeftCorner",
   "vertex_entry_direction": "Counterclockwise", "coordinate_system": "Relative"}},
 "Zone": {"Room": {"direction_of_relative_north": 0, "x_origin": 0, "y_origin": 0, "z_origin": 0}},
 "BuildingSurface:Detailed": {"Wall South": {"surface_type": "Wall", "construction_name": "Ext",
   "zone_name": "Room", "outside_boundary_condition": "Outdoors", "sun_exposure": "SunExposed",
   "wind_exposure": "WindExposed", "number_of_vertices": 4,
   "vertices": [{"vertex_x_coordinate": 0, "vertex_y_coordinate": 0, "vertex_z_coordinate": 3},
                {"vertex_x_coordinate": 0, "vertex_y_coordinate": 0, "vertex_z_coordinate": 0},
                {"vertex_x_coordinate": 10, "vertex_y_coordinate": 0, "vertex_z_coordinate": 0},
                {"vertex_x_coordinate": 10, "vertex_y_coordinate": 0, "vertex_z_coordinate": 3}]}},
 "FenestrationSurface:Detailed": {"Door": {"surface_type": "Door", "construction_name": "Wood",
   "building_surface_name": "Wall South", "number_of_vertices": 4,
   "vertex_1_x_coordinate": 6, "vertex_1_y_coordinate": 0, "vertex_1_z_coordinate": 2,
   "vertex_2_x_coordinate": 6, "vertex_2_y_coordinate": 0, "vertex_2_z_coordinate": 0,
   "vertex_3_x_coordinate": 7, "vertex_3_y_coordinate": 0, "vertex_3_z_coordinate": 0,
   "vertex_4_x_coordinate": 7, "vertex_4_y_coordinate": 0, "vertex_4_z_coordinate": 2}}}
"""

# A 10 m box at millimetre precision in RD New + NAP, one of its walls with a window hole.
CITYJSON_OBJECTS = """{"b1": {"type": "Building", "children": ["b1-p"], "attributes": {"name": "box"}},
  "b1-p": {"type": "BuildingPart", "parents": ["b1"], "geometry": [
   {"type": "Solid", "lod": "1.2", "boundaries": [[[[0,3,2,1]],[[4,5,6,7]],[[0,1,5,4],[8,9,10,11]],
     [[1,2,6,5]],[[2,3,7,6]],[[3,0,4,7]]]],
    "semantics": {"surfaces": [{"type": "GroundSurface"}, {"type": "RoofSurface"},
                               {"type": "WallSurface"}], "values": [[0,1,2,2,2,2]]}}]}}"""
CITYJSON_VERTICES = """[[0,0,0],[10000,0,0],[10000,10000,0],[0,10000,0],
  [0,0,6000],[10000,0,6000],[10000,10000,6000],[0,10000,6000],
  [2000,0,1000],[2000,0,2000],[4000,0,2000],[4000,0,1000]]"""
CITYJSON_HEAD = """"version": "2.0",
 "transform": {"scale": [0.001, 0.001, 0.001], "translate": [85000.0, 447000.0, 0.0]},
 "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"}"""
CITYJSON = ('{"type": "CityJSON", ' + CITYJSON_HEAD + ',\n "CityObjects": ' + CITYJSON_OBJECTS +
            ',\n "vertices": ' + CITYJSON_VERTICES + '}\n')
CITYJSON_SEQ = ('{"type": "CityJSON", ' + CITYJSON_HEAD.replace("\n", "") +
                ', "CityObjects": {}, "vertices": []}\n' +
                '{"type": "CityJSONFeature", "id": "b1", "CityObjects": ' +
                CITYJSON_OBJECTS.replace("\n", "") + ', "vertices": ' +
                CITYJSON_VERTICES.replace("\n", "") + '}\n')


def gltf_parts():
    """A unit square as two indexed triangles under a node turned and moved, as the JSON
    and the binary buffer of a glTF file."""
    positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 0, -1, 0, 0, -1)
    indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    buffer = positions + indices
    document = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "roof", "mesh": 0, "translation": [0, 3, 0],
                   "rotation": [0, 0.38268343, 0, 0.92387953]}],
        "meshes": [{"name": "roof", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [0, 0, -1], "max": [1, 0, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
        "buffers": [{"byteLength": len(buffer)}],
    }
    return document, buffer


def gltf_text():
    document, buffer = gltf_parts()
    document["buffers"][0]["uri"] = ("data:application/octet-stream;base64," +
                                     base64.b64encode(buffer).decode())
    return json.dumps(document)


def glb(text, buffer):
    """A binary glTF file of JSON `text` and the BIN chunk `buffer`, each padded."""
    text = text.encode() + b" " * (-len(text) % 4)
    buffer += b"\0" * (-len(buffer) % 4)
    chunks = (struct.pack("<II", len(text), 0x4E4F534A) + text +
              struct.pack("<II", len(buffer), 0x004E4942) + buffer)
    return struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks


def glb_bytes():
    document, buffer = gltf_parts()
    return glb(json.dumps(document), buffer)


def model_scene(file, site=""):
    return """{"format": "shadowgen-scene/1",
 "polygons": [{"id": "ground", "outer": [[-20,-20,0],[40,-20,0],[40,40,0],[-20,40,0]]}],
 "meshes": [{"id": "m", "file": "%s"}],%s
 "lights": [{"id": "noon", "type": "sun", "time": "2026-06-21T13:00"}]}""" % (file, site)


def model_seeds():
    utc = '\n "site": {"utc_offset_h": 1},'
    cityjson_scene = model_scene("m.city.json", utc)
    return {
        "scene-model-idf": seed(SCENE + GENERATE, model_scene("m.idf"), ("m.idf", IDF)),
        "scene-model-epjson": seed(SCENE + GENERATE, model_scene("m.epJSON"), ("m.epJSON", EPJSON)),
        "scene-model-cityjson": seed(SCENE + GENERATE, cityjson_scene, ("m.city.json", CITYJSON)),
        "scene-model-cityjson-lod": seed(
            SCENE, cityjson_scene.replace('"file": "m.city.json"', '"file": "m.city.json", "lod": "1.2"'),
            ("m.city.json", CITYJSON)),
        "scene-model-cityjsonseq": seed(SCENE + GENERATE, model_scene("m.city.jsonl", utc),
                                        ("m.city.jsonl", CITYJSON_SEQ)),
        "scene-model-gltf": seed(SCENE + GENERATE,
                                 model_scene("m.gltf", '\n "site": {"latitude_deg": 52, '
                                             '"longitude_deg": 4.4, "utc_offset_h": 1},'),
                                 ("m.gltf", gltf_text())),
        "scene-model-glb": seed(SCENE + GENERATE,
                                model_scene("m.glb", '\n "site": {"latitude_deg": 52, '
                                            '"longitude_deg": 4.4, "utc_offset_h": 1},'),
                                ("m.glb", glb_bytes())),
    }


def database_from_cli(shadowgen, scene="examples/scenes/courtyard.json"):
    with tempfile.TemporaryDirectory() as work:
        target = pathlib.Path(work) / "shadowed.json"
        # From the root, so that the database names its source file as the repository does.
        subprocess.run([str(pathlib.Path(shadowgen).resolve()), "generate",
                        scene, "-o", str(target), "--quiet"],
                       check=True, cwd=ROOT)
        return seed(DATABASE, target.read_bytes())


# A post on a patio at Greenwich, 21 March 10:00 to 14:00 every 10 minutes (25 instants,
# two blocks of the path's tree): small enough that its shards stay seeds of a few KiB.
SHARD_SCENE = """{"format": "shadowgen-scene/1",
 "polygons": [{"id": "patio", "outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]]},
              {"id": "post", "outer": [[1,2,0],[2,2,0],[2,2,2],[1,2,2]]}],
 "site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "utc_offset_h": 0},
 "lights": [{"id": "noon", "type": "sun", "from": "2026-03-21T10:00", "to": "2026-03-21T14:00",
             "step_min": 10}]}
"""


def shards_from_cli(shadowgen):
    out = {}
    with tempfile.TemporaryDirectory() as work:
        scene = pathlib.Path(work) / "patio.json"
        scene.write_text(SHARD_SCENE)
        for share in ("1/1", "2/2"):
            target = pathlib.Path(work) / "shard.json"
            subprocess.run([str(pathlib.Path(shadowgen).resolve()), "generate", str(scene),
                            "-o", str(target), "--instants", share, "--quiet"], check=True)
            name = "database-shard-" + share.replace("/", "-of-")
            out[name] = seed(DATABASE, target.read_bytes())
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--shadowgen", help="the shadowgen executable, for the database seed")
    args = parser.parse_args()
    wanted = seeds()
    wanted.update(sun_path_seeds())
    wanted.update(model_seeds())
    wanted.update(gltf_seeds())
    if args.check:
        stale = [n for n, d in wanted.items()
                 if not (CORPUS / n).is_file() or (CORPUS / n).read_bytes() != d]
        for name in stale:
            print(f"stale or missing: {CORPUS / name}", file=sys.stderr)
        return 1 if stale else 0
    if args.shadowgen:
        wanted["database-example-courtyard"] = database_from_cli(args.shadowgen)
        wanted["database-example-garden-sun-path"] = database_from_cli(
            args.shadowgen, "examples/scenes/garden.json")
        wanted.update(shards_from_cli(args.shadowgen))
    CORPUS.mkdir(parents=True, exist_ok=True)
    for name, data in wanted.items():
        (CORPUS / name).write_bytes(data)
    print(f"wrote {len(wanted)} seeds to {CORPUS}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
