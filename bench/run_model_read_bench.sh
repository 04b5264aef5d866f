#!/usr/bin/env bash
# Reading one district in every format a scene's meshes[] takes, through the command
# line: a grid of box buildings (a roof and four walls each, 10 m apart, 6 m tall, at
# real projected coordinates near (85000, 447000)) written by this script as a scene's
# own polygons, an OBJ mesh, a binary glTF (each face two triangles), a CityJSON file (a
# Solid per building, millimetre transform), a CityJSONSeq file and an EnergyPlus IDF
# (a Shading:Site:Detailed per face, four decimals). Each is read by `shadowgen generate
# SCENE` with no light (reading and building the faces, then writing them as a database:
# nothing generated), the formats in turn, REPETITIONS times: each run's wall time and
# peak resident memory, and the medians.
#
#   bench/run_model_read_bench.sh [BUILDINGS]
#
# Default: 20000 buildings (100,000 faces; the glTF's 200,000 triangles). BUILD_DIR
# (default build/release) must hold cli/shadowgen. REPETITIONS (default 3).
set -euo pipefail

buildings=${1:-20000}
build=${BUILD_DIR:-build/release}
repetitions=${REPETITIONS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$buildings" "$work" <<'PY'
import json, math, struct, sys
n, work = int(sys.argv[1]), sys.argv[2]
side = math.ceil(math.sqrt(n))
x0, y0 = 85000.0, 447000.0
boxes = [(x0 + 10 * (k % side), y0 + 10 * (k // side)) for k in range(n)]

def faces(x, y):
    a, b, h = 6.0, 6.0, 6.0
    c = [(x, y), (x + a, y), (x + a, y + b), (x, y + b)]
    out = [[(px, py, h) for px, py in c]]  # roof, counter-clockwise from above
    for i in range(4):
        (p, q), (r, s) = c[i], c[(i + 1) % 4]
        out.append([(p, q, 0), (r, s, 0), (r, s, h), (p, q, h)])  # wall, outward
    return out

polygons = []
for k, (x, y) in enumerate(boxes):
    for j, f in enumerate(faces(x, y)):
        polygons.append({"id": "b%d.%d" % (k, j), "outer": [list(p) for p in f]})

def scene(name, entry):
    body = {"format": "shadowgen-scene/1", "polygons": [], "meshes": [entry], "lights": []}
    json.dump(body, open("%s/%s.json" % (work, name), "w"))

json.dump({"format": "shadowgen-scene/1", "polygons": polygons, "lights": []},
          open(work + "/polygons.json", "w"))

with open(work + "/city.obj", "w") as obj:
    v = 0
    for k, (x, y) in enumerate(boxes):
        for f in faces(x, y):
            for p in f:
                obj.write("v %.4f %.4f %.4f\n" % p)
            obj.write("f %s\n" % " ".join(str(v + i + 1) for i in range(4)))
            v += 4
scene("obj", {"id": "m", "file": "city.obj"})

# glTF: +y up, (x, y, z) -> (x, z, -y), positions relative to the node's translation.
pos, idx = [], []
for k, (x, y) in enumerate(boxes):
    for f in faces(x, y):
        base = len(pos) // 3
        for px, py, pz in f:
            pos += [px - x0, pz, -(py - y0)]
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
pb = struct.pack("<%df" % len(pos), *pos)
ib = struct.pack("<%dI" % len(idx), *idx)
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
       "nodes": [{"name": "city", "mesh": 0, "translation": [x0, 0, -y0]}],
       "meshes": [{"name": "city", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
       "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(pos) // 3, "type": "VEC3",
                      "min": [min(pos[0::3]), min(pos[1::3]), min(pos[2::3])],
                      "max": [max(pos[0::3]), max(pos[1::3]), max(pos[2::3])]},
                     {"bufferView": 1, "componentType": 5125, "count": len(idx), "type": "SCALAR"}],
       "bufferViews": [{"buffer": 0, "byteLength": len(pb)},
                       {"buffer": 0, "byteOffset": len(pb), "byteLength": len(ib)}],
       "buffers": [{"byteLength": len(pb) + len(ib)}]}
text = json.dumps(doc).encode()
text += b" " * (-len(text) % 4)
chunks = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(pb) + len(ib), 0x004E4942) + pb + ib
open(work + "/city.glb", "wb").write(struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks)
scene("gltf", {"id": "m", "file": "city.glb"})

# CityJSON 2.0: a Solid per building; vertices in millimetres from the translate.
head = {"type": "CityJSON", "version": "2.0",
        "transform": {"scale": [0.001, 0.001, 0.001], "translate": [x0, y0, 0.0]},
        "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"}}
def solid(x, y, base):
    verts = []
    for px, py in [(x, y), (x + 6, y), (x + 6, y + 6), (x, y + 6)]:
        verts.append([round((px - x0) * 1000), round((py - y0) * 1000), 0])
    for px, py in [(x, y), (x + 6, y), (x + 6, y + 6), (x, y + 6)]:
        verts.append([round((px - x0) * 1000), round((py - y0) * 1000), 6000])
    b = base
    shell = [[[b + 4, b + 5, b + 6, b + 7]]] + [[[b + i, b + (i + 1) % 4, b + 4 + (i + 1) % 4, b + 4 + i]] for i in range(4)]
    return verts, {"type": "Building", "geometry": [{"type": "Solid", "lod": "1.2", "boundaries": [shell]}]}
objects, vertices = {}, []
with open(work + "/city.city.jsonl", "w") as seq:
    seq.write(json.dumps(dict(head, CityObjects={}, vertices=[])) + "\n")
    for k, (x, y) in enumerate(boxes):
        verts, obj = solid(x, y, len(vertices))
        vertices += verts
        objects["b%d" % k] = obj
        local_verts, local = solid(x, y, 0)
        seq.write(json.dumps({"type": "CityJSONFeature", "id": "b%d" % k,
                              "CityObjects": {"b%d" % k: local}, "vertices": local_verts}) + "\n")
json.dump(dict(head, CityObjects=objects, vertices=vertices), open(work + "/city.city.json", "w"))
scene("cityjson", {"id": "m", "file": "city.city.json"})
scene("cityjsonseq", {"id": "m", "file": "city.city.jsonl"})

with open(work + "/city.idf", "w") as idf:
    idf.write("Version,23.2;\nGlobalGeometryRules,UpperLeftCorner,Counterclockwise,World;\n")
    for k, (x, y) in enumerate(boxes):
        for j, f in enumerate(faces(x, y)):
            # EnergyPlus's vertex order from the upper left corner, counter-clockwise: a
            # wall's top vertex first; the roof as it is.
            f = f if j == 0 else [f[3], f[0], f[1], f[2]]
            idf.write("Shading:Site:Detailed,b%d.%d,,4,%s;\n" % (
                k, j, ",".join("%.4f,%.4f,%.4f" % p for p in f)))
scene("energyplus", {"id": "m", "file": "city.idf"})
PY

echo "district of $buildings box buildings ($((buildings * 5)) faces), read with no light, $repetitions runs each"
echo
echo "| format | file MB | wall s (runs) | median s | peak MB (median) | faces |"
echo "|---|---:|---|---:|---:|---:|"
for format in polygons obj gltf cityjson cityjsonseq energyplus; do
  walls=()
  peaks=()
  for _ in $(seq "$repetitions"); do
    /usr/bin/time -f "%e %M" -o "$work/time" "$build/cli/shadowgen" generate "$work/$format.json" \
      -o "$work/db.json" --quiet 2>"$work/warnings" || {
      cat "$work/warnings" >&2
      exit 1
    }
    read -r wall kb <"$work/time"
    walls+=("$wall")
    peaks+=("$((kb / 1024))")
  done
  case $format in
    polygons) file=$work/polygons.json ;;
    obj) file=$work/city.obj ;;
    gltf) file=$work/city.glb ;;
    cityjson) file=$work/city.city.json ;;
    cityjsonseq) file=$work/city.city.jsonl ;;
    energyplus) file=$work/city.idf ;;
  esac
  faces=$(python3 -c "import json, sys; print(len(json.load(open(sys.argv[1]))['faces']))" "$work/db.json")
  python3 - "$format" "$(stat -c %s "$file")" "$faces" "${walls[*]}" "${peaks[*]}" <<'PY'
import statistics, sys
walls = [float(w) for w in sys.argv[4].split()]
peaks = [int(p) for p in sys.argv[5].split()]
print("| %s | %.1f | %s | %.2f | %d | %s |" % (sys.argv[1], int(sys.argv[2]) / 1e6,
      ", ".join("%.2f" % w for w in walls), statistics.median(walls), statistics.median(peaks), sys.argv[3]))
PY
done
