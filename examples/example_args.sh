# The command line of the scripts that make the examples' outputs (render_examples.sh,
# view_examples.sh, export_models.sh), read in one place. Sourced, not run:
#
#   example_options=(--out=FOLDER --databases=FOLDER)  # the options it takes, with their value
#   example_required=(--out)                           # those it cannot do without
#   source "$(dirname "${BASH_SOURCE[0]}")/example_args.sh" "$@"
#
# reads SHADOWGEN [OPTION VALUE ...] [NAME ...] (options and names in any order) into
#   examples        this folder, absolute
#   shadowgen       the executable, absolute, checked to be one
#   option_values   the value given to each option, by option ("--out" -> FOLDER)
#   names           the scenes asked for (NAME: scenes/NAME.json, or district: the CityJSON
#                   district, cityjson/district.json), each checked to exist; every scene in
#                   scenes/ where none is named
#   every_scene     true where no name was given, else false
#   sun_hours_maps  the scenes whose sun path gets a sun-hours map, and the path's id
#   sun_hours_plans those of them whose map is also drawn as a plan, and its centre
#   radiation_maps  the scenes whose sun path gets a radiation map, and the path's id;
#   radiation_weather  the weather file of each, relative to the folder of weather files
#                   the build makes (BUILD/examples/weather: the target example_weather)
# and gives scene_file NAME (the scene's file) and databases_folder FOLDER (FOLDER made,
# or where FOLDER is empty a temporary folder removed when the script ends). A usage
# mistake prints the usage line and exits 2; a missing executable or scene exits 1.

examples=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

declare -A sun_hours_maps=([garden]=march21 [roof]=dec21 [district]=march21)
# The scenes whose sun-hours map is also drawn as a plan, from straight above in an
# orthographic view (north arrow and scale bar): the point X,Y,Z the plan looks down on,
# the middle of the scene's box.
declare -A sun_hours_plans=([garden]=5,9,0 [roof]=5,2.5,0)
# The scenes whose sun path also gets a radiation map (render --radiation), and the weather
# file it reads, in the folder the build writes them to: a synthetic clear sky at the
# scene's site (weather/clear_sky_epw.py, run by the target example_weather).
declare -A radiation_maps=([garden]=march21)
declare -A radiation_weather=([garden]=greenwich-clear-sky.epw)

example_usage() {
  local line="usage: $0 SHADOWGEN"
  local spec
  for spec in "${example_options[@]}"; do
    if [[ " ${example_required[*]} " == *" ${spec%%=*} "* ]]; then
      line+=" ${spec%%=*} ${spec#*=}"
    else
      line+=" [${spec%%=*} ${spec#*=}]"
    fi
  done
  echo "$line [NAME ...]" >&2
  exit 2
}

scene_file() {
  if [[ $1 == district ]]; then
    echo "$examples/cityjson/district.json"
  else
    echo "$examples/scenes/$1.json"
  fi
}

# Sets `databases` to FOLDER (made) or, where FOLDER is empty, to a temporary folder that
# is removed when the script ends.
databases_folder() {
  if [[ -n $1 ]]; then
    databases=$1
    mkdir -p "$databases"
  else
    databases=$(mktemp -d)
    trap 'rm -rf "$databases"' EXIT
  fi
}

shadowgen=
declare -A option_values=()
names=()
while [[ $# -gt 0 ]]; do
  case $1 in
    -*)
      [[ " ${example_options[*]} " == *" $1="* && $# -ge 2 ]] || example_usage
      option_values[$1]=$2
      shift 2
      ;;
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
[[ -n $shadowgen ]] || example_usage
for option in "${example_required[@]}"; do
  [[ -n ${option_values[$option]:-} ]] || example_usage
done
shadowgen=$(realpath "$shadowgen")
if [[ ! -x $shadowgen ]]; then
  echo "$0: $shadowgen is not an executable (build the target shadowgen first)" >&2
  exit 1
fi

every_scene=false
if [[ ${#names[@]} -eq 0 ]]; then
  every_scene=true
  for scene in "$examples"/scenes/*.json; do
    names+=("$(basename "$scene" .json)")
  done
fi
for name in "${names[@]}"; do
  if [[ ! -f $(scene_file "$name") ]]; then
    echo "$0: no scene $(scene_file "$name")" >&2
    exit 1
  fi
done
