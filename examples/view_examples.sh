#!/usr/bin/env bash
# Makes the example viewer pages: for each scene in examples/scenes, generate its shadowed
# database and write its page (`shadowgen view`) into FOLDER/<name>/; for a scene listed in
# sun_hours_maps (example_args.sh), also the page of its sun-hours map,
# FOLDER/<name>-sun-hours/.
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
# scene's. The command line is read by example_args.sh, as the other example scripts' are.
set -euo pipefail

example_options=(--out=FOLDER --screenshot=PNG)
example_required=(--out)
source "$(dirname "${BASH_SOURCE[0]}")/example_args.sh" "$@"
pages=${option_values[--out]}
screenshot=${option_values[--screenshot]:-}

mkdir -p "$pages"
databases_folder ""
for name in "${names[@]}"; do
  database="$databases/$name.shadowed.json"
  "$shadowgen" generate "$(scene_file "$name")" -o "$database" --keep-instants --quiet
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
