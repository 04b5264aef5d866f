#!/usr/bin/env bash
# Makes the example pictures: for each scene in examples/scenes, generate its shadowed
# database and draw its `main` view to <name>.svg; for a scene listed in sun_hours_maps
# (example_args.sh), also the sun-hours map of its sun path from that view,
# <name>-sun-hours.svg (render --sun-hours), and for one in sun_hours_plans that map as a
# plan from straight above, <name>-sun-hours-plan.svg (render --ortho). The one way the pictures are made: the build
# target `example_pictures` runs it into examples/, and the end-to-end test
# (tests/cli/examples_cli_test.cpp) runs it into a temporary folder and compares the bytes
# with the pictures checked in.
#
#   examples/render_examples.sh SHADOWGEN [--out FOLDER] [--databases FOLDER]
#                               [--weather FOLDER] [NAME ...]
#
# SHADOWGEN is the built executable (e.g. build/release/cli/shadowgen). NAME is a scene's
# name (scenes/NAME.json), all of whose pictures are made; without any, every scene's. The
# pictures go to --out (default: examples/, beside this script); the databases to
# --databases when given (kept), else to a temporary folder (removed at the end). A
# radiation map reads its weather file from --weather, the folder the build writes it to
# (BUILD/examples/weather, the target example_weather); a scene with one needs it. Usually
# run through
#
#   cmake --build --preset release --target example_pictures
#
# The command line is read by example_args.sh, as the other example scripts' are.
set -euo pipefail

example_options=(--out=FOLDER --databases=FOLDER --weather=FOLDER)
example_required=()
source "$(dirname "${BASH_SOURCE[0]}")/example_args.sh" "$@"
pictures=${option_values[--out]:-$examples}

weather=${option_values[--weather]:-}
for name in "${names[@]}"; do
  file=${radiation_weather[$name]:-}
  if [[ -n $file && ! -f $weather/$file ]]; then
    echo "$0: the radiation map of $name reads $file: give --weather FOLDER, the folder the" \
      "build writes it to (cmake --build --preset release --target example_weather:" \
      "build/release/examples/weather)" >&2
    exit 2
  fi
done

mkdir -p "$pictures"
databases_folder "${option_values[--databases]:-}"

for name in "${names[@]}"; do
  database="$databases/$name.shadowed.json"
  "$shadowgen" generate "$(scene_file "$name")" -o "$database" --keep-instants --quiet
  "$shadowgen" render "$database" --view main --svg "$pictures/$name.svg"
  echo "$name: $pictures/$name.svg"
  if [[ -n ${sun_hours_maps[$name]:-} ]]; then
    "$shadowgen" render "$database" --view main --sun-hours "${sun_hours_maps[$name]}" \
      --svg "$pictures/$name-sun-hours.svg"
    echo "$name: $pictures/$name-sun-hours.svg"
  fi
  if [[ -n ${sun_hours_plans[$name]:-} ]]; then
    centre=${sun_hours_plans[$name]}
    "$shadowgen" render "$database" --sun-hours "${sun_hours_maps[$name]}" --ortho \
      --target "$centre" --eye "${centre%,*},1000" --svg "$pictures/$name-sun-hours-plan.svg"
    echo "$name: $pictures/$name-sun-hours-plan.svg"
  fi
  if [[ -n ${radiation_maps[$name]:-} ]]; then
    "$shadowgen" render "$database" --view main --radiation "${radiation_maps[$name]}" \
      --weather "$weather/${radiation_weather[$name]}" --svg "$pictures/$name-radiation.svg"
    echo "$name: $pictures/$name-radiation.svg"
  fi
done
