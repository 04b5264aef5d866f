#!/usr/bin/env bash
# Builds the fuzz targets (CMake preset "fuzz": clang, libFuzzer, ASan, UBSan) and runs
# each on a scratch copy of its seed corpus, so the checked-in corpora never change:
#   clip     clip_fuzzer (clipper/clip.h), corpus/clip/;
#   readers  reader_fuzzer (scene JSON, OBJ, STL, OFF, PLY, the database), corpus/readers/.
#
#   tests/fuzz/run_fuzz.sh [SECONDS] [LIBFUZZER_FLAG...]      (default 60 seconds)
#
# SECONDS is the whole run, split evenly between the targets, which run one after the
# other, or side by side, each for its same share, with SHADOWGEN_FUZZ_PARALLEL=1 (a
# core each, as on CI's two; each target's output is printed once it ends). Exits
# non-zero when a fuzzer finds a crash (both run all the same); the crashing input is
# kept in build/fuzz/artifacts/, named clip-* or readers-* (the fuzzer prints it as
# well). Extra flags go to libFuzzer, for every target, e.g. -jobs=2 or -only_ascii=1.
# Environment:
#   SHADOWGEN_FUZZ_TARGETS="clip readers"   the targets to run, in this order;
#   SHADOWGEN_FUZZ_SKIP=name,...            skips checks that guard a bug already reported
#                                           (clip_fuzzer.cpp, reader_fuzzer.cpp);
#   SHADOWGEN_FUZZ_BUILD_DIR=DIR            build there instead of build/fuzz.
# Long reader runs go about 1.5 times as fast in a build whose geometry traces no
# comparisons (tests/fuzz/CMakeLists.txt), with short allocation stacks:
#   cmake --preset fuzz -B build/fuzz-fast -DSHADOWGEN_FUZZ_GEOMETRY_TRACE_CMP=OFF
#   cmake --build build/fuzz-fast --target reader_fuzzer
#   ASAN_OPTIONS=malloc_context_size=2 build/fuzz-fast/tests/fuzz/reader_fuzzer \
#     -seed=N -max_len=65536 -timeout=60 CORPUS_COPY
# Beside such processes, ones built with UndefinedBehaviorSanitizer alone
# (-DSHADOWGEN_FUZZ_SANITIZERS=undefined) run about 1.6 times as fast again, but miss
# the memory errors that do not crash. A process paused (SIGSTOP) for longer than
# -timeout reports a timeout when it resumes: stop it (SIGINT) and start another instead.
set -euo pipefail

seconds=${1:-60}
shift || true
case $seconds in
  '' | *[!0-9]*) echo "usage: $0 [SECONDS] [LIBFUZZER_FLAG...]" >&2; exit 2 ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
build=${SHADOWGEN_FUZZ_BUILD_DIR:-build/fuzz}
read -r -a targets <<<"${SHADOWGEN_FUZZ_TARGETS:-clip readers}"
binaries=()
for target in "${targets[@]}"; do
  case $target in
    clip) binaries+=(clip_fuzzer) ;;
    readers) binaries+=(reader_fuzzer) ;;
    *) echo "run_fuzz.sh: unknown target '$target' (clip, readers)" >&2; exit 2 ;;
  esac
done
if [ "${#targets[@]}" -eq 0 ]; then
  echo "run_fuzz.sh: SHADOWGEN_FUZZ_TARGETS names no target" >&2
  exit 2
fi

cmake --preset fuzz -B "$build"
cmake --build "$build" -j2 --target "${binaries[@]}"

work=$(mktemp -d "${TMPDIR:-/tmp}/shadowgen_fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
artifacts=$build/artifacts
mkdir -p "$artifacts"
share=$((seconds / ${#targets[@]}))
[ "$share" -ge 1 ] || share=1

parallel=${SHADOWGEN_FUZZ_PARALLEL:-0}
# Runs one target for its share; its exit status is the fuzzer's.
run_target() {
  local target=$1 binary corpus flags
  case $target in
    # -max_len: the clip fuzzer's input format reads at most a few hundred bytes; the
    # readers take a scene or mesh of up to 64 KiB. -timeout: seconds for one input.
    clip) binary=clip_fuzzer corpus=clip flags=(-max_len=2048 -timeout=30) ;;
    # The readers' dictionary spells the formats' keys and values (readers.dict).
    readers)
      binary=reader_fuzzer corpus=readers
      flags=(-max_len=65536 -timeout=10 -dict=tests/fuzz/readers.dict)
      ;;
  esac
  echo "== run_fuzz.sh: $binary for $share s"
  cp -R "tests/fuzz/corpus/$corpus" "$work/$corpus"
  "$build/tests/fuzz/$binary" "$work/$corpus" \
    -max_total_time="$share" "${flags[@]}" -print_final_stats=1 \
    -artifact_prefix="$artifacts/$target-" "${@:2}"
}

status=0
failed=()
pids=()
for target in "${targets[@]}"; do
  if [ "$parallel" = 1 ]; then
    run_target "$target" "$@" >"$work/$target.log" 2>&1 &
    pids+=($!)
    continue
  fi
  one=0
  run_target "$target" "$@" || one=$?
  if [ "$one" -ne 0 ]; then
    status=$one
    failed+=("$target (status $one)")
  fi
done
for i in "${!pids[@]}"; do
  one=0
  wait "${pids[$i]}" || one=$?
  cat "$work/${targets[$i]}.log"
  if [ "$one" -ne 0 ]; then
    status=$one
    failed+=("${targets[$i]} (status $one)")
  fi
done

if [ "$status" -ne 0 ]; then
  echo "run_fuzz.sh: failed: ${failed[*]}; crashing inputs in $artifacts/:" >&2
  ls -t "$artifacts" >&2 || true
fi
exit "$status"
