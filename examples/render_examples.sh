#!/usr/bin/env bash
# Makes the example pictures: for each scene in examples/scenes, generate its shadowed
# database and draw its `main` view to <name>.svg; for a scene listed in sun_hours_maps
# below, also the sun-hours map of its sun path from that view, <name>-sun-hours.svg
# (render --sun-hours). The one way the pictures are made: the build target
# `example_pictures` runs it into examples/, and the end-to-end test
# (tests/cli/examples_cli_test.cpp) runs it into a temporary folder and compares the bytes
# with the pictures checked in.
#
#   examples/render_examples.sh SHADOWGEN [--out FOLDER] [--databases FOLDER] [NAME ...]
#
# SHADOWGEN is the built executable (e.g. build/release/cli/shadowgen). NAME is a scene's
# name (scenes/NAME.json), all of whose pictures are made; without any, every scene's. The
# pictures go to --out (default: examples/, beside this script); the databases to
# --databases when given (kept), else to a temporary folder (removed at the end). Usually
# run through
#
#   cmake --build --preset release --target example_pictures
set -euo pipefail

usage() {
  echo "usage: $0 SHADOWGEN [--out FOLDER] [--databases FOLDER] [NAME ...]" >&2
  exit 2
}

examples=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
shadowgen=
pictures=$examples
databases=
names=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --out)
      [[ $# -ge 2 ]] || usage
      pictures=$2
      shift 2
      ;;
    --databases)
      [[ $# -ge 2 ]] || usage
      databases=$2
      shift 2
      ;;
    -*) usage ;;
    *)
      if [[ -z $shadowgen ]]; then
        shadowgen=$1
      else
        names+=("$1")
      fi
      shift
      ;;
  esac
done
[[ -n $shadowgen ]] || usage
shadowgen=$(realpath "$shadowgen")
if [[ ! -x $shadowgen ]]; then
  echo "$0: $shadowgen is not an executable (build the target shadowgen first)" >&2
  exit 1
fi

# The scenes whose sun path gets a sun-hours map, and the path's id.
declare -A sun_hours_maps=([garden]=march21 [roof]=dec21)

if [[ ${#names[@]} -eq 0 ]]; then
  for scene in "$examples"/scenes/*.json; do
    names+=("$(basename "$scene" .json)")
  done
fi
for name in "${names[@]}"; do
  if [[ ! -f $examples/scenes/$name.json ]]; then
    echo "$0: no scene $examples/scenes/$name.json" >&2
    exit 1
  fi
done

mkdir -p "$pictures"
if [[ -n $databases ]]; then
  mkdir -p "$databases"
else
  databases=$(mktemp -d)
  trap 'rm -rf "$databases"' EXIT
fi

for name in "${names[@]}"; do
  database="$databases/$name.shadowed.json"
  "$shadowgen" generate "$examples/scenes/$name.json" -o "$database" --keep-instants --quiet
  "$shadowgen" render "$database" --view main --svg "$pictures/$name.svg"
  echo "$name: $pictures/$name.svg"
  if [[ -n ${sun_hours_maps[$name]:-} ]]; then
    "$shadowgen" render "$database" --view main --sun-hours "${sun_hours_maps[$name]}" \
      --svg "$pictures/$name-sun-hours.svg"
    echo "$name: $pictures/$name-sun-hours.svg"
  fi
done
