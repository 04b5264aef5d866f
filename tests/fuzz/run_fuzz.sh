#!/usr/bin/env bash
# Builds the clip fuzzer (CMake preset "fuzz": clang, libFuzzer, ASan, UBSan) and runs it
# on a scratch copy of the seed corpus, so the checked-in corpus never changes.
#
#   tests/fuzz/run_fuzz.sh [SECONDS] [LIBFUZZER_FLAG...]      (default 60 seconds)
#
# Exits non-zero when the fuzzer finds a crash; the crashing input is kept in
# build/fuzz/artifacts/ (the fuzzer prints it decoded as well). Extra flags go to
# libFuzzer, e.g. -jobs=2 or -only_ascii=1; SHADOWGEN_FUZZ_SKIP=name,... in the
# environment skips checks that guard a bug already reported (clip_fuzzer.cpp).
set -euo pipefail

seconds=${1:-60}
shift || true
case $seconds in
  '' | *[!0-9]*) echo "usage: $0 [SECONDS] [LIBFUZZER_FLAG...]" >&2; exit 2 ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
cmake --preset fuzz
cmake --build --preset fuzz -j2 --target clip_fuzzer

work=$(mktemp -d "${TMPDIR:-/tmp}/clip_fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp -R tests/fuzz/corpus/clip "$work/corpus"
artifacts=build/fuzz/artifacts
mkdir -p "$artifacts"

status=0
build/fuzz/tests/fuzz/clip_fuzzer "$work/corpus" \
  -max_total_time="$seconds" -max_len=2048 -timeout=30 -print_final_stats=1 \
  -artifact_prefix="$artifacts/" "$@" || status=$?

if [ "$status" -ne 0 ]; then
  echo "run_fuzz.sh: the fuzzer failed (status $status); crashing inputs in $artifacts/:" >&2
  ls -t "$artifacts" >&2 || true
fi
exit "$status"
