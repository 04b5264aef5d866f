#!/usr/bin/env bash
# The procedural city seen from above, through the command line: `generate` of its scene,
# then `render` of the database from an aerial camera (the eye 0.6 × the city's width up,
# one city-width south of its south side, looking at its centre: 800 × 600, perspective,
# 45°, so the ground between the buildings shows) and `export -o OUT.obj`. Two cities
# per size: bench/scenes/city.h as it is (a ground tile per lot), and the same buildings
# on one ground face under the whole city, whose lit region has a hole per building.
# Old and new builds run side by side, in alternating rounds, so that both see the same
# load; prints each run and, as markdown, the medians of wall and CPU seconds, render and
# export against generate, new ÷ old, and the log-log slope of each step from the
# smallest size to the largest.
#
#   bench/run_aerial_bench.sh OLD_BUILD NEW_BUILD [FACES ...]
#
# FACES defaults to 10000 20000 40000 100000. Each build folder must hold cli/shadowgen;
# NEW_BUILD also bench/output_bench (SHADOWGEN_BENCH=ON), which writes the cities. OLD_BUILD
# may be "-" (the new build alone). Environment: ROUNDS (default 3); THREADS (default 2)
# for generate (render uses every hardware thread); OLD_MAX_FACES (default: all) leaves
# the old build out above that size, for an old build that takes minutes there; CITIES
# (default "lots one") picks the cities.
set -euo pipefail

old=$1
new=$2
shift 2
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(10000 20000 40000 100000)
rounds=${ROUNDS:-3}
threads=${THREADS:-2}
old_max=${OLD_MAX_FACES:-999999999}
cities=${CITIES:-lots one}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The scenes: the city's faces as polygons with its sun and lamp, and the camera.
for faces in "${sizes[@]}"; do
  "$new/bench/output_bench" --write-database="city:$faces:$work/city$faces.db.json" >/dev/null
  for city in $cities; do
    python3 - "$work/city$faces.db.json" "$work/$city$faces.json" "$city" \
      >"$work/$city$faces.camera" <<'PY'
import json, sys
db = json.load(open(sys.argv[1]))
polygons = []
for face in db["faces"]:
    if sys.argv[3] == "one" and face["id"].endswith("/ground"):
        continue
    for k, part in enumerate(face["parts"]):
        suffix = "" if len(face["parts"]) == 1 else "/%d" % k
        polygons.append({"id": (face["id"] + suffix).replace("/", "."), "outer": part["outer"],
                         "holes": part["holes"]})
xs = [p[0] for q in polygons for p in q["outer"]]
ys = [p[1] for q in polygons for p in q["outer"]]
x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
if sys.argv[3] == "one":
    polygons.insert(0, {"id": "ground", "outer": [[x0, y0, 0.0], [x1, y0, 0.0], [x1, y1, 0.0],
                                                  [x0, y1, 0.0]], "holes": []})
json.dump({"format": "shadowgen-scene/1", "polygons": polygons, "lights": db["lights"]},
          open(sys.argv[2], "w"))
width = x1 - x0
print("%r,%r,%r %r,%r,0" % ((x0 + x1) / 2, y0 - width, 0.6 * width, (x0 + x1) / 2, (y0 + y1) / 2))
PY
  done
done

# One step of one build: "wall cpu" seconds appended to $work/rows with its labels.
step() {  # SIDE BUILD CITY FACES STEP
  local side=$1 build=$2 city=$3 faces=$4 what=$5
  local db=$work/$side.$city$faces.db.json
  local eye target
  read -r eye target <"$work/$city$faces.camera"
  case $what in
    generate) set -- generate "$work/$city$faces.json" -o "$db" --threads "$threads" ;;
    render) set -- render "$db" --eye "$eye" --target "$target" -o "$work/$side.svg" ;;
    export) set -- export "$db" -o "$work/$side.obj" ;;
  esac
  /usr/bin/time -f "%e %U %S" -o "$work/time" "$build/cli/shadowgen" "$@" --quiet
  read -r wall user sys <"$work/time"
  local cpu
  cpu=$(python3 -c "print(round($user + $sys, 2))")
  echo "$side $city $faces $what: $wall s wall, $cpu s CPU" >&2
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$side" "$city" "$faces" "$what" "$wall" "$cpu" >>"$work/rows"
}

: >"$work/rows"
for ((r = 1; r <= rounds; ++r)); do
  for city in $cities; do
    for faces in "${sizes[@]}"; do
      for side in old new; do
        build=$new
        if [[ $side == old ]]; then
          [[ $old != - && $faces -le $old_max ]] || continue
          build=$old
        fi
        for what in generate render export; do step "$side" "$build" "$city" "$faces" "$what"; done
      done
    done
  done
done

python3 - "$work/rows" "${sizes[@]}" <<'PY'
import math, statistics, sys
rows = [line.rstrip("\n").split("\t") for line in open(sys.argv[1]) if line.strip()]
sizes = [int(s) for s in sys.argv[2:]]
med = {}
for side, city, faces, what, wall, cpu in rows:
    med.setdefault((side, city, int(faces), what), []).append((float(wall), float(cpu)))
def m(side, city, faces, what, k):
    runs = med.get((side, city, faces, what))
    return statistics.median(r[k] for r in runs) if runs else None
def f(x):
    return "–" if x is None else ("%.2f" % x if x < 100 else "%.0f" % x)
def ratio(a, b):
    return None if a is None or b is None or b == 0 else a / b
names = {"lots": "city (a ground tile per lot)", "one": "city on one ground face"}
print("| city | faces | build | generate s | render s | export s | render ÷ generate | export ÷ generate |")
print("|---|---:|---|---:|---:|---:|---:|---:|")
cities = sorted({r[1] for r in rows}, key=lambda c: c != "lots")
for city in cities:
    for faces in sizes:
        for side in ("old", "new"):
            g, r, e = (m(side, city, faces, w, 0) for w in ("generate", "render", "export"))
            if g is None:
                continue
            gc, rc, ec = (m(side, city, faces, w, 1) for w in ("generate", "render", "export"))
            print("| %s | %d | %s | %s (%s CPU) | %s (%s CPU) | %s (%s CPU) | %s (%s CPU) | %s (%s CPU) |" % (
                names[city], faces, side, f(g), f(gc), f(r), f(rc), f(e), f(ec),
                f(ratio(r, g)), f(ratio(rc, gc)), f(ratio(e, g)), f(ratio(ec, gc))))
print()
print("| city | step | new ÷ old at each size (wall) | slope new, %d to %d faces (wall, CPU) | slope old |" % (sizes[0], sizes[-1]))
print("|---|---|---|---:|---:|")
def slope(side, city, what, k):
    a, b = m(side, city, sizes[0], what, k), m(side, city, sizes[-1], what, k)
    if a is None or b is None or len(sizes) < 2:
        return None
    return math.log(b / a) / math.log(sizes[-1] / sizes[0])
for city in cities:
    for what in ("generate", "render", "export"):
        per = ", ".join("%d: %s" % (n, f(ratio(m("new", city, n, what, 0), m("old", city, n, what, 0))))
                        for n in sizes if m("old", city, n, what, 0) is not None)
        print("| %s | %s | %s | %s, %s | %s |" % (names[city], what, per or "–",
              f(slope("new", city, what, 0)), f(slope("new", city, what, 1)), f(slope("old", city, what, 0))))
PY
