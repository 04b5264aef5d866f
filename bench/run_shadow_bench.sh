#!/usr/bin/env bash
# Builds shadow_bench and prints, as markdown, the median CPU time of generate_shadows
# (one thread, one light) per workload, with the light's own seconds, the lit detail
# polygon count, the peak resident memory of a process that runs the workload once, and
# the log-log slope of time against faces for the city.
#
#   bench/run_shadow_bench.sh [--no-build] [extra Google Benchmark flags...]
#
# BUILD_DIR (default build/release) and REPETITIONS (default 5) as in run_hsr_bench.sh;
# the 1e5-face city takes about a minute per sun run, so REPETITIONS=3 is the practical
# choice, or leave it out of the timed run (--benchmark_filter='-BM_CitySun/100000') and
# read its light's seconds from its memory run. Peak memory: one
# `shadow_bench --peak-rss=...` process per workload (PEAK_RSS_WORKLOADS, default all),
# after the timed run.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/run_benchmark.sh"
run_benchmark shadow_bench "$@"
build=$BENCH_BUILD
json=$BENCH_JSON
load=$BENCH_LOAD
binary="$build/bench/shadow_bench"
load_mid="$(cut -d' ' -f1-3 /proc/loadavg)"

rss="$build/bench/shadow_bench.rss"
: >"$rss"
for w in ${PEAK_RSS_WORKLOADS:-city:1000:sun city:1000:lamp city:10000:sun city:10000:lamp \
  city:100000:sun city:100000:lamp cubes:2000:sun cubes:2000:lamp}; do
  "$binary" --peak-rss="$w" | sed "s/^/$w /" >>"$rss"
done

python3 - "$json" "$rss" "$load" "$load_mid" <<'PY'
import json, math, re, sys

path, rss_path, load, load_mid = sys.argv[1:5]
report = json.load(open(path))
rows = {}
for b in report["benchmarks"]:
    if b.get("error_occurred"):
        rows[b["run_name"]] = {"error": b.get("error_message", "failed")}
    elif b.get("aggregate_name") == "median":
        rows[b["run_name"]] = b
peak = {}
for line in open(rss_path):
    m = re.match(r"(\S+) .*scene built (\d+) kB, peak (\d+) kB", line)
    if m:
        peak[m.group(1)] = (int(m.group(2)), int(m.group(3)))
reps = next((b["repetitions"] for b in rows.values() if "repetitions" in b), "?")
with open("/proc/loadavg") as f:
    after = " ".join(f.read().split()[:3])
print(f"{report['context'].get('date', '?')}; load average (1, 5, 15 min) {load} before the "
      f"timed run, {load_mid} after it, {after} after the memory runs. Median of {reps} "
      f"repetitions (one generate_shadows call each).")
print()
print("| scene | light | faces | CPU time | light's seconds | faces in range | frusta | fragments | lit detail polygons | lit fraction | peak RSS (scene alone) | slope from previous size |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
work = [("BM_CitySun", "city", "sun", [1000, 10000, 100000]),
        ("BM_CityLamp", "city", "lamp", [1000, 10000, 100000]),
        ("BM_CubesSun", "cubes", "sun", [2000]),
        ("BM_CubesLamp", "cubes", "lamp", [2000])]
for bench, scene, light, sizes in work:
    prev = None
    for size in sizes:
        key = f"{bench}/{size}/iterations:1"
        b = rows.get(key)
        if b is None:
            continue
        if "error" in b:
            print(f"| {scene} | {light} | {size} | failed: {b['error']} |||||||||")
            continue
        t = b["cpu_time"] * {"ms": 1e-3, "s": 1.0, "us": 1e-6, "ns": 1e-9}[b["time_unit"]]
        slope = ""
        if prev:
            slope = f"{math.log(t / prev[1]) / math.log(b['faces'] / prev[0]):.2f}"
        prev = (b["faces"], t)
        base, top = peak.get(f"{scene}:{size}:{light}", (0, 0))
        print(f"| {'2000 cubes on ground' if scene == 'cubes' else scene} | {light} | {b['faces']:.0f} | {t:.3g} s | "
              f"{b['light_s']:.3g} s | {b['considered']:.0f} | {b['frusta']:.0f} | "
              f"{b['fragments']:.0f} | {b['detail_polygons']:.0f} | {b['lit_fraction']:.3f} | "
              f"{top / 1024:.0f} MiB ({base / 1024:.0f}) | {slope} |")
PY
