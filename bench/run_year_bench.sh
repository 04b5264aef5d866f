#!/usr/bin/env bash
# An hourly year of sun, lit areas alone (`generate --areas-only`), on the procedural city
# (bench/scenes/city.h) written as a scene at Greenwich (bench/city_sun_scene.py), side by
# side with another build's shadowgen (OLD, e.g. one built from main): REPETITIONS rounds
# of each binary in turn, its CPU seconds (user + sys: the figure that means something on
# a loaded machine), wall seconds and peak memory; medians and the ratio of this build to
# OLD. The two databases must be the same bytes (cmp). Without OLD, this build alone.
#
#   [OLD=PATH/TO/shadowgen] bench/run_year_bench.sh [FACES] [DAYS]
#
# FACES defaults to 30000. DAYS: `year` (default), every hour of 2026, one sun path; or a
# day of the month, e.g. `21`: every hour of that day in each month, twelve sun paths, and
# the figures scaled to the year by the instants with the sun up (a year's ÷ the subset's,
# both counted by `shadowgen sun`). BUILD_DIR (default build/release) must hold
# cli/shadowgen and bench/output_bench (SHADOWGEN_BENCH=ON). Environment: THREADS
# (default 2); REPETITIONS (default 1); KEEP=FOLDER keeps the scene and the databases.
set -euo pipefail

faces=${1:-30000}
days=${2:-year}
build=${BUILD_DIR:-build/release}
threads=${THREADS:-2}
repetitions=${REPETITIONS:-1}
new=$build/cli/shadowgen
. "$(dirname "$0")/city_work.sh"
work_folder

city_sun_scene "$faces" "$work/year.json" 2026-01-01T00:00 2026-12-31T23:00 60 >/dev/null
if [ "$days" = year ]; then
  scene=$work/year.json
else
  scene=$work/days.json
  python3 - "$work/year.json" "$scene" "$days" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
day = int(sys.argv[3])
scene["lights"] = [{"id": "m%02d" % m, "type": "sun", "from": "2026-%02d-%02dT00:00" % (m, day),
                    "to": "2026-%02d-%02dT23:00" % (m, day), "step_min": 60} for m in range(1, 13)]
json.dump(scene, open(sys.argv[2], "w"))
PY
fi
count() { "$new" sun "$1" | tail -n +2 | wc -l; }
year_instants=$(count "$work/year.json")
instants=$(count "$scene")
polygons=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['polygons']))" \
  "$scene")
echo "city of $faces faces ($polygons polygons as read), $threads threads: $instants instants" \
  "with the sun up ($days; the year has $year_instants)"
echo

# One timed run of binary $2 (old or new: $1), "cpu_s wall_s peak_MB" appended to $work/$1.
timed() {
  /usr/bin/time -f "%U %S %e %M" -o "$work/time" "$2" generate "$scene" -o "$work/$1.db.json" \
    --areas-only --threads "$threads" --quiet
  read -r user sys wall kb <"$work/time"
  echo "$(python3 -c "print(f'{$user + $sys:.2f}')") $wall $((kb / 1024))" >>"$work/$1"
}
binaries=(new)
[ -n "${OLD:-}" ] && binaries=(old new)
rm -f "$work/old" "$work/new"
for _ in $(seq "$repetitions"); do
  for which in "${binaries[@]}"; do
    binary=$new
    [ "$which" = old ] && binary=$OLD
    timed "$which" "$binary"
  done
done
if [ -n "${OLD:-}" ]; then
  cmp "$work/old.db.json" "$work/new.db.json" # a difference ends the run, with its place
  echo "databases: same bytes"
fi

python3 - "$work" "$instants" "$year_instants" "${binaries[@]}" <<'PY'
import statistics, sys
work, instants, year = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
scale = year / instants
print("| binary | CPU s (runs) | wall s (runs) | CPU s median | wall s median | peak MB |"
      " year CPU s | year wall s | CPU ratio to OLD |")
print("|---|---|---|---:|---:|---:|---:|---:|---:|")
medians = {}
for which in sys.argv[4:]:
    rows = [[float(x) for x in line.split()] for line in open("%s/%s" % (work, which))]
    cpu, wall = [r[0] for r in rows], [r[1] for r in rows]
    medians[which] = statistics.median(cpu)
    print("| %s | %s | %s | %.1f | %.1f | %d | %.0f | %.0f | %s |" % (
        "OLD" if which == "old" else "this build", ", ".join("%.1f" % c for c in cpu),
        ", ".join("%.1f" % w for w in wall), statistics.median(cpu), statistics.median(wall),
        statistics.median(r[2] for r in rows), statistics.median(cpu) * scale,
        statistics.median(wall) * scale,
        "%.2f" % (medians["new"] / medians["old"]) if which == "new" and "old" in medians else ""))
PY
