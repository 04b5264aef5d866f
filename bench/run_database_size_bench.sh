#!/usr/bin/env bash
# A day of sun-hours regions on a district, as a database beside its scene, side by side
# with another build's shadowgen (OLD, e.g. one built from main): the procedural city
# (bench/scenes/city.h) written as a scene at Greenwich with one `sun` path
# (bench/city_sun_scene.py), then REPETITIONS rounds of, for each binary in turn,
# `generate` (its wall time and peak memory: the shadows, the sums and the database
# written) and `report --format sun-hours` of the database it wrote (the database read and
# checked, and one CSV written); the database's size against the scene's, medians, and the
# ratios of this build to OLD. The two sun-hours reports must be the same bytes.
#
#   OLD=PATH/TO/shadowgen bench/run_database_size_bench.sh [FACES] [FROM] [TO] [STEP_MIN]
#
# Defaults: 30000 faces, 21 March 2026 from 00:00 to 23:59 every 30 minutes. BUILD_DIR
# (default build/release) must hold cli/shadowgen and bench/output_bench
# (SHADOWGEN_BENCH=ON). Environment: THREADS (default 2); REPETITIONS (default 2); KEEP=
# FOLDER keeps the scene and the databases there.
set -euo pipefail

faces=${1:-30000}
from=${2:-2026-03-21T00:00}
to=${3:-2026-03-21T23:59}
step=${4:-30}
build=${BUILD_DIR:-build/release}
threads=${THREADS:-2}
repetitions=${REPETITIONS:-2}
old=${OLD:?set OLD to the shadowgen executable to compare with}
new=$build/cli/shadowgen
if [ -n "${KEEP:-}" ]; then
  work=$KEEP
  mkdir -p "$work"
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi

"$build/bench/output_bench" --write-database="city:$faces:$work/city.db.json" >/dev/null
python3 "$(dirname "$0")/city_sun_scene.py" "$work/city.db.json" "$work/scene.json" "$from" "$to" \
  "$step" >/dev/null
instants=$("$new" sun "$work/scene.json" | tail -n +2 | wc -l)
echo "city of $faces faces, sun path $from to $to every $step min: $instants instants with" \
  "the sun up, $threads threads; scene $(stat -c %s "$work/scene.json") bytes"
echo

# One timed run of `$2 ...` for binary $1 (old or new): "wall_s peak_MB" appended to
# $work/$1.$3.
timed() {
  local which=$1 binary=$2 step=$3
  shift 3
  /usr/bin/time -f "%e %M" -o "$work/time" "$binary" "$@"
  read -r wall kb <"$work/time"
  echo "$wall $((kb / 1024))" >>"$work/$which.$step"
}
for _ in $(seq "$repetitions"); do
  for which in old new; do
    binary=$old
    [ "$which" = new ] && binary=$new
    timed "$which" "$binary" generate generate "$work/scene.json" -o "$work/$which.db.json" \
      --threads "$threads" --quiet
    timed "$which" "$binary" read report "$work/$which.db.json" --format sun-hours \
      -o "$work/$which.sun-hours.csv" --quiet
  done
done
cmp "$work/old.sun-hours.csv" "$work/new.sun-hours.csv"

python3 - "$work" "$(stat -c %s "$work/scene.json")" "$(stat -c %s "$work/old.db.json")" \
  "$(stat -c %s "$work/new.db.json")" <<'PY'
import statistics, sys
work, scene, old_db, new_db = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
def runs(which, step):
    return [line.split() for line in open("%s/%s.%s" % (work, which, step))]
print("| database | bytes | × scene |")
print("|---|---:|---:|")
print("| OLD (%s) | %s | %.1f |" % ("inline coordinates", format(old_db, ","), old_db / scene))
print("| this build | %s | %.1f |" % (format(new_db, ","), new_db / scene))
print()
print("| step | binary | wall s (runs) | median s | peak MB (median) | ratio to OLD |")
print("|---|---|---|---:|---:|---:|")
for step, name in (("generate", "generate (shadows, sums, database written)"),
                   ("read", "report --format sun-hours (database read)")):
    medians = {}
    for which in ("old", "new"):
        rows = runs(which, step)
        walls = [float(r[0]) for r in rows]
        medians[which] = statistics.median(walls)
        print("| %s | %s | %s | %.2f | %d | %s |" % (
            name, "OLD" if which == "old" else "this build", ", ".join("%.2f" % w for w in walls),
            medians[which], statistics.median(int(r[1]) for r in rows),
            "" if which == "old" else "%.2f" % (medians["new"] / medians["old"])))
PY
