#!/usr/bin/env bash
# `shadowgen report` of one sun on the procedural city from end to end (reading the
# 25 MB scene, its shadows, writing the report), on one thread and on two, side by side
# with an older build in alternating rounds so that both see the same load on a shared
# machine: the wall seconds, the CPU seconds (user + system, every thread's) and the peak
# memory of each run (/usr/bin/time), their medians, new ÷ old, and two threads ÷ one.
# Every report must be the same bytes (checked). Then, with BIG set, the 1e6-face city's
# sun on two threads, once per build, with its peak memory.
#
#   bench/run_end_to_end_bench.sh OLD_BUILD NEW_BUILD [ROUNDS] [FACES]
#
# Each build folder must hold cli/shadowgen; NEW_BUILD also bench/output_bench (a release
# build with SHADOWGEN_BENCH=ON), which writes the city as a scene. ROUNDS defaults to 5,
# FACES to 100000 (129 × 129 lots: 99,846 faces). BIG=1000000 adds the big city.
set -euo pipefail

old=$1
new=$2
rounds=${3:-5}
faces=${4:-100000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$new/bench/output_bench" --write-database="cityscene:$faces:$work/city.json"
echo "scene: $(stat -c %s "$work/city.json") bytes" >&2

run() {  # BUILD THREADS SCENE OUT: "wall cpu peak_kb" of one report
  /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$1/cli/shadowgen" report "$3" \
    --threads "$2" --quiet -o "$4"
  awk '{ printf "%s %.2f %s\n", $1, $2 + $3, $4 }' "$work/time"
}

: >"$work/rows"
for ((r = 1; r <= rounds; ++r)); do
  for threads in 1 2; do
    for side in old new; do
      build=$old
      [[ $side == new ]] && build=$new
      line=$(run "$build" "$threads" "$work/city.json" "$work/$side.$threads.csv")
      echo "round $r $side $threads threads: $line" >&2
      printf '%s\t%s\t%s\n' "$side" "$threads" "$line" >>"$work/rows"
      cmp -s "$work/$side.$threads.csv" "$work/old.1.csv" ||
        { echo "the report differs: $side, $threads threads" >&2; exit 1; }
    done
  done
done

python3 - "$work/rows" "$faces" <<'PY'
import statistics, sys
rows = [line.split("\t") for line in open(sys.argv[1]).read().split("\n") if line]
med = {}
for side in ("old", "new"):
    for threads in ("1", "2"):
        runs = [r[2].split() for r in rows if r[0] == side and r[1] == threads]
        med[side, threads] = [statistics.median(float(x[i]) for x in runs) for i in range(3)]
print(f"report of one sun on the {int(sys.argv[2]):,}-face city, end to end, medians of "
      f"{len([r for r in rows if r[0] == 'old' and r[1] == '1'])} alternating rounds\n")
print("| build | threads | wall s | CPU s | peak MB | 1 thread ÷ 2 threads (wall) |")
print("|---|---:|---:|---:|---:|---:|")
for side in ("old", "new"):
    for threads in ("1", "2"):
        wall, cpu, kb = med[side, threads]
        ratio = f"{med[side, '1'][0] / wall:.2f}" if threads == "2" else ""
        print(f"| {side} | {threads} | {wall:.2f} | {cpu:.2f} | {kb / 1024:.0f} | {ratio} |")
for threads in ("1", "2"):
    print(f"\nnew ÷ old, {threads} thread(s): wall {med['new', threads][0] / med['old', threads][0]:.2f}, "
          f"CPU {med['new', threads][1] / med['old', threads][1]:.2f}")
PY

if [[ -n ${BIG:-} ]]; then
  "$new/bench/output_bench" --write-database="cityscene:$BIG:$work/big.json"
  echo "big scene: $(stat -c %s "$work/big.json") bytes" >&2
  for side in old new; do
    build=$old
    [[ $side == new ]] && build=$new
    echo "the $BIG-face city, one sun, 2 threads, $side: wall s, CPU s, peak KB: $(run "$build" 2 "$work/big.json" "$work/big.$side.csv")"
  done
  cmp -s "$work/big.old.csv" "$work/big.new.csv" || { echo "the big reports differ" >&2; exit 1; }
fi
