#!/usr/bin/env bash
# The methods' trade of speed for accuracy (`shadowgen compare`) on the benchmark scenes,
# one run per scene, on one thread: the procedural city (bench/scenes/city.h, with its sun
# and lamp), Thakur, Cheng and Miura's grid of 2000 cubes on a ground (bench/scenes/
# cube_grid.h, sun and lamp), and real meshes standing on a ground under a sun and a lamp
# (Debian's assimp-testmodels and the CGAL demo meshes, placed as bench/scenes/
# mesh_on_ground.h places them). Prints each scene's table (markdown) and leaves its plot
# and its input (a scene, or a database whose scene compare takes) in OUT_DIR (default: a
# temporary folder, removed).
#
#   bench/run_compare_bench.sh [CITY_FACES]          (default 10000)
#
# BUILD_DIR (default build/release) must hold cli/shadowgen and bench/output_bench.
# METHODS (default: rays at 16, 64, 256 and 1024 points, shadow maps at 16/512, 64/1024,
# 256/2048 and 1024/4096) is passed to --methods.
set -euo pipefail

faces=${1:-10000}
build=${BUILD_DIR:-build/release}
methods=${METHODS:-rays:16,rays:64,rays:256,rays:1024,shadow-map:512:samples=16,shadow-map:1024:samples=64,shadow-map:2048:samples=256,shadow-map:4096:samples=1024}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=${OUT_DIR:-$work}
mkdir -p "$out"
meshes=$(cd "$build/bench/cgal-data/data/meshes" && pwd)
assimp=/usr/share/assimp/models

"$build/bench/output_bench" --write-database="city:$faces:$work/city.json" >/dev/null
"$build/bench/output_bench" --write-database="cubes:2000:$work/cubes.json" >/dev/null

# A mesh file as a scene: turned so that `up` is +z, on a square ground 4 times its largest
# extent, 2 % of it below its lowest point, a sun from (-0.5, 0.35, -1) and a lamp beside
# and above it. The mesh's box comes from a first read by shadowgen itself (its database).
mesh_scene() {
  local file=$1 up=$2 name=$3
  python3 - "$file" "$up" "$work/$name.probe.json" <<'PY'
import json, sys
file, up, out = sys.argv[1:4]
turn = [[1,0,0,0],[0,0,-1,0],[0,1,0,0],[0,0,0,1]] if up == "y" else [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]
json.dump({"format": "shadowgen-scene/1", "meshes": [{"id": "mesh", "file": file, "transform": turn}],
           "lights": []}, open(out, "w"))
PY
  "$build/cli/shadowgen" generate "$work/$name.probe.json" -o "$work/$name.probe.db.json" --quiet
  python3 - "$work/$name.probe.db.json" "$file" "$up" "$work/$name.json" <<'PY'
import json, sys
db, file, up, out = sys.argv[1:5]
points = [p for face in json.load(open(db))["faces"] for part in face["parts"] for p in part["outer"]]
lo = [min(p[i] for p in points) for i in range(3)]
hi = [max(p[i] for p in points) for i in range(3)]
size = max(h - l for h, l in zip(hi, lo))
cx, cy = (lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2
z = lo[2] - 0.02 * size
g = 2 * size
turn = [[1,0,0,0],[0,0,-1,0],[0,1,0,0],[0,0,0,1]] if up == "y" else [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]
scene = {"format": "shadowgen-scene/1",
         "polygons": [{"id": "ground", "outer": [[cx-g,cy-g,z],[cx+g,cy-g,z],[cx+g,cy+g,z],[cx-g,cy+g,z]]}],
         "meshes": [{"id": "mesh", "file": file, "transform": turn}],
         "lights": [{"id": "sun", "type": "directional", "direction": [-0.5, 0.35, -1]},
                    {"id": "lamp", "type": "point",
                     "position": [cx + 0.7 * size, cy - 0.55 * size, z + 1.2 * size]}]}
json.dump(scene, open(out, "w"))
PY
}
mesh_scene "$assimp/OBJ/spider.obj" y spider
mesh_scene "$meshes/anchor.off" z anchor
mesh_scene "$meshes/elk.off" z elk

# SCENES (default: all five) picks some of them.
for scene in ${SCENES:-city cubes spider anchor elk}; do
  echo "### $scene"
  echo
  "$build/cli/shadowgen" compare "$work/$scene.json" --methods "$methods" --threads 1 \
    --format csv --plot "$out/$scene.svg" --quiet >"$work/$scene.csv"
  [ "$out" = "$work" ] || cp "$work/$scene.json" "$out/$scene.json"
  python3 - "$work/$scene.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| method | seconds | ÷ exact | mean abs. error | max abs. error | Pareto |")
print("|---|---:|---:|---:|---:|:---:|")
exact = float(rows[0]["seconds"])
for r in rows:
    name = r["method"] + ("" if not r["samples"] else " " + r["samples"]) + ("" if not r["resolution"] else " @ " + r["resolution"])
    print("| %s | %.3g | %.2f | %.2e | %.2e | %s |" % (name, float(r["seconds"]), float(r["seconds"]) / exact,
          float(r["mean_error"]), float(r["max_error"]), "*" if r["pareto"] == "1" else ""))
PY
  echo
done
