#!/usr/bin/env bash
# Reading a gzip database, side by side with another build's shadowgen (OLD, e.g. one built
# from main): the procedural city (bench/scenes/city.h) written as a scene at Greenwich
# with one `sun` path (bench/city_sun_scene.py), generated once by this build to DB.json.gz;
# then REPETITIONS rounds of `report DB.json.gz -o CSV` (the database inflated, parsed and
# checked, one CSV of areas written), OLD and this build in turn, one thread each. Prints
# each run's wall and CPU (user + system) seconds and, as markdown, their medians and this
# build ÷ OLD; the two reports must be the same bytes. Last, where valgrind is installed,
# the instructions each executes for the same report of a smaller city's gzip database
# (CALLGRIND_FACES faces; callgrind's Ir, deterministic where wall times are noisy).
#
#   OLD=PATH/TO/shadowgen bench/run_gzip_read_bench.sh [FACES] [FROM] [TO] [STEP_MIN]
#
# Defaults: 10000 faces, 21 March 2026 from 00:00 to 23:59 every 30 minutes. BUILD_DIR
# (default build/release) must hold cli/shadowgen and bench/output_bench
# (SHADOWGEN_BENCH=ON). Environment: REPETITIONS (default 5); CALLGRIND_FACES (default
# 1000); KEEP=FOLDER keeps the scene and the database there.
set -euo pipefail

faces=${1:-10000}
from=${2:-2026-03-21T00:00}
to=${3:-2026-03-21T23:59}
step=${4:-30}
build=${BUILD_DIR:-build/release}
repetitions=${REPETITIONS:-5}
callgrind_faces=${CALLGRIND_FACES:-1000}
old=${OLD:?set OLD to the shadowgen executable to compare with}
new=$build/cli/shadowgen
. "$(dirname "$0")/city_work.sh"
work_folder

city_sun_scene "$faces" "$work/scene.json" "$from" "$to" "$step" >/dev/null
"$new" generate "$work/scene.json" -o "$work/db.json.gz" --quiet
echo "city of $faces faces, sun path $from to $to every $step min; gzip database" \
  "$(stat -c %s "$work/db.json.gz") bytes, $(zcat "$work/db.json.gz" | wc -c) inflated"

declare -A walls cpus
for round in $(seq "$repetitions"); do
  for which in old new; do
    binary=$old
    [ "$which" = new ] && binary=$new
    /usr/bin/time -f "%e %U %S" -o "$work/time" \
      "$binary" report "$work/db.json.gz" -o "$work/$which.csv" --threads 1 --quiet
    read -r wall user sys <"$work/time"
    cpu=$(python3 -c "print('%.2f' % ($user + $sys))")
    walls[$which]+="$wall "
    cpus[$which]+="$cpu "
    echo "round $round $which: wall $wall s, CPU $cpu s"
  done
done
cmp "$work/old.csv" "$work/new.csv"

. "$(dirname "$0")/median.sh"
echo
echo "| binary | wall s (runs) | median wall s | CPU s (runs) | median CPU s |"
echo "|---|---|---:|---|---:|"
for which in old new; do
  echo "| $which | ${walls[$which]}| $(echo "${walls[$which]}" | median) | ${cpus[$which]}|" \
    "$(echo "${cpus[$which]}" | median) |"
done
ratio() { python3 -c "print('%.3f' % ($(echo "$1" | median) / $(echo "$2" | median)))"; }
echo
echo "new ÷ old: wall $(ratio "${walls[new]}" "${walls[old]}"), CPU $(ratio "${cpus[new]}" "${cpus[old]}")"

if command -v valgrind >/dev/null; then
  echo
  rm -f "$work/city.db.json"
  city_sun_scene "$callgrind_faces" "$work/small.json" "$from" "$to" "$step" >/dev/null
  "$new" generate "$work/small.json" -o "$work/small.db.json.gz" --quiet
  for which in old new; do
    binary=$old
    [ "$which" = new ] && binary=$new
    valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.$which" "$binary" \
      report "$work/small.db.json.gz" -o "$work/small.$which.csv" --threads 1 --quiet \
      2>"$work/valgrind.$which"
    echo "city of $callgrind_faces faces, $which: $(grep -o 'Collected : [0-9]*' \
      "$work/valgrind.$which" | grep -o '[0-9]*') instructions (Ir)"
  done
fi
