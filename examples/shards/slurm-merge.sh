#!/usr/bin/env bash
#SBATCH --job-name=shadowgen-merge
#SBATCH --cpus-per-task=1
#SBATCH --mem=1G
#SBATCH --time=01:00:00
#SBATCH --output=shadowgen-merge-%j.log
#
# Joins the shards that slurm.sh wrote into the shadowed database of the whole run:
#
#   shadowgen merge OUT/shard-1.json.gz ... OUT/shard-SHARDS.json.gz -o DATABASE
#
# Submit it to start when every task of the shards' array has succeeded (submit-slurm.sh
# does both, with the CPUs from CPUS_PER_TASK, the memory from MERGE_MEM and the time
# limit from MERGE_TIME):
#
#   sbatch --dependency=afterok:JOBID examples/shards/slurm-merge.sh
#
# with JOBID the array's job id; --cpus-per-task, --mem and --time on that command line
# win over the #SBATCH lines above (merge holds every shard at once: give it their memory). merge
# refuses, naming the file, shards missing or given twice, shards of another count or
# another scene, and a whole database among them.
#
# Environment (as for slurm.sh):
#   SCENE      the scene (default: scene.json): only its name is used here
#   SHARDS     N, the number of shards (default: 8)
#   OUT        the folder of the shard files (default: shards)
#   SHARD_FORMAT  json.gz (default) or json: the shard files' ending, as slurm.sh wrote
#              them (merge reads either by its content)
#   DATABASE   the database to write (default: NAME.shadowed.json for the scene NAME.json,
#              in the folder sbatch was run in; a name ending in .gz writes gzip)
#   SHADOWGEN  the shadowgen command (default: shadowgen)
set -euo pipefail

scene=${SCENE:-scene.json}
shards=${SHARDS:-8}
out=${OUT:-shards}
name=$(basename -- "$scene")
database=${DATABASE:-${name%.json}.shadowed.json}
format=${SHARD_FORMAT:-json.gz}
shadowgen=${SHADOWGEN:-shadowgen}

files=()
for ((k = 1; k <= shards; k++)); do
  files+=("$out/shard-$k.$format")
done

echo "merging $shards shards from $out into $database, --threads ${SLURM_CPUS_PER_TASK:-1}"
"$shadowgen" merge "${files[@]}" -o "$database" --threads "${SLURM_CPUS_PER_TASK:-1}"
