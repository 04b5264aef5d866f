# The work folder and the procedural city as a scene with one sun path, for the
# benchmark scripts that run the command on a district; sourced, with `build` set to a
# build folder holding bench/output_bench.
#
#   work_folder
#       sets `work`: the folder KEEP names (made where missing), else a temporary folder
#       removed when the script exits.
#   city_sun_scene FACES SCENE FROM TO STEP_MIN
#       writes the city of FACES faces (bench/scenes/city.h) as $work/city.db.json, kept
#       where REUSE is set and the file is there, and SCENE from it at Greenwich with one
#       sun path, "path" (bench/city_sun_scene.py); prints that script's line: the middle
#       of the city's box in x and y and a height above it, for a camera looking down.

bench_folder=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

work_folder() {
  if [ -n "${KEEP:-}" ]; then
    work=$KEEP
    mkdir -p "$work"
  else
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
  fi
}

city_sun_scene() {
  local faces=$1 scene=$2 from=$3 to=$4 step=$5
  [ -f "$work/city.db.json" ] && [ -n "${REUSE:-}" ] ||
    "$build/bench/output_bench" --write-database="city:$faces:$work/city.db.json" >/dev/null
  python3 "$bench_folder/city_sun_scene.py" "$work/city.db.json" "$scene" "$from" "$to" "$step"
}
