#!/usr/bin/env bash
# Builds hsr_bench and prints, as markdown, the median CPU time of hidden-surface removal
# and its fragment counts per workload and size, with the log-log slope of time against
# the number of polygons (between neighbouring sizes, and the least-squares fit over all).
#
#   bench/run_hsr_bench.sh [--no-build] [extra Google Benchmark flags...]
#
# BUILD_DIR (default build/release, the release preset's) names the build folder; with
# another folder it is used as configured. Conventions of bench/run_clip_bench.sh: -j2,
# 5 repetitions (REPETITIONS) in random interleaved order, CPU time, load averages
# before and after printed with the table. The JSON is kept in $BUILD_DIR/bench/.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/run_benchmark.sh"
run_benchmark hsr_bench "$@"
build=$BENCH_BUILD
json=$BENCH_JSON
load=$BENCH_LOAD

python3 - "$json" "$load" <<'PY'
import json, math, sys

path, load = sys.argv[1], sys.argv[2]
report = json.load(open(path))
to_ms = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
rows, failure = {}, {}
for b in report["benchmarks"]:
    name, _, size = b["run_name"].partition("/")
    if b.get("error_occurred"):
        failure[(name, int(size))] = b.get("error_message", "failed")
        continue
    if b.get("aggregate_name") != "median":
        continue
    rows[(name, int(size))] = b
reps = next(iter(rows.values()))["repetitions"] if rows else "?"
titles = {
    "BM_HsrCubesOrtho": "cube grid, oblique orthographic view",
    "BM_HsrCubesPerspective": "cube grid, perspective view",
    "BM_HsrSoup": "random triangles, oblique orthographic view",
}
with open("/proc/loadavg") as f:
    after = " ".join(f.read().split()[:3])
ctx = report["context"]
print(f"Host {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs, {ctx.get('date', '?')}; "
      f"load average (1, 5, 15 min) {load} before the run, {after} after. "
      f"Median CPU time of {reps} repetitions.")
print()
print("| workload | size | polygons | CPU time | fragments | zero-area fragments | clips | depth errors | slope from previous size |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for name, title in titles.items():
    sizes = sorted(s for (n, s) in list(rows) + list(failure) if n == name)
    pts = []
    for size in sizes:
        if (name, size) in failure:
            print(f"| {title} | {size} | | failed: {failure[(name, size)]} | | | | | |")
            continue
        b = rows[(name, size)]
        t = b["cpu_time"] * to_ms[b["time_unit"]]
        n = b["polygons"]
        slope = ""
        if pts:
            slope = f"{math.log(t / pts[-1][1]) / math.log(n / pts[-1][0]):.2f}"
        pts.append((n, t))
        cell = f"{t:.3g} ms" if t < 1000 else f"{t / 1000:.3g} s"
        print(f"| {title} | {size} | {n:.0f} | {cell} | {b['fragments']:.0f} | "
              f"{b['zero_area_fragments']:.0f} | {b['clips']:.0f} | {b['depth_errors']:.0f} | {slope} |")
    if len(pts) >= 2:
        xs = [math.log(n) for n, _ in pts]
        ys = [math.log(t) for _, t in pts]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        fit = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        print(f"| {title}: least-squares slope | | | | | | | | {fit:.2f} |")
PY
