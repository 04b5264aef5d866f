#!/usr/bin/env bash
# Two `shadowgen` executables side by side on the example scenes, one thread each, in
# alternating rounds so that both see the same load on a shared machine: the pergola (119
# faces, one sun), the garden's faces under a sun every 5 minutes of 21 March (144
# instants, sun-hours regions) and its sun-hours report. Prints each round's wall seconds
# and, as markdown, the medians and new ÷ old; then the instructions each executes to
# generate the pergola and the garden's day (valgrind's callgrind: Ir, deterministic where
# wall times are noisy).
#
#   bench/run_command_side_by_side.sh OLD_SHADOWGEN NEW_SHADOWGEN [ROUNDS]
#
# ROUNDS defaults to 5. Used for the rooms built position-independent (for the Python
# module and users' shared libraries) against the same rooms built as before.
set -euo pipefail
old=$1
new=$2
rounds=${3:-5}
scenes=$(cd "$(dirname "$0")/../examples/scenes" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$scenes/garden.json" "$work/garden-day.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["lights"] = [{"id": "day", "type": "sun", "from": "2026-03-21T06:00",
                    "to": "2026-03-21T18:00", "step_min": 5}]
json.dump(scene, open(sys.argv[2], "w"))
PY

seconds() {  # EXECUTABLE ARGS...: wall seconds of one run, to the millisecond
  local start end
  start=$(date +%s.%N)
  "$@" --quiet >/dev/null
  end=$(date +%s.%N)
  python3 -c "print(f'{$end - $start:.3f}')"
}
declare -A runs
workloads=(pergola garden-day report)
run() {  # WORKLOAD EXECUTABLE
  case $1 in
    pergola) seconds "$2" generate "$scenes/pergola.json" -o "$work/db.json" --threads 1 ;;
    garden-day) seconds "$2" generate "$work/garden-day.json" -o "$work/db.json" --threads 1 ;;
    report) seconds "$2" report "$work/garden-day.json" --format sun-hours --threads 1 ;;
  esac
}
for round in $(seq "$rounds"); do
  for workload in "${workloads[@]}"; do
    for build in old new; do
      executable=$old
      [[ $build == new ]] && executable=$new
      s=$(run "$workload" "$executable")
      runs[$workload.$build]+="$s "
      echo "round $round $workload $build: $s s"
    done
  done
done

. "$(dirname "$0")/median.sh"
echo
echo "| workload | old runs (s) | new runs (s) | old median | new median | new ÷ old |"
echo "|---|---|---|---:|---:|---:|"
for workload in "${workloads[@]}"; do
  o=$(echo "${runs[$workload.old]}" | median)
  n=$(echo "${runs[$workload.new]}" | median)
  echo "| $workload | ${runs[$workload.old]}| ${runs[$workload.new]}| $o | $n | $(python3 -c "print(f'{$n / $o:.3f}')") |"
done

if command -v valgrind >/dev/null; then
  echo
  for scene in "$scenes/pergola.json" "$work/garden-day.json"; do
    for build in old new; do
      executable=$old
      [[ $build == new ]] && executable=$new
      valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.$build" "$executable" \
        generate "$scene" -o "$work/db.json" --threads 1 --quiet 2>"$work/valgrind.$build"
      echo "$(basename "$scene" .json), $build: $(grep -o 'Collected : [0-9]*' "$work/valgrind.$build" | grep -o '[0-9]*') instructions (Ir)"
    done
  done
fi
