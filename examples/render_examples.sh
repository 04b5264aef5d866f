#!/usr/bin/env bash
# Remakes the example pictures: for every scene in examples/scenes, generate its shadowed
# database and draw its `main` view to examples/<name>.svg.
#
#   examples/render_examples.sh SHADOWGEN [DATABASE_FOLDER]
#
# SHADOWGEN is the built executable (e.g. build/release/cli/shadowgen). The databases go to
# DATABASE_FOLDER when given (kept), else to a temporary folder (removed at the end).
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 SHADOWGEN [DATABASE_FOLDER]" >&2
  exit 2
fi
shadowgen=$(realpath "$1")
examples=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [[ $# -eq 2 ]]; then
  databases=$2
  mkdir -p "$databases"
else
  databases=$(mktemp -d)
  trap 'rm -rf "$databases"' EXIT
fi

for scene in "$examples"/scenes/*.json; do
  name=$(basename "$scene" .json)
  database="$databases/$name.shadowed.json"
  "$shadowgen" generate "$scene" -o "$database"
  "$shadowgen" render "$database" --view main --svg "$examples/$name.svg"
  echo "$name: $examples/$name.svg"
done
