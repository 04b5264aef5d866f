#!/usr/bin/env bash
# A day of sun-hours regions on a district, as a database beside its scene, side by side
# with another build's shadowgen (OLD, e.g. one built from main): the procedural city
# (bench/scenes/city.h) written as a scene at Greenwich with one `sun` path
# (bench/city_sun_scene.py), then REPETITIONS rounds of, for each binary in turn,
# `generate` (its wall time and peak memory: the shadows, the sums and the database
# written) and `report --format sun-hours` of the database it wrote (the database read and
# checked, and one CSV written); then this build's `generate` to a gzip database (DB.json.gz)
# and its `report` from that. The database's size against the scene's, plain and gzip;
# medians of wall and CPU (user + system) seconds, and the ratios of this build to OLD.
# The sun-hours reports must all be the same bytes, and `zcat` of the gzip database the
# plain one's. Last, zlib's levels 1, 6 and 9 on the plain database as the writer cuts it
# (members of 4 MiB; Python's zlib, the same library): size and CPU seconds on one thread.
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
. "$(dirname "$0")/city_work.sh"
work_folder

city_sun_scene "$faces" "$work/scene.json" "$from" "$to" "$step" >/dev/null
instants=$("$new" sun "$work/scene.json" | tail -n +2 | wc -l)
echo "city of $faces faces, sun path $from to $to every $step min: $instants instants with" \
  "the sun up, $threads threads; scene $(stat -c %s "$work/scene.json") bytes"
echo

# One timed run of `$2 ...` for $1 (old, new or gz): "wall_s peak_MB cpu_s" appended to
# $work/$1.$3.
timed() {
  local which=$1 binary=$2 step=$3
  shift 3
  /usr/bin/time -f "%e %M %U %S" -o "$work/time" "$binary" "$@"
  read -r wall kb user sys <"$work/time"
  echo "$wall $((kb / 1024)) $(python3 -c "print('%.2f' % ($user + $sys))")" >>"$work/$which.$step"
}
for _ in $(seq "$repetitions"); do
  for which in old new gz; do
    binary=$old db=$work/$which.db.json
    [ "$which" = old ] || binary=$new
    [ "$which" = gz ] && db=$work/new.db.json.gz
    timed "$which" "$binary" generate generate "$work/scene.json" -o "$db" \
      --threads "$threads" --quiet
    timed "$which" "$binary" read report "$db" --format sun-hours \
      -o "$work/$which.sun-hours.csv" --quiet
  done
done
cmp "$work/old.sun-hours.csv" "$work/new.sun-hours.csv"
cmp "$work/new.sun-hours.csv" "$work/gz.sun-hours.csv"
zcat "$work/new.db.json.gz" | cmp - "$work/new.db.json"

python3 - "$work" "$(stat -c %s "$work/scene.json")" "$(stat -c %s "$work/old.db.json")" \
  "$(stat -c %s "$work/new.db.json")" "$(stat -c %s "$work/new.db.json.gz")" <<'PY'
import resource, statistics, sys, zlib
work, scene, old_db, new_db, gz_db = sys.argv[1], *map(int, sys.argv[2:6])
def runs(which, step):
    return [line.split() for line in open("%s/%s.%s" % (work, which, step))]
print("| database | bytes | × scene |")
print("|---|---:|---:|")
print("| OLD | %s | %.1f |" % (format(old_db, ","), old_db / scene))
print("| this build | %s | %.1f |" % (format(new_db, ","), new_db / scene))
print("| this build, DB.json.gz | %s | %.2f |" % (format(gz_db, ","), gz_db / scene))
print()
print("| step | binary | wall s (runs) | median s | CPU s (median) | peak MB (median) "
      "| wall, CPU ratio to OLD |")
print("|---|---|---|---:|---:|---:|---:|")
names = {"old": "OLD", "new": "this build", "gz": "this build, .gz"}
for step, name in (("generate", "generate (shadows, sums, database written)"),
                   ("read", "report --format sun-hours (database read)")):
    wall, cpu = {}, {}
    for which in ("old", "new", "gz"):
        rows = runs(which, step)
        walls = [float(r[0]) for r in rows]
        wall[which] = statistics.median(walls)
        cpu[which] = statistics.median(float(r[2]) for r in rows)
        print("| %s | %s | %s | %.2f | %.2f | %d | %s |" % (
            name, names[which], ", ".join("%.2f" % w for w in walls), wall[which], cpu[which],
            statistics.median(int(r[1]) for r in rows),
            "" if which == "old" else "%.2f, %.2f" % (wall[which] / wall["old"],
                                                      cpu[which] / cpu["old"])))
print()
# zlib's levels on the plain database, cut as the writer cuts it (gzip_members.h).
text = open("%s/new.db.json" % work, "rb").read()
member = 4 << 20
print("| zlib level | bytes | × scene | CPU s (one thread) |")
print("|---:|---:|---:|---:|")
for level in (1, 6, 9):
    start = resource.getrusage(resource.RUSAGE_SELF)
    size = 0
    for at in range(0, len(text), member):
        z = zlib.compressobj(level, zlib.DEFLATED, 31)
        size += len(z.compress(text[at:at + member])) + len(z.flush())
    end = resource.getrusage(resource.RUSAGE_SELF)
    seconds = end.ru_utime - start.ru_utime + end.ru_stime - start.ru_stime
    print("| %d | %s | %.2f | %.2f |" % (level, format(size, ","), size / scene, seconds))
PY
