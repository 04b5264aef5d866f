#!/usr/bin/env bash
# Makes the example viewer pages: for each scene in examples/scenes, generate its shadowed
# database and write its page (`shadowgen view`) into FOLDER/<name>/; for a scene with a
# sun path listed below, also the page of its sun-hours map, FOLDER/<name>-sun-hours/.
# With --screenshot PNG, the garden's sun-hours page is then opened in headless Chromium
# (web/test/viewer_check.mjs) and its picture written to PNG: the README's picture of the
# viewer, examples/viewer.png. The build target `example_viewer_pages` runs it into the
# build folder, with --screenshot examples/viewer.png; the end-to-end test
# (tests/cli/view_cli_test.cpp) runs it for each scene into a temporary folder and opens
# every page it made.
#
#   examples/view_examples.sh SHADOWGEN --out FOLDER [--screenshot PNG] [NAME ...]
#
# SHADOWGEN is the built executable (e.g. build/release/cli/shadowgen), whose page assets
# the build put beside it. NAME is a scene's name (scenes/NAME.json); without any, every
# scene's.
set -euo pipefail

usage() {
  echo "usage: $0 SHADOWGEN --out FOLDER [--screenshot PNG] [NAME ...]" >&2
  exit 2
}

examples=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
shadowgen=
pages=
screenshot=
names=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --out)
      [[ $# -ge 2 ]] || usage
      pages=$2
      shift 2
      ;;
    --screenshot)
      [[ $# -ge 2 ]] || usage
      screenshot=$2
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
[[ -n $shadowgen && -n $pages ]] || usage

# The scenes whose sun path gets a sun-hours page, and the path's id (as the pictures'
# render_examples.sh has them).
declare -A sun_hours_maps=([garden]=march21 [roof]=dec21)

if [[ ${#names[@]} -eq 0 ]]; then
  for scene in "$examples"/scenes/*.json; do
    names+=("$(basename "$scene" .json)")
  done
fi
mkdir -p "$pages"
databases=$(mktemp -d)
trap 'rm -rf "$databases"' EXIT
for name in "${names[@]}"; do
  database="$databases/$name.shadowed.json"
  "$shadowgen" generate "$examples/scenes/$name.json" -o "$database" --keep-instants --quiet
  "$shadowgen" view "$database" -o "$pages/$name"
  echo "$name: $pages/$name/index.html"
  if [[ -n ${sun_hours_maps[$name]:-} ]]; then
    "$shadowgen" view "$database" --sun-hours "${sun_hours_maps[$name]}" -o "$pages/$name-sun-hours"
    echo "$name: $pages/$name-sun-hours/index.html"
  fi
done

if [[ -n $screenshot ]]; then
  node "$examples/../web/test/viewer_check.mjs" "$pages/garden-sun-hours" --width 960 \
    --height 600 --screenshot "$screenshot" >/dev/null
  echo "screenshot: $screenshot"
fi
