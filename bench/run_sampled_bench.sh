#!/usr/bin/env bash
# Builds sampled_bench and prints, as markdown, the accuracy ladder: per scene and light,
# the median CPU time and the lit-area error of shadowgen's exact generator, of shadow
# maps (N × N, k × k samples per face) and of shadow rays (k × k samples per face), all
# measured in one run.
#
#   bench/run_sampled_bench.sh [--no-build] [extra Google Benchmark flags...]
#
# BUILD_DIR (default build/release) and REPETITIONS (default 5) as in run_hsr_bench.sh.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/run_benchmark.sh"
run_benchmark sampled_bench "$@"
build=$BENCH_BUILD
json=$BENCH_JSON
load=$BENCH_LOAD

python3 - "$json" "$load" <<'PY'
import json, sys

path, load = sys.argv[1], sys.argv[2]
report = json.load(open(path))
to_ms = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
rows = []
for b in report["benchmarks"]:
    if b.get("aggregate_name") != "median" and not b.get("error_occurred"):
        continue
    parts = b["run_name"].split("/")
    args = [int(p) for p in parts[1:] if p.isdigit()]
    rows.append((parts[0], args, b))
order = {"BM_Exact": 0, "BM_ShadowMap": 1, "BM_ShadowRays": 2}
rows.sort(key=lambda r: (order[r[0]], r[1]))
reps = next((b["repetitions"] for _, _, b in rows if "repetitions" in b), "?")
with open("/proc/loadavg") as f:
    after = " ".join(f.read().split()[:3])
print(f"{report['context'].get('date', '?')}; load average (1, 5, 15 min) {load} before the "
      f"run, {after} after. Median CPU time of {reps} repetitions; error = Σ|estimated − exact "
      f"lit area| / total area.")
scenes = {0: "city, 1014 faces", 1: "2000 cubes on a ground, 13271 faces"}
lights = {0: "sun", 1: "lamp"}
method = {"BM_Exact": "shadowgen exact", "BM_ShadowMap": "shadow map", "BM_ShadowRays": "shadow rays"}
for s in scenes:
    for l in lights:
        print()
        print(f"**{scenes[s]}, {lights[l]}**")
        print()
        print("| method | resolution | CPU time | × exact time | lit-area error |")
        print("|---|---|---:|---:|---:|")
        exact = None
        for name, args, b in rows:
            if args[:2] == [s, l] and name == "BM_Exact" and not b.get("error_occurred"):
                exact = b["cpu_time"] * to_ms[b["time_unit"]]
        for name, args, b in rows:
            if args[:2] != [s, l]:
                continue
            res = {"BM_Exact": "exact", "BM_ShadowMap": f"N={args[2:][0] if len(args) > 2 else '?'}, k={args[3] if len(args) > 3 else '?'}",
                   "BM_ShadowRays": f"k={args[2] if len(args) > 2 else '?'}"}[name]
            if b.get("error_occurred"):
                print(f"| {method[name]} | {res} | failed: {b.get('error_message')} | | |")
                continue
            t = b["cpu_time"] * to_ms[b["time_unit"]]
            cell = f"{t:.3g} ms" if t < 1000 else f"{t / 1000:.3g} s"
            ratio = f"{t / exact:.3f}" if exact else "n/a"
            print(f"| {method[name]} | {res} | {cell} | {ratio} | {b['lit_area_err']:.1e} |")
PY
