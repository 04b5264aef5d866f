#!/usr/bin/env bash
# Submits a sun-path run to Slurm: the shards as a job array (slurm.sh), then the merge
# (slurm-merge.sh) as a job that starts once every task of the array has succeeded.
#
# Usage: SCENE=city.json SHARDS=16 examples/shards/submit-slurm.sh
#
# Environment: SCENE, SHARDS, OUT, DATABASE and SHADOWGEN as slurm.sh and slurm-merge.sh
# read them (exported here, so that both jobs see the same), and
#   MAX_RUNNING  at most this many shards running at a time (default: no limit)
#
# If a shard fails, the merge job is cancelled (--kill-on-invalid-dep=yes). Run the
# failed task again alone, then the merge:
#
#   sbatch --array=K examples/shards/slurm.sh
#   sbatch --dependency=afterok:NEWJOBID examples/shards/slurm-merge.sh
set -euo pipefail

here=$(cd -- "$(dirname -- "$0")" && pwd)
export SCENE=${SCENE:-scene.json}
export SHARDS=${SHARDS:-8}
export OUT=${OUT:-shards}
export SHADOWGEN=${SHADOWGEN:-shadowgen}
if [[ -n ${DATABASE:-} ]]; then export DATABASE; fi

[[ -f $SCENE ]] || { echo "submit-slurm.sh: $SCENE: no such file" >&2; exit 1; }
mkdir -p -- "$OUT"

array=1-$SHARDS${MAX_RUNNING:+%$MAX_RUNNING}
# --parsable prints JOBID, or JOBID;CLUSTER on a federation.
shards_job=$(sbatch --parsable --array="$array" "$here/slurm.sh")
shards_job=${shards_job%%;*}
merge_job=$(sbatch --parsable --dependency=afterok:"$shards_job" --kill-on-invalid-dep=yes \
  "$here/slurm-merge.sh")
merge_job=${merge_job%%;*}

echo "shards: job array $shards_job, tasks $array; merge: job $merge_job, once they all succeed"
