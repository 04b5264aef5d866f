#!/usr/bin/env bash
# Builds the Debian package (cpack -G DEB) from the build, unpacks it into a throw-away
# root (dpkg -x) and runs the command from there, and checks the package's declared
# Depends: the libraries the command loads (dpkg-shlibdeps) and the -dev packages the
# library's users link. Where the Python module is built (PYTHON, its folder under the
# prefix and the source tree given), the package holds it and depends on python3 and
# python3-numpy, and examples/python/lit_areas.py run with the unpacked module prints the
# CSV the unpacked command does. Skips (77) without dpkg-deb and dpkg-shlibdeps (dpkg-dev).
# Usage: deb_test.sh BUILD_DIR VERSION [PYTHON PYTHON_DIR SOURCE_DIR]
set -euo pipefail
build_dir=$(realpath "$1")
version=$2
python=${3:-}
python_dir=${4:-}
source_dir=${5:-}
for tool in dpkg-deb dpkg-shlibdeps; do
  command -v "$tool" >/dev/null || { echo "no $tool (dpkg-dev): skipped"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

(cd "$work" && cpack -G DEB --config "$build_dir/CPackConfig.cmake" -B "$work/out" >/dev/null)
deb=$(find "$work/out" -maxdepth 1 -name "shadowgen_${version}_*.deb")
[[ -n $deb ]] || fail "no shadowgen_${version}_*.deb"
[[ $(dpkg-deb -f "$deb" Package) == shadowgen ]] || fail "package name"
[[ $(dpkg-deb -f "$deb" Version) == "$version" ]] || fail "package version"
[[ -n $(dpkg-deb -f "$deb" Maintainer) ]] || fail "no maintainer"
description=$(dpkg-deb -f "$deb" Description)
[[ $description == "exact polygon shadows"* && $description != *";"* ]] || fail "description: $description"
depends=$(dpkg-deb -f "$deb" Depends)
for package in libc6 libstdc++6 libproj25 libembree3-3 libtinygltf-dev libproj-dev libembree-dev; do
  [[ $depends == *"$package"* ]] || fail "Depends lacks $package: $depends"
done

root=$work/root
dpkg -x "$deb" "$root"
for file in usr/bin/shadowgen usr/include/shadowgen/shadowgen.h usr/include/shadowgen/api/version.h; do
  [[ -f $root/$file ]] || fail "no /$file in the package"
done
find "$root/usr/lib" -name libshadowgen.a | grep -q . || fail "no libshadowgen.a in the package"
find "$root/usr/lib" -name shadowgenConfig.cmake | grep -q . || fail "no CMake package in the package"
find "$root/usr/lib" -name shadowgen.pc | grep -q . || fail "no shadowgen.pc in the package"
[[ $("$root/usr/bin/shadowgen" --version) == "shadowgen $version" ]] || fail "shadowgen --version"

if [[ -z $python ]]; then
  echo "package $(basename "$deb"): ok (no Python module built)"
  exit 0
fi
for package in python3 python3-numpy; do
  [[ $depends =~ (^|", ")$package( |,|$) ]] || fail "Depends lacks $package: $depends"
done
module_dir=$root/usr/$python_dir
find "$module_dir" -maxdepth 1 -name 'shadowgen.*.so' | grep -q . || fail "no Python module in /usr/$python_dir"
scene=$source_dir/examples/scenes/courtyard.json
"$root/usr/bin/shadowgen" report "$scene" --quiet > "$work/command.csv"
PYTHONPATH=$module_dir "$python" -s "$source_dir/examples/python/lit_areas.py" "$scene" > "$work/python.csv"
cmp "$work/python.csv" "$work/command.csv" || fail "the unpacked Python module's CSV differs from the command's"
echo "package $(basename "$deb") with the Python module: ok"
