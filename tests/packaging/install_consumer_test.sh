#!/usr/bin/env bash
# Installs the build into a temporary prefix and checks what a user of it gets:
#  - the executable, the public headers alone (none naming a detail/ header), the library,
#    the CMake package and shadowgen.pc; no test or benchmark;
#  - examples/library, copied out of the source tree and built against the prefix alone
#    (CMAKE_PREFIX_PATH), prints the report CSV of an example scene byte for byte as
#    `shadowgen report` does;
#  - a one-file program built with `pkg-config --cflags --libs shadowgen` runs;
#  - where the Python module is built (PYTHON and its folder under the prefix given), it
#    imports from the prefix alone and examples/python/lit_areas.py, copied out of the
#    source tree, prints the same CSV as `shadowgen report`.
# Usage: install_consumer_test.sh SOURCE_DIR BUILD_DIR VERSION [PYTHON PYTHON_DIR]
set -euo pipefail
source_dir=$(realpath "$1")
build_dir=$(realpath "$2")
version=$3
python=${4:-}
python_dir=${5:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build_dir" --prefix "$prefix" >/dev/null
libdir=$(cd "$prefix" && dirname "$(find . -name libshadowgen.a)")
[[ -x $prefix/bin/shadowgen ]] || fail "no bin/shadowgen"
[[ -f $prefix/$libdir/cmake/shadowgen/shadowgenConfig.cmake ]] || fail "no CMake package"
[[ -f $prefix/$libdir/cmake/shadowgen/shadowgenConfigVersion.cmake ]] || fail "no version file"
[[ -f $prefix/$libdir/pkgconfig/shadowgen.pc ]] || fail "no shadowgen.pc"
headers=$(cd "$prefix/include" && find . -type f | sort | tr '\n' ' ')
expected="./shadowgen/api/errors.h ./shadowgen/api/outputs.h ./shadowgen/api/scene.h ./shadowgen/api/scene_data.h ./shadowgen/api/shadows.h ./shadowgen/api/version.h ./shadowgen/shadowgen.h "
[[ $headers == "$expected" ]] || fail "headers installed: $headers"
if grep -rn 'detail/' "$prefix/include" | grep '#include'; then fail "a public header includes detail/"; fi
if find "$prefix" -iname '*test*' -o -iname '*bench*' | grep .; then fail "tests or benchmarks installed"; fi
[[ $("$prefix/bin/shadowgen" --version) == "shadowgen $version" ]] || fail "shadowgen --version"

# The consumer, out of the source tree: only the prefix gives it shadowgen.
cp -r "$source_dir/examples/library" "$work/consumer"
cmake -S "$work/consumer" -B "$work/consumer-build" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
for tree in "$source_dir" "$build_dir"; do
  if grep -q -- "$tree" "$work/consumer-build/compile_commands.json" \
      "$work/consumer-build/CMakeFiles/shadowgen_report.dir/link.txt"; then
    fail "the consumer's build reaches into $tree"
  fi
done
cmake --build "$work/consumer-build" >/dev/null
scene=$source_dir/examples/scenes/courtyard.json
"$work/consumer-build/shadowgen_report" "$scene" > "$work/consumer.csv"
"$prefix/bin/shadowgen" report "$scene" --quiet > "$work/command.csv"
cmp "$work/consumer.csv" "$work/command.csv" || fail "the consumer's CSV differs from shadowgen report's"
[[ $(wc -l < "$work/consumer.csv") -gt 1 ]] || fail "an empty report"

# pkg-config, on a program of one file.
cat > "$work/version.cpp" <<'PROGRAM'
#include <cstring>
#include <iostream>
#include <shadowgen/shadowgen.h>
int main() {
  std::cout << shadowgen::api::version() << '\n';
  return std::strcmp(shadowgen::api::version(), SHADOWGEN_VERSION) == 0 ? 0 : 1;
}
PROGRAM
flags=$(PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig" pkg-config --cflags --libs shadowgen)
# shellcheck disable=SC2086
c++ -o "$work/version" "$work/version.cpp" $flags
[[ $("$work/version") == "$version" ]] || fail "the pkg-config program's version"

# The Python module, from the prefix alone (-s: no user site; the build folder is not on
# the path).
if [[ -z $python ]]; then
  echo "install, consumer and pkg-config: ok (no Python module built)"
  exit 0
fi
module_dir=$prefix/$python_dir
find "$module_dir" -maxdepth 1 -name 'shadowgen.*.so' | grep -q . || fail "no Python module in $python_dir"
[[ $(PYTHONPATH=$module_dir "$python" -s -c 'import shadowgen; print(shadowgen.__file__)') == "$module_dir"/* ]] ||
  fail "the module imported is not the prefix's"
cp "$source_dir/examples/python/lit_areas.py" "$work/lit_areas.py"
PYTHONPATH=$module_dir "$python" -s "$work/lit_areas.py" "$scene" > "$work/python.csv"
cmp "$work/python.csv" "$work/command.csv" || fail "the Python example's CSV differs from shadowgen report's"
echo "install, consumer, pkg-config and Python module: ok"
