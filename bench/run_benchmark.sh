# Sourced by the bench/run_*_bench.sh scripts: what they share.
#
#   run_benchmark TARGET [--no-build] [extra Google Benchmark flags...]
#
# Builds TARGET (unless --no-build) in BUILD_DIR (default build/release, configured by
# the release preset; another folder is used as configured), then runs it the way
# bench/run_clip_bench.sh does: REPETITIONS (default 5) repetitions in random interleaved
# order, aggregates only, JSON kept in $BENCH_BUILD/bench/TARGET.json. Sets BENCH_BUILD,
# BENCH_JSON and BENCH_LOAD (the load averages before the run), and leaves the shell in
# the repository root.

run_benchmark() {
  local target=$1
  shift
  cd "$(dirname "${BASH_SOURCE[0]}")/.."
  BENCH_BUILD="${BUILD_DIR:-build/release}"
  if [[ "${1:-}" == "--no-build" ]]; then
    shift
  else
    [[ "$BENCH_BUILD" == build/release ]] && cmake --preset release >&2
    cmake --build "$BENCH_BUILD" -j2 --target "$target" >&2
  fi
  BENCH_JSON="$BENCH_BUILD/bench/$target.json"
  BENCH_LOAD="$(cut -d' ' -f1-3 /proc/loadavg)"
  "$BENCH_BUILD/bench/$target" \
    --benchmark_repetitions="${REPETITIONS:-5}" \
    --benchmark_report_aggregates_only=true \
    --benchmark_enable_random_interleaving=true \
    --benchmark_out="$BENCH_JSON" --benchmark_out_format=json "$@" >&2
}
