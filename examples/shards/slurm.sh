#!/usr/bin/env bash
#SBATCH --job-name=shadowgen-shard
#SBATCH --array=1-8
#SBATCH --cpus-per-task=1
#SBATCH --mem=1G
#SBATCH --time=04:00:00
#SBATCH --output=shadowgen-shard-%A_%a.log
#
# One shard of a sun-path run per task of a Slurm job array: task K runs
#
#   shadowgen generate SCENE -o OUT/shard-K.json.gz --instants K/SHARDS
#
# The array must be 1-SHARDS. submit-slurm.sh submits it so, and the merge after it, with
# each task's CPUs, memory and time limit from CPUS_PER_TASK, MEM_PER_TASK and
# TIME_PER_TASK (default: 1 CPU, 1G and 4 hours, as above: a small node gives them),
# having checked that the partition can give them; by hand, the options on the command
# line win over the #SBATCH lines above:
#
#   SCENE=city.json SHARDS=16 sbatch --array=1-16 --cpus-per-task=4 --mem=8G \
#     examples/shards/slurm.sh
#
# A task that failed is run again alone with --array=K (K its task id); its shard file
# is written whole or not at all, so the others stay as they are.
#
# Environment (sbatch passes the submitting shell's environment on to the job):
#   SCENE      the scene (default: scene.json), with its mesh files, where every node
#              reads it (a relative path is from the folder sbatch was run in)
#   SHARDS     N, the number of shards (default: 8): the array is 1-N
#   OUT        the folder of the shard files (default: shards), on a file system every
#              node writes to and the merge job reads
#   SHARD_FORMAT  json.gz (the default: each shard written as gzip, some 2.7 times smaller than
#              the text) or json (plain text); slurm-merge.sh reads the same setting
#   SHADOWGEN  the shadowgen command (default: shadowgen)
# Each shard runs with --threads SLURM_CPUS_PER_TASK (its --cpus-per-task).
set -euo pipefail

scene=${SCENE:-scene.json}
shards=${SHARDS:-8}
out=${OUT:-shards}
format=${SHARD_FORMAT:-json.gz}
shadowgen=${SHADOWGEN:-shadowgen}

if [[ $format != json && $format != json.gz ]]; then
  echo "slurm.sh: SHARD_FORMAT=$format: expected json.gz (gzip) or json (plain text)" >&2
  exit 2
fi
if [[ -z ${SLURM_ARRAY_TASK_ID:-} ]]; then
  echo "slurm.sh: not a task of a job array; submit it with sbatch --array=1-$shards" >&2
  exit 2
fi
k=$SLURM_ARRAY_TASK_ID
if ! [[ $shards =~ ^[1-9][0-9]*$ ]] || ((k < 1 || k > shards)); then
  echo "slurm.sh: array task $k is not a shard of SHARDS=$shards (the array must be 1-$shards)" >&2
  exit 2
fi

mkdir -p -- "$out"
echo "shard $k of $shards of $scene on $(hostname), --threads ${SLURM_CPUS_PER_TASK:-1}"
"$shadowgen" generate "$scene" -o "$out/shard-$k.$format" --instants "$k/$shards" \
  --threads "${SLURM_CPUS_PER_TASK:-1}"
