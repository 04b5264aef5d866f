#!/usr/bin/env bash
# Computes a scene's sun paths as N shards on this machine, a few at a time, then joins
# them with shadowgen merge into the database one plain generate writes.
#
# Usage: examples/shards/run-local.sh SCENE N OUT.json
#
# OUT.json.gz writes the database as gzip, and the shards too (shard-K.json.gz): zcat gives
# the plain file byte for byte.
#
# Environment (all optional):
#   SHADOWGEN    the shadowgen command (default: shadowgen)
#   JOBS         shards running at a time (default: the number of cores)
#   THREADS      --threads of each shard (default: the cores shared among the shards
#                running at a time, at least 1)
#   SHARDS_DIR   where the shard files go (default: a new folder next to OUT.json,
#                removed at the end); a folder given here is kept
#   CHECK=1      also run one plain generate and compare its database with OUT.json (cmp)
#
# Each shard's messages go to a log next to its file; a shard that fails has its log
# printed, the shards still running are stopped, and the script exits with the shard's
# exit code. Needs bash 4.3 or later (wait -n).
set -euo pipefail

usage() {
  echo "usage: $0 SCENE N OUT.json  (N: the number of shards, 1 to 1000000)" >&2
  exit 2
}
[[ $# -eq 3 ]] || usage
scene=$1
shards=$2
out=$3
suffix=.json
if [[ $out == *.gz ]]; then suffix=.json.gz; fi
if ! [[ $shards =~ ^[1-9][0-9]{0,6}$ ]] || ((shards > 1000000)); then usage; fi
[[ -f $scene ]] || { echo "$0: $scene: no such file" >&2; exit 1; }

shadowgen=${SHADOWGEN:-shadowgen}
cores=$(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN)
max_jobs=${JOBS:-$cores}
[[ $max_jobs =~ ^[1-9][0-9]*$ ]] || { echo "$0: JOBS=$max_jobs: expected a positive whole number" >&2; exit 2; }
at_once=$((max_jobs < shards ? max_jobs : shards))
threads=${THREADS:-$((cores / at_once > 0 ? cores / at_once : 1))}

if [[ -n ${SHARDS_DIR:-} ]]; then
  dir=$SHARDS_DIR
  mkdir -p -- "$dir"
  made_dir=
else
  dir=$(mktemp -d "$(dirname -- "$out")/shadowgen-shards.XXXXXX")
  made_dir=$dir
fi

# Each shard runs in its own process group (job control), so that it can be stopped
# whole: the subshell and the shadowgen it runs.
set -m

# On any exit: stop the shards still running (this script's own, by process group), and
# remove the folder this script made.
cleanup() {
  local pgid
  for pgid in $(jobs -pr); do
    kill -TERM -- "-$pgid" 2>/dev/null || true
  done
  { wait || true; } 2>/dev/null # without the shell's "Terminated" notices
  if [[ -n $made_dir ]]; then rm -rf -- "$made_dir"; fi
}
trap cleanup EXIT

# Shard k of N, its messages in its log; on failure the log is shown.
run_shard() {
  local k=$1 rc=0
  "$shadowgen" generate "$scene" -o "$dir/shard-$k$suffix" --instants "$k/$shards" \
    --threads "$threads" 2>"$dir/shard-$k.log" || rc=$?
  if ((rc != 0)); then
    echo "$0: shard $k of $shards failed (exit code $rc):" >&2
    cat -- "$dir/shard-$k.log" >&2
    return "$rc"
  fi
}

# Seconds since the epoch, to a microsecond where bash has it (5.0 on).
now() { if [[ -n ${EPOCHREALTIME:-} ]]; then echo "${EPOCHREALTIME/,/.}"; else date +%s; fi; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

echo "$shards shards of $scene, $at_once at a time, --threads $threads each, into $dir" >&2
start=$(now)
running=0
files=()
for ((k = 1; k <= shards; k++)); do
  if ((running >= max_jobs)); then
    wait -n # a shard that failed ends the script here (set -e)
    running=$((running - 1))
  fi
  run_shard "$k" &
  running=$((running + 1))
  files+=("$dir/shard-$k$suffix")
done
while ((running > 0)); do
  wait -n
  running=$((running - 1))
done
# The scene's reading warnings, once (every shard reads the same scene).
if [[ -s $dir/shard-1.log ]]; then cat -- "$dir/shard-1.log" >&2; fi
echo "shards done in $(since "$start") s; merging" >&2

merge_start=$(now)
"$shadowgen" merge "${files[@]}" -o "$out" -q
echo "merged into $out in $(since "$merge_start") s (shards and merge: $(since "$start") s)" >&2

if [[ ${CHECK:-0} == 1 ]]; then
  start=$(now)
  "$shadowgen" generate "$scene" -o "$dir/one-run$suffix" -q
  echo "one plain generate: $(since "$start") s" >&2
  if cmp -- "$dir/one-run$suffix" "$out"; then
    echo "check: $out is byte for byte the database of one plain generate" >&2
  else
    echo "check: $out differs from the database of one plain generate" >&2
    exit 1
  fi
fi
