#!/usr/bin/env bash
# The sun-hours map of a district, through the command line: the procedural city
# (bench/scenes/city.h) written as a scene at Greenwich with one `sun` path, generated
# once (`shadowgen generate`, its wall time and the database's size), then its sun-hours
# plan drawn from straight above (`render --sun-hours --ortho`, the scene fitted to an
# 800 × 600 picture) as one path per piece (`--pieces`, as every map was drawn before the
# pieces of one colour were joined), as one path per colour (coordinates on the grid of
# 1/1000 pixel) and as one path per colour with `--full-precision` (every coordinate the
# double it is), and, where BASE_BUILD_DIR names a second build (another commit's), its
# plan one path per colour beside them, all in turn, each REPETITIONS times: the SVG's size
# and path count, where its bytes go (the fills' path data, the outlines' path data, the
# rest), and each run's wall time and peak resident memory, with the medians and the
# ratio to the second build's; then the same bands exported as a glTF and an OBJ model
# (`export --sun-hours`), likewise (MODEL_REPETITIONS times, default REPETITIONS). PIECES=0
# leaves the plan one path per piece out.
#
#   bench/run_map_bench.sh [FACES] [FROM] [TO] [STEP_MIN]
#
# Defaults: 30000 faces, 21 March 2026 from 00:00 to 23:59 every 30 minutes. BUILD_DIR
# (default build/release) must hold cli/shadowgen and bench/output_bench
# (SHADOWGEN_BENCH=ON); BASE_BUILD_DIR, cli/shadowgen. Environment: THREADS (default 2)
# for generate and render; REPETITIONS (default 3); KEEP=FOLDER keeps the scene, database
# and pictures there, and with REUSE=1 a later run takes the city and database it finds
# there instead of making them again (the pictures alone measured).
set -euo pipefail

faces=${1:-30000}
from=${2:-2026-03-21T00:00}
to=${3:-2026-03-21T23:59}
step=${4:-30}
build=${BUILD_DIR:-build/release}
threads=${THREADS:-2}
repetitions=${REPETITIONS:-3}
. "$(dirname "$0")/city_work.sh"
work_folder

# The scene, and the middle of its bounding box: where the camera looks down from.
centre=$(city_sun_scene "$faces" "$work/scene.json" "$from" "$to" "$step")
read -r cx cy top <<<"$centre"
instants=$("$build/cli/shadowgen" sun "$work/scene.json" | tail -n +2 | wc -l)
polygons=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['polygons']))" "$work/scene.json")
echo "city of $faces faces ($polygons polygons), sun path $from to $to every $step min: $instants instants with the sun up, $threads threads"
echo

if [ -f "$work/db.json" ] && [ -n "${REUSE:-}" ]; then
  echo "generate: the database of an earlier run, $(du -m --apparent-size "$work/db.json" | cut -f1) MB"
else
  /usr/bin/time -f "%e %M" -o "$work/time" "$build/cli/shadowgen" generate "$work/scene.json" \
    -o "$work/db.json" --threads "$threads" --quiet
  read -r wall kb <"$work/time"
  echo "generate: $wall s, $((kb / 1024)) MB at peak, database $(du -m --apparent-size "$work/db.json" | cut -f1) MB"
fi
echo

# One render by the executable $2: its wall time and peak MB, the SVG's bytes and paths,
# and the bytes of its fills' path data, its outlines' path data and the rest, appended to
# $work/$1.runs.
render() {
  local mode=$1 shadowgen=$2
  shift 2
  /usr/bin/time -f "%e %M" -o "$work/time" "$shadowgen" render "$work/db.json" \
    --eye "$cx,$cy,$top" --target "$cx,$cy,0" --ortho --sun-hours path \
    --svg "$work/$mode.svg" --quiet "$@"
  read -r wall kb <"$work/time"
  local where
  where=$(python3 - "$work/$mode.svg" <<'PY'
import re, sys
svg = open(sys.argv[1]).read()
outlines = svg.find("data-outlines")
fills = sum(len(d) for d in re.findall(r'<path d="([^"]*)" fill=', svg[:outlines] if outlines >= 0 else svg))
lines = sum(len(d) for d in re.findall(r'<path d="([^"]*)" data-', svg[outlines:])) if outlines >= 0 else 0
print(fills, lines, len(svg.encode()) - fills - lines)
PY
  )
  echo "$wall $((kb / 1024)) $(stat -c %s "$work/$mode.svg") $(grep -c '<path' "$work/$mode.svg") $where" \
    >>"$work/$mode.runs"
  cp "$work/$mode.svg" "$work/$mode.last.svg"
}
modes="merged exact"
[ "${PIECES:-1}" = 0 ] || modes="pieces $modes"
for _ in $(seq "$repetitions"); do
  [ "${PIECES:-1}" = 0 ] || render pieces "$build/cli/shadowgen" --pieces
  render merged "$build/cli/shadowgen"
  render exact "$build/cli/shadowgen" --full-precision
  if [ -n "${BASE_BUILD_DIR:-}" ]; then
    render base "$BASE_BUILD_DIR/cli/shadowgen"
  fi
done
[ -z "${BASE_BUILD_DIR:-}" ] || modes="$modes base"
echo "| SVG | wall s (runs) | median s | × base | peak MB | SVG bytes | × base | paths | fills' d | outlines' d | rest |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for mode in $modes; do
  python3 - "$mode" "$work/$mode.runs" "$work/base.runs" <<'PY'
import os, statistics, sys
names = {"pieces": "one path per piece (--pieces)", "merged": "one path per colour",
         "exact": "one path per colour, --full-precision", "base": "one path per colour, base build"}
def rows(path):
    return [line.split() for line in open(path)]
r = rows(sys.argv[2])
walls = [float(x[0]) for x in r]
base = rows(sys.argv[3]) if os.path.exists(sys.argv[3]) else None
def ratio(a, b):
    return "%.2f" % (a / b) if b else ""
base_wall = statistics.median(float(x[0]) for x in base) if base else 0
base_bytes = int(base[-1][2]) if base else 0
print("| %s | %s | %.2f | %s | %d | %s | %s | %s | %s | %s | %s |" % (
    names[sys.argv[1]], ", ".join("%.2f" % w for w in walls), statistics.median(walls),
    ratio(statistics.median(walls), base_wall), statistics.median(int(x[1]) for x in r),
    format(int(r[-1][2]), ","), ratio(int(r[-1][2]), base_bytes), format(int(r[-1][3]), ","),
    format(int(r[-1][4]), ","), format(int(r[-1][5]), ","), format(int(r[-1][6]), ",")))
PY
done

# The same bands as a 3D model, for a viewer: `export --sun-hours` as binary glTF and as
# OBJ (with its MTL), in turn, REPETITIONS times, each run's wall time and peak memory
# and the file's size.
model() {
  local form=$1
  /usr/bin/time -f "%e %M" -o "$work/time" "$build/cli/shadowgen" export "$work/db.json" \
    --sun-hours path -o "$work/bands.$form" --quiet
  read -r wall kb <"$work/time"
  local bytes
  bytes=$(stat -c %s "$work/bands.$form")
  [ "$form" = obj ] && bytes=$((bytes + $(stat -c %s "$work/bands.mtl")))
  echo "$wall $((kb / 1024)) $bytes" >>"$work/$form.runs"
}
for _ in $(seq "${MODEL_REPETITIONS:-$repetitions}"); do
  model glb
  model obj
done
echo
echo "| model | wall s (runs) | median s | peak MB | bytes |"
echo "|---|---|---:|---:|---:|"
for form in glb obj; do
  python3 - "$form" "$work/$form.runs" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[2])]
walls = [float(r[0]) for r in rows]
print("| %s | %s | %.2f | %d | %s |" % (
    "glTF (.glb)" if sys.argv[1] == "glb" else "OBJ + MTL",
    ", ".join("%.2f" % w for w in walls), statistics.median(walls),
    statistics.median(int(r[1]) for r in rows), format(int(rows[-1][2]), ",")))
PY
done
