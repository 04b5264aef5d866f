#!/usr/bin/env bash
# Builds the release preset's clip_bench and prints the medians of 5 repetitions as
# markdown: CPU time per tool and size, shadowgen's time as a fraction of each other
# tool's, and the relative area error against CGAL's exact result.
#
#   bench/run_clip_bench.sh [--no-build] [extra Google Benchmark flags...]
#
# The JSON of the run is kept in build/release/bench/clip_bench.json. The machine has
# few cores and may be shared: the build uses -j2, the repetitions of all benchmarks are
# run in random interleaved order (so a burst of load from elsewhere hits every tool
# alike rather than one), CPU time rather than wall time is reported, and the load
# averages before and after the run are printed with the table.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

if [[ "${1:-}" == "--no-build" ]]; then
  shift
else
  cmake --preset release >&2
  cmake --build --preset release -j2 --target clip_bench >&2
fi

binary=build/release/bench/clip_bench
json=build/release/bench/clip_bench.json
load="$(cut -d' ' -f1-3 /proc/loadavg)"

"$binary" \
  --benchmark_repetitions=5 \
  --benchmark_report_aggregates_only=true \
  --benchmark_enable_random_interleaving=true \
  --benchmark_out="$json" \
  --benchmark_out_format=json \
  "$@" >&2

python3 - "$json" "$load" <<'PY'
import json
import sys

path, load = sys.argv[1], sys.argv[2]
with open(path) as f:
    report = json.load(f)

tools = [  # (benchmark, column title)
    ("BM_Shadowgen", "shadowgen"),
    ("BM_Clipper1", "Clipper 1 (PolyTree)"),
    ("BM_Clipper1Paths", "Clipper 1 (Paths)"),
    ("BM_Geos", "GEOS"),
    ("BM_Cgal", "CGAL Epeck"),
]
to_us = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}

median_us, error, failure, sizes, repetitions = {}, {}, {}, set(), "?"
for b in report["benchmarks"]:
    name, _, size = b["run_name"].partition("/")
    size = int(size)
    sizes.add(size)
    if b.get("error_occurred"):
        failure[(name, size)] = b.get("error_message", "failed")
        continue
    if b.get("run_type") != "aggregate" or b.get("aggregate_name") != "median":
        continue
    median_us[(name, size)] = b["cpu_time"] * to_us[b["time_unit"]]
    repetitions = b.get("repetitions", repetitions)
    if "rel_area_err" in b:
        error[(name, size)] = b["rel_area_err"]

def time_cell(key):
    if key in median_us:
        t = median_us[key]
        return f"{t:.3g} µs" if t < 1000 else f"{t / 1000:.3g} ms"
    return "failed" if key in failure else "n/a"

def ratio_cell(size, other):
    ours, theirs = median_us.get(("BM_Shadowgen", size)), median_us.get((other, size))
    return f"{ours / theirs:.2f}" if ours and theirs else "n/a"

ctx = report["context"]
with open("/proc/loadavg") as f:
    load_after = " ".join(f.read().split()[:3])
print(f"Host {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs at "
      f"{ctx.get('mhz_per_cpu', '?')} MHz, {ctx.get('date', '?')}; "
      f"load average (1, 5, 15 min) {load} before the run, {load_after} after.")
print()
print(f"Median CPU time of {repetitions} repetitions, inside and outside pieces of one pair:")
print()
print("| vertices per polygon | " + " | ".join(t for _, t in tools) + " |")
print("|---:|" + "---:|" * len(tools))
for size in sorted(sizes):
    print(f"| {size} | " + " | ".join(time_cell((b, size)) for b, _ in tools) + " |")
print()
print("shadowgen's time ÷ the other tool's (below 1: shadowgen is faster):")
print()
print("| vertices per polygon | " + " | ".join(t for _, t in tools[1:]) + " |")
print("|---:|" + "---:|" * (len(tools) - 1))
for size in sorted(sizes):
    print(f"| {size} | " + " | ".join(ratio_cell(size, b) for b, _ in tools[1:]) + " |")
print()
print("Relative area error of inside + outside against CGAL's exact result:")
print()
accurate = [(b, t) for b, t in tools if b != "BM_Clipper1Paths"]
print("| vertices per polygon | " + " | ".join(t for _, t in accurate) + " |")
print("|---:|" + "---:|" * len(accurate))
for size in sorted(sizes):
    cells = [f"{error[(b, size)]:.1e}" if (b, size) in error else "n/a" for b, _ in accurate]
    print(f"| {size} | " + " | ".join(cells) + " |")
for (name, size), message in sorted(failure.items()):
    print(f"\n{name}/{size} failed: {message}")
PY
