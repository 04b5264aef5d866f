#!/usr/bin/env bash
# Makes the example glTF models: for each scene in examples/scenes and the CityJSON
# district (examples/cityjson/district.json), its faces split by light sets as a binary
# glTF, <name>.glb (`shadowgen export -o`); for a scene listed in
# sun_hours_maps below, also its sun path's sun-hours map, <name>-sun-hours.glb. Run by
# the build target `example_models` into the build folder, and by the test
# gltf.validator, which checks every one with the Khronos glTF validator.
#
#   examples/export_models.sh SHADOWGEN --out FOLDER
#
# SHADOWGEN is the built executable (e.g. build/release/cli/shadowgen).
set -euo pipefail

usage() {
  echo "usage: $0 SHADOWGEN --out FOLDER" >&2
  exit 2
}

examples=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[[ $# -eq 3 && $2 == --out ]] || usage
shadowgen=$(realpath "$1")
models=$3
if [[ ! -x $shadowgen ]]; then
  echo "$0: $shadowgen is not an executable (build the target shadowgen first)" >&2
  exit 1
fi

# The scenes whose sun path gets a sun-hours map, and the path's id.
declare -A sun_hours_maps=([garden]=march21 [roof]=dec21 [district]=march21)

mkdir -p "$models"
databases=$(mktemp -d)
trap 'rm -rf "$databases"' EXIT
for scene in "$examples"/scenes/*.json "$examples"/cityjson/district.json; do
  name=$(basename "$scene" .json)
  database="$databases/$name.shadowed.json"
  "$shadowgen" generate "$scene" -o "$database" --quiet
  "$shadowgen" export "$database" -o "$models/$name.glb" --quiet
  echo "$name: $models/$name.glb"
  if [[ -n ${sun_hours_maps[$name]:-} ]]; then
    "$shadowgen" export "$database" --sun-hours "${sun_hours_maps[$name]}" \
      -o "$models/$name-sun-hours.glb" --quiet
    echo "$name: $models/$name-sun-hours.glb"
  fi
done
