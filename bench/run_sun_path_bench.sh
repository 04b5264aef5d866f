#!/usr/bin/env bash
# A sun path on the procedural city (bench/scenes/city.h), through the command line:
# `shadowgen generate` on 1 and 2 threads, with its wall time, peak resident memory and
# the database's size, and the sun-hours report of the result. The city's faces are
# written as a scene (polygons) at Greenwich with one `sun` path instead of its own lights.
#
#   bench/run_sun_path_bench.sh [FACES] [FROM] [TO] [STEP_MIN]
#
# Defaults: 10000 faces, 21 March 2026 from 00:00 to 23:59 every 10 minutes. A year of
# hourly instants: 10000 2026-01-01T00:00 2026-12-31T23:00 60. BUILD_DIR (default
# build/release) must hold cli/shadowgen and bench/output_bench (SHADOWGEN_BENCH=ON).
# Environment: THREADS (default "1 2"), the thread counts to run in turn; SUMS=areas runs
# generate --areas-only (lit areas alone, no sun-hours regions) and sums the EnergyPlus
# schedule instead of the sun-hours report; GENERATE_ARGS adds arguments to generate (e.g.
# "--method rays --samples 64", whose lit areas alone go with SUMS=areas).
set -euo pipefail

faces=${1:-10000}
from=${2:-2026-03-21T00:00}
to=${3:-2026-03-21T23:59}
step=${4:-10}
build=${BUILD_DIR:-build/release}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$build/bench/output_bench" --write-database="city:$faces:$work/city.db.json" >/dev/null
python3 "$(dirname "$0")/city_sun_scene.py" "$work/city.db.json" "$work/scene.json" "$from" "$to" \
  "$step" >/dev/null
instants=$("$build/cli/shadowgen" sun "$work/scene.json" | tail -n +2 | wc -l)
echo "city of $faces faces (as read: $(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['polygons']))" "$work/scene.json") polygons), sun path $from to $to every $step min: $instants instants with the sun up"
echo
echo "| threads | wall s | peak MB | database MB |"
echo "|---:|---:|---:|---:|"
sums=()
[ "${SUMS:-regions}" = areas ] && sums=(--areas-only)
read -r -a extra <<<"${GENERATE_ARGS:-}"
for threads in ${THREADS:-1 2}; do
  /usr/bin/time -f "%e %M" -o "$work/time" "$build/cli/shadowgen" generate "$work/scene.json" \
    -o "$work/db.json" --threads "$threads" --quiet "${sums[@]}" "${extra[@]}"
  read -r wall kb <"$work/time"
  mb=$(du -m --apparent-size "$work/db.json" | cut -f1)
  echo "| $threads | $wall | $((kb / 1024)) | $mb |"
done
echo
if [ "${SUMS:-regions}" = areas ]; then
  "$build/cli/shadowgen" report "$work/db.json" --format energyplus 2>/dev/null |
    python3 -c "
import sys
rows = [line.rstrip(',\n').split(',') for line in sys.stdin][1:]
fractions = [float(x) for row in rows for x in row[1:]]
print('EnergyPlus schedule: %d rows of %d faces, mean sunlit fraction %.4f' % (len(rows), len(rows[0]) - 1, sum(fractions) / len(fractions)))
"
  exit 0
fi
"$build/cli/shadowgen" report "$work/db.json" --format sun-hours --threshold 2,6 |
  python3 -c "
import csv, sys
rows = list(csv.DictReader(sys.stdin))
area = sum(float(r['area']) for r in rows)
two = sum(float(r['area_at_least_2h']) for r in rows)
mean = sum(float(r['mean_sun_hours']) * float(r['area']) for r in rows) / area
print('sun hours over all faces: area-weighted mean %.3f h, %.1f %% of the area with at least 2 h' % (mean, 100 * two / area))
"
