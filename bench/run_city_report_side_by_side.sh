#!/usr/bin/env bash
# Two release builds side by side on the clipper and on a city's report, for a change
# that must leave speed as it was (code moved between files): instructions executed
# (valgrind's callgrind: Ir, deterministic where wall times are noisy) and wall and CPU
# seconds in alternating rounds, so that both builds see the same load on a shared
# machine.
#
#   bench/run_city_report_side_by_side.sh OLD_BUILD NEW_BUILD [ROUNDS]
#
# Each build is a release build folder holding cli/shadowgen, bench/clip_bench and
# bench/output_bench. Prints, as markdown:
#   - instructions per clip of clip_bench's small cases (BM_Shadowgen/64, two 64-vertex
#     stars; BM_GroundUnderBlocks/1024, a square under 1,024 blocks), from the calls of
#     shadowgen::clipper::clip under callgrind (the first call's allocations are spread
#     over the calls each run makes, which may differ by one or two);
#   - instructions of `report` on the 10,000-face city, one thread;
#   - the wall and CPU seconds of ROUNDS (default 5) alternating runs of `report` on the
#     100,000-face city, one thread, with medians and new ÷ old;
# and fails unless both builds' reports are the same byte for byte. KEEP=DIR keeps the
# cities, reports and callgrind files there (bench/city_work.sh).
set -euo pipefail
old=$1
new=$2
rounds=${3:-5}
source "$(dirname "$0")/city_work.sh"
work_folder

"$old/bench/output_bench" --write-database="cityscene:10000:$work/city1e4.json" >/dev/null
"$old/bench/output_bench" --write-database="cityscene:100000:$work/city1e5.json" >/dev/null

# Ir per call of shadowgen::clipper::clip from a benchmark function, from a callgrind file.
per_clip() {  # CALLGRIND_FILE BENCHMARK_NAME
  python3 - "$1" "$2" <<'PY'
import re, sys
path, caller = sys.argv[1], sys.argv[2]
names, fn, cfn, pending, calls, cost = {}, "", "", None, 0, 0
def name(spec):
    m = re.match(r"\((\d+)\)(?:\s+(.*))?$", spec.strip())
    if not m:
        return spec.strip()
    if m.group(2):
        names[m.group(1)] = m.group(2)
    return names.get(m.group(1), "")
for line in open(path):
    if line.startswith("fn="):
        fn = name(line[3:])
    elif line.startswith("cfn="):
        cfn = name(line[4:])
    elif line.startswith("calls="):
        pending = int(line[6:].split()[0])
    elif pending is not None:
        if caller in fn and "shadowgen::clipper::clip(" in cfn:
            calls += pending
            cost += int(line.split()[1])
        pending = None
print(f"{calls} {cost / calls:.0f}")
PY
}

echo "| clip_bench case | old: calls, Ir per clip | new: calls, Ir per clip | new ÷ old |"
echo "|---|---:|---:|---:|"
for build in old new; do
  dir=$old
  [[ $build == new ]] && dir=$new
  valgrind --tool=callgrind --callgrind-out-file="$work/clip.$build" "$dir/bench/clip_bench" \
    --benchmark_filter='BM_Shadowgen/64$|BM_GroundUnderBlocks/1024$' \
    --benchmark_min_time=0.2 >/dev/null 2>&1
done
for case in BM_Shadowgen BM_GroundUnderBlocks; do
  read -r oc oi < <(per_clip "$work/clip.old" "$case")
  read -r nc ni < <(per_clip "$work/clip.new" "$case")
  echo "| $case | $oc, $oi | $nc, $ni | $(python3 -c "print(f'{$ni / $oi:.4f}')") |"
done

echo
for build in old new; do
  dir=$old
  [[ $build == new ]] && dir=$new
  valgrind --tool=callgrind --callgrind-out-file="$work/report.$build" "$dir/cli/shadowgen" \
    report "$work/city1e4.json" --threads 1 --quiet -o "$work/r1e4.$build.csv" \
    2>"$work/valgrind.$build"
  ir[$([[ $build == old ]] && echo 0 || echo 1)]=$(grep -o 'Collected : [0-9]*' \
    "$work/valgrind.$build" | grep -o '[0-9]*')
done
cmp "$work/r1e4.old.csv" "$work/r1e4.new.csv"
echo "report, 10,000-face city, 1 thread: old ${ir[0]} Ir, new ${ir[1]} Ir," \
  "new ÷ old $(python3 -c "print(f'{${ir[1]} / ${ir[0]}:.4f}')")"

declare -A wall cpu
for round in $(seq "$rounds"); do
  for build in old new; do
    dir=$old
    [[ $build == new ]] && dir=$new
    /usr/bin/time -f "%e %U %S" -o "$work/time" "$dir/cli/shadowgen" report \
      "$work/city1e5.json" --threads 1 --quiet -o "$work/r1e5.$build.csv"
    read -r e u s <"$work/time"
    wall[$build]+="$e "
    cpu[$build]+="$(python3 -c "print(f'{$u + $s:.2f}')") "
    echo "round $round $build: $e s wall, $u + $s s CPU" >&2
  done
done
cmp "$work/r1e5.old.csv" "$work/r1e5.new.csv"

. "$(dirname "$0")/median.sh"
echo
echo "| report, 100,000-face city, 1 thread | old runs (s) | new runs (s) | old median | new median | new ÷ old |"
echo "|---|---|---|---:|---:|---:|"
for what in wall cpu; do
  if [[ $what == wall ]]; then o_runs=${wall[old]} n_runs=${wall[new]}; else o_runs=${cpu[old]} n_runs=${cpu[new]}; fi
  o=$(echo "$o_runs" | median)
  n=$(echo "$n_runs" | median)
  echo "| $what | $o_runs| $n_runs| $o | $n | $(python3 -c "print(f'{$n / $o:.3f}')") |"
done
echo
echo "reports byte-identical (1e4 and 1e5 cities); load average $(cut -d' ' -f1-3 /proc/loadavg)"
