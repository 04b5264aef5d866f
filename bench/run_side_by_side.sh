#!/usr/bin/env bash
# Two builds side by side on the same workloads, in alternating rounds, so that both see
# the same load on this shared machine: the 1e5-face city under its sun (shadow_bench,
# one and two threads; CPU seconds of generate_shadows) and the 1e4-face city under the
# six lowest suns of a year sampled every 73 hours (`shadowgen generate`, one thread;
# wall seconds of the command, the suns whose long shadows cost most in a sun path).
# Prints each round and, as markdown, the medians and new ÷ old.
#
#   bench/run_side_by_side.sh OLD_BUILD NEW_BUILD [ROUNDS]
#
# Each build folder must hold bench/shadow_bench, bench/output_bench and cli/shadowgen
# (a release build with SHADOWGEN_BENCH=ON, e.g. of the previous commit in a worktree:
# `git worktree add ../prev HEAD~1 && cmake --preset release -S ../prev -B ../prev/build/release`).
# ROUNDS defaults to 3.
set -euo pipefail

old=$1
new=$2
rounds=${3:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The low suns: the city written as a scene with the year's instants as directional
# lights, from the new build's own sun positions.
"$new/bench/output_bench" --write-database="city:10000:$work/city.db.json" >/dev/null
python3 - "$work/city.db.json" "$work/path.json" <<'PY'
import json, sys
db = json.load(open(sys.argv[1]))
polygons = []
for face in db["faces"]:
    for k, part in enumerate(face["parts"]):
        suffix = "" if len(face["parts"]) == 1 else "/%d" % k
        polygons.append({"id": (face["id"] + suffix).replace("/", "."), "outer": part["outer"],
                         "holes": part["holes"]})
scene = {"format": "shadowgen-scene/1", "polygons": polygons,
         "site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "utc_offset_h": 0},
         "lights": [{"id": "path", "type": "sun", "from": "2026-01-01T00:00",
                     "to": "2026-12-31T23:00", "step_min": 4380}]}
json.dump(scene, open(sys.argv[2], "w"))
PY
"$new/cli/shadowgen" sun "$work/path.json" >"$work/sun.csv"
python3 - "$work/path.json" "$work/sun.csv" "$work/low.json" <<'PY'
import csv, json, sys
scene = json.load(open(sys.argv[1]))
rows = sorted(csv.DictReader(open(sys.argv[2])), key=lambda r: float(r["elevation_deg"]))[:6]
scene["lights"] = [{"id": "sun%d" % i, "type": "directional",
                    "direction": [float(r["direction_x"]), float(r["direction_y"]),
                                  float(r["direction_z"])]} for i, r in enumerate(rows)]
del scene["site"]
json.dump(scene, open(sys.argv[3], "w"))
print("low suns: elevations " + ", ".join("%.1f°" % float(r["elevation_deg"]) for r in rows))
PY

bench_seconds() {  # BUILD FILTER: CPU seconds of one benchmark run
  "$1/bench/shadow_bench" --benchmark_filter="$2" --benchmark_format=csv 2>/dev/null |
    awk -F, '/^"BM_/ { print $4 }'
}
generate_seconds() {  # BUILD
  /usr/bin/time -f "%e" -o "$work/time" "$1/cli/shadowgen" generate "$work/low.json" \
    -o "$work/db.json" --threads 1 --quiet
  cat "$work/time"
}

workloads=("city 1e5, sun, 1 thread" "city 1e5, sun, 2 threads" "city 1e4, 6 low suns, 1 thread")
: >"$work/rows"
for ((r = 1; r <= rounds; ++r)); do
  for side in old new; do
    build=$old
    [[ $side == new ]] && build=$new
    a=$(bench_seconds "$build" 'BM_CitySun/100000/1/')
    b=$(bench_seconds "$build" 'BM_CitySun/100000/2/')
    c=$(generate_seconds "$build")
    echo "round $r $side: $a $b $c" >&2
    printf '%s\t%s\t%s\n' "$side" 0 "$a" "$side" 1 "$b" "$side" 2 "$c" >>"$work/rows"
  done
done
python3 - "$work/rows" "${workloads[@]}" <<'PY'
import statistics, sys
rows = [line.split("\t") for line in open(sys.argv[1]).read().split("\n") if line]
names = sys.argv[2:]
print("| workload | old s | new s | new ÷ old | rounds (old; new) |")
print("|---|---:|---:|---:|---|")
for w, name in enumerate(names):
    got = {side: [float(s) for k, i, s in rows if k == side and int(i) == w] for side in ("old", "new")}
    o, n = statistics.median(got["old"]), statistics.median(got["new"])
    print("| %s | %.2f | %.2f | %.2f | %s; %s |" % (name, o, n, n / o,
          ", ".join("%.2f" % x for x in got["old"]), ", ".join("%.2f" % x for x in got["new"])))
PY
