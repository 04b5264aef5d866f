#!/usr/bin/env bash
# The roof example (scenes/roof.json: a house with six solar panels raised above its south
# roof, a chimney, a taller neighbour to the south-east) over a whole year of hourly sun,
# as EnergyPlus reads a shading schedule: the sunlit fraction of every face at every hour
# of 2026 (Schedule:File:Shading; docs/scene-format.md, "Shading schedule for EnergyPlus").
#
#   examples/roof-year.sh SHADOWGEN OUT.csv
#
# The scene's own sun path is 21 December (its pictures); this script gives the same faces
# and site a path over the year, from 2026-01-01T00:00 to 2026-12-31T23:00 every 60
# minutes, in a temporary scene, and writes the schedule from it. A report on a scene
# makes only what the report needs: here each instant's lit areas, not the sun-hours
# regions, so the year costs about what its instants' shadows cost.
set -euo pipefail

if [[ $# -ne 2 ]]; then
  echo "usage: $0 SHADOWGEN OUT.csv" >&2
  exit 2
fi
shadowgen=$1
out=$2
examples=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$examples/scenes/roof.json" "$work/roof-year.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["lights"] = [{"id": "year", "type": "sun", "from": "2026-01-01T00:00",
                    "to": "2026-12-31T23:00", "step_min": 60}]
json.dump(scene, open(sys.argv[2], "w"), indent=1)
PY
"$shadowgen" report "$work/roof-year.json" --format energyplus -o "$out" --quiet
