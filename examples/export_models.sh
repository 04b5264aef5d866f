#!/usr/bin/env bash
# Makes the example glTF models: for each scene in examples/scenes and the CityJSON
# district (examples/cityjson/district.json), its faces split by light sets as a binary
# glTF, <name>.glb (`shadowgen export -o`); for a scene listed in
# sun_hours_maps (example_args.sh), also its sun path's sun-hours map, <name>-sun-hours.glb. Run by
# the build target `example_models` into the build folder, and by the test
# gltf.validator, which checks every one with the Khronos glTF validator.
#
#   examples/export_models.sh SHADOWGEN --out FOLDER [NAME ...]
#
# SHADOWGEN is the built executable (e.g. build/release/cli/shadowgen). NAME is a scene's
# name (scenes/NAME.json, or district); without any, every scene's and the district's.
# The command line is read by example_args.sh, as the other example scripts' are.
set -euo pipefail

example_options=(--out=FOLDER)
example_required=(--out)
source "$(dirname "${BASH_SOURCE[0]}")/example_args.sh" "$@"
models=${option_values[--out]}
# Every scene's models include the CityJSON district's.
! $every_scene || names+=(district)

mkdir -p "$models"
databases_folder ""
for name in "${names[@]}"; do
  database="$databases/$name.shadowed.json"
  "$shadowgen" generate "$(scene_file "$name")" -o "$database" --quiet
  "$shadowgen" export "$database" -o "$models/$name.glb" --quiet
  echo "$name: $models/$name.glb"
  if [[ -n ${sun_hours_maps[$name]:-} ]]; then
    "$shadowgen" export "$database" --sun-hours "${sun_hours_maps[$name]}" \
      -o "$models/$name-sun-hours.glb" --quiet
    echo "$name: $models/$name-sun-hours.glb"
  fi
done
