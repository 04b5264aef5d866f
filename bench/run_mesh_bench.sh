#!/usr/bin/env bash
# Builds mesh_bench and prints, as markdown, shadowgen's exact generator against Embree
# casting 1024 stratified shadow rays per face, one core each, on real meshes above a
# ground under a sun and a lamp: per mesh and light the median CPU times (Embree one ray
# per call and in packets of 16), the ratios, and Embree's errors against the exact
# result (the same for both ways of casting), all measured in one run.
#
#   bench/run_mesh_bench.sh [--no-build] [extra Google Benchmark flags...]
#
# BUILD_DIR (default build/release) and REPETITIONS (default 5) as in run_hsr_bench.sh.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/run_benchmark.sh"
run_benchmark mesh_bench "$@"

python3 - "$BENCH_JSON" "$BENCH_LOAD" <<'PY'
import json, sys

path, load = sys.argv[1], sys.argv[2]
report = json.load(open(path))
to_ms = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
runs = {}
for b in report["benchmarks"]:
    # the median, or the run itself when there is one repetition (and so no aggregate)
    if b.get("aggregate_name") not in ("median", None):
        continue
    name, mesh, light = b["run_name"].split("/")[:3]
    key = (name, int(mesh), int(light))
    if b.get("aggregate_name") == "median" or key not in runs:
        runs[key] = b
reps = next((b["repetitions"] for b in runs.values() if "repetitions" in b), "?")
with open("/proc/loadavg") as f:
    after = " ".join(f.read().split()[:3])
print(f"{report['context'].get('date', '?')}; load average (1, 5, 15 min) {load} before the "
      f"run, {after} after. Median CPU time of {reps} repetitions, one core each.")
print()
print("| mesh | faces | light | partly shadowed | exact | Embree, 1 ray | exact ÷ it "
      "| Embree, 16-ray packets | exact ÷ it | mean frac. err | max frac. err | area err |")
print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
lights = ["sun", "lamp"]

def ms(b):
    return b["cpu_time"] * to_ms[b["time_unit"]]

def cell(t):
    return f"{t:.3g} ms" if t < 1000 else f"{t / 1000:.3g} s"

for m in sorted({k[1] for k in runs}):
    for l in sorted({k[2] for k in runs if k[1] == m}):
        ex, em, em16 = (runs.get((n, m, l)) for n in ("BM_Exact", "BM_Embree", "BM_Embree16"))
        label = f"{(ex or {}).get('label', m)} | "
        failed = [b for b in (ex, em, em16) if b is None or b.get("error_occurred")]
        if failed:
            why = "; ".join(b.get("error_message", "?") for b in failed if b)
            print(f"| {label}| {lights[l]} | failed: {why or 'missing'} | | | | | | | | |")
            continue
        print(f"| {label}{ex['faces']:.0f} | {lights[l]} | {100 * ex['partly']:.0f} % "
              f"| {cell(ms(ex))} | {cell(ms(em))} | {ms(ex) / ms(em):.2f} "
              f"| {cell(ms(em16))} | {ms(ex) / ms(em16):.2f} "
              f"| {em['frac_err_mean']:.1e} | {em['frac_err_max']:.1e} | {em['area_err']:.1e} |")
PY
