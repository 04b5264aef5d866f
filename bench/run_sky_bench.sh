#!/usr/bin/env bash
# The sky on a district against its sun path: the procedural city (bench/scenes/city.h)
# written as a scene at Greenwich with one `sun` path (bench/city_sun_scene.py), then
# REPETITIONS rounds of, in turn, `report --format sky` (every face's sky view factor: one
# light per patch of the subdivision), `report --format radiation` over the path's year
# where the binary has it (its --help names it; WEATHER names the EPW file, else a
# synthetic one is written), and the sun path alone (`generate --areas-only`, the lit
# areas the EnergyPlus schedule and irradiation read). Each run's wall, user and system
# seconds and peak memory; medians, and each one's CPU seconds per light.
#
#   bench/run_sky_bench.sh [FACES] [SKY] [FROM] [TO] [STEP_MIN]
#
# Defaults: 30000 faces, the report's default sky (SKY empty; else tregenza or reinhart:N),
# a year of hourly sun, 2026-01-01T00:00 to 2026-12-31T23:00 every 60 minutes. BUILD_DIR
# (default build/release) must hold cli/shadowgen and bench/output_bench
# (SHADOWGEN_BENCH=ON). Environment: THREADS (default 2); REPETITIONS (default 3); KEEP=
# FOLDER keeps the scene and the outputs there; WORKLOADS (default "sky radiation sun", those
# the binary has) the ones to run.
set -euo pipefail

faces=${1:-30000}
sky=${2:-}
from=${3:-2026-01-01T00:00}
to=${4:-2026-12-31T23:00}
step=${5:-60}
build=${BUILD_DIR:-build/release}
threads=${THREADS:-2}
repetitions=${REPETITIONS:-3}
shadowgen=$build/cli/shadowgen
. "$(dirname "$0")/city_work.sh"
work_folder

city_sun_scene "$faces" "$work/scene.json" "$from" "$to" "$step" >/dev/null
instants=$("$shadowgen" sun "$work/scene.json" | tail -n +2 | wc -l)
sky_args=()
[ -n "$sky" ] && sky_args=(--sky "$sky")
patches=$(python3 - "$sky" <<'PY'
import sys
name = sys.argv[1] or "reinhart:8"  # the report's default
n = 1 if name == "tregenza" else int(name.split(":")[1])
print(144 * n * n + 1)
PY
)
workloads=(sky sun)
radiation=()
if "$shadowgen" report --help | grep -qw radiation; then
  weather=${WEATHER:-}
  if [ -z "$weather" ]; then
    weather=$work/synthetic.epw
    python3 - "$weather" <<'PY'
# A synthetic year at Greenwich: the 8 header lines, then 8760 hourly rows whose direct
# normal and diffuse horizontal irradiance follow the sun's height by day and alternate
# clear and overcast days; enough for the radiation report's time, not its values.
import math, sys
rows = ["LOCATION,Greenwich,,GBR,synthetic,000000,51.4779,-0.0015,0.0,10.0",
        "DESIGN CONDITIONS,0", "TYPICAL/EXTREME PERIODS,0", "GROUND TEMPERATURES,0",
        "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0", "COMMENTS 1,synthetic", "COMMENTS 2,synthetic",
        "DATA PERIODS,1,1,Data,Thursday, 1/ 1,12/31"]
days = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]
n = 0
for month, count in enumerate(days, 1):
    for day in range(1, count + 1):
        n += 1
        declination = 23.44 * math.sin(2 * math.pi * (284 + n) / 365)
        for hour in range(1, 25):
            angle = math.radians(15 * (hour - 0.5 - 12))
            lat, dec = math.radians(51.48), math.radians(declination)
            s = math.sin(lat) * math.sin(dec) + math.cos(lat) * math.cos(dec) * math.cos(angle)
            clear = n % 2 == 0
            dni = max(0.0, 800 * s) if clear else 0.0
            dhi = max(0.0, (120 if clear else 250) * s)
            ghi = dni * max(s, 0) + dhi
            rows.append("2026,%d,%d,%d,0,?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9?9?9,10.0,6.0,80,"
                        "101300,0,0,300,%d,%d,%d,0,0,0,0,240,4.0,5,5,20.0,77777,9,999999999,0,"
                        "0.1,0,88,0.2,0.0,0.0" % (month, day, hour, ghi, dni, dhi))
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
PY
  fi
  radiation=(--weather "$weather")
  workloads=(sky radiation sun)
fi

run() {  # WORKLOAD ROUND: one timed run, "wall user sys peak_kb" appended to its file
  local args
  case $1 in
    sky) args=(report "$work/scene.json" --format sky "${sky_args[@]}" -o "$work/sky.csv") ;;
    radiation)
      args=(report "$work/scene.json" --format radiation "${sky_args[@]}" "${radiation[@]}"
        -o "$work/radiation.csv") ;;
    sun) args=(generate "$work/scene.json" --areas-only -o "$work/sun.db.json") ;;
  esac
  /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$shadowgen" "${args[@]}" --threads "$threads" \
    --quiet
  cat "$work/time" >>"$work/$1.times"
}

[ -n "${WORKLOADS:-}" ] && read -r -a workloads <<<"$WORKLOADS"

for ((round = 1; round <= repetitions; round++)); do
  for workload in "${workloads[@]}"; do run "$workload" "$round"; done
done

echo "city of $faces faces, $threads thread(s), $repetitions round(s): the sky of $patches" \
  "patches (${sky:-the default}); the sun path $from to $to every $step min, $instants" \
  "instants with the sun up"
echo
echo "| workload | lights | wall s (median) | CPU s (user+sys, median) | CPU s per light | peak MB |"
echo "|---|---:|---:|---:|---:|---:|"
for workload in "${workloads[@]}"; do
  case $workload in
    sky) lights=$patches ;;
    radiation) lights=$((patches + instants)) ;;
    sun) lights=$instants ;;
  esac
  python3 - "$work/$workload.times" "$workload" "$lights" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])]
wall = statistics.median(float(r[0]) for r in rows)
cpu = statistics.median(float(r[1]) + float(r[2]) for r in rows)
peak = statistics.median(int(r[3]) for r in rows) / 1024
lights = int(sys.argv[3])
print("| %s | %d | %.1f | %.1f | %.4f | %.0f |" % (sys.argv[2], lights, wall, cpu, cpu / lights, peak))
PY
done
