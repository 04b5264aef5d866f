#!/usr/bin/env bash
# examples/shards/submit-slurm.sh against a real Slurm: a one-node cluster of the test's
# own (tests/cli/slurm_mini_cluster.sh) is started, then
#   - asked for more CPUs per task than its node has, more memory, or more time than a
#     partition allows, submit-slurm.sh exits 1 naming the setting to lower, and submits
#     nothing; likewise for settings that are not a count, a memory size or a time;
#   - with the defaults, a street's sun path of 71 instants (5 blocks of 16) in 4 shards
#     runs as a job array and its merge job, and the database merged is byte for byte
#     the one of a plain generate.
# The cluster and everything it ran are stopped at the end, whatever happens.
#
# Usage: slurm_cluster_test.sh SHADOWGEN EXAMPLES_SHARDS_DIR
#
# Exits 0 when every check holds, 1 when one fails, and 77 (ctest's SKIP_RETURN_CODE)
# when the cluster cannot start here (not root, Slurm or munge not installed, a daemon
# that does not start), printing why; with SHADOWGEN_SLURM_REQUIRED=1 (CI) that is a
# failure instead.
set -euo pipefail

[[ $# -eq 2 ]] || {
  echo "usage: $0 SHADOWGEN EXAMPLES_SHARDS_DIR" >&2
  exit 2
}
shadowgen=$(realpath -- "$1")
scripts=$(realpath -- "$2")
here=$(cd -- "$(dirname -- "$0")" && pwd)
# The bound on the wait for the jobs, in seconds (they take a few); with the cluster's
# start (slurm_cluster_start_wait) well under ctest's TIMEOUT.
jobs_wait=120

# Nothing of a surrounding Slurm job or of the user's sbatch defaults applies here.
while read -r name; do unset "$name"; done < <(compgen -e | grep -E '^(SLURM|SBATCH)_' || true)

# shellcheck source=tests/cli/slurm_mini_cluster.sh
source "$here/slurm_mini_cluster.sh"

dir=$(mktemp -d "${TMPDIR:-/tmp}/shadowgen-slurm.XXXXXX")
chmod 755 "$dir" # the cluster's munge socket is in it
finish() {
  local code=$?
  slurm_cluster_stop
  if [[ -n $(slurm_cluster_marked) ]]; then
    echo "FAIL: processes of the test's cluster still run after it stopped: $(slurm_cluster_marked | paste -sd ' ')"
    code=1
  fi
  # The daemons' logs and the jobs' are kept when something went wrong with them.
  if ((code == 0)) || [[ ! -e $dir/cluster/slurm.conf ]]; then
    rm -rf -- "$dir"
  else
    echo "(the cluster's and the jobs' files are kept in $dir)"
  fi
  exit "$code"
}
trap finish EXIT
trap 'exit 1' INT TERM

if ! slurm_cluster_start "$dir/cluster"; then
  if [[ ${SHADOWGEN_SLURM_REQUIRED:-} == 1 ]]; then
    echo "FAIL: the Slurm cluster could not start, and SHADOWGEN_SLURM_REQUIRED=1: $slurm_cluster_reason"
    exit 1
  fi
  echo "slurm_cluster skipped: the one-node Slurm cluster could not start: $slurm_cluster_reason"
  exit 77
fi
cpus=$(sinfo -h -N -p shards -o '%c')
memory=$(sinfo -h -N -p shards -o '%m')
echo "a one-node Slurm cluster: $cpus CPUs, $memory MB, SLURM_CONF=$SLURM_CONF"

failed=0
fail() {
  echo "FAIL: $*"
  failed=1
}

mkdir "$dir/run"
cd "$dir/run"
# A street between a 6 m block and an 8 m block in Edinburgh over 21 June 2026 every 15
# minutes: 71 instants with the sun up, 5 blocks of 16, so that each of 4 shards holds some.
cat >street.json <<'EOF'
{
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "street", "outer": [[0,0,0],[12,0,0],[12,30,0],[0,30,0]]},
    {"id": "west face", "outer": [[0,30,0],[0,0,0],[0,0,6],[0,30,6]]},
    {"id": "east face", "outer": [[12,0,0],[12,30,0],[12,30,8],[12,0,8]]}
  ],
  "site": {"latitude_deg": 55.9533, "longitude_deg": -3.1883, "utc_offset_h": 1},
  "lights": [{"id": "june21", "type": "sun", "from": "2026-06-21T00:00",
              "to": "2026-06-21T23:59", "step_min": 15}]
}
EOF

# submit-slurm.sh with the settings "$@" (NAME=VALUE), its stderr in $said; its exit code.
submit() {
  local code=0
  said=$(slurm_cluster_env env SCENE=street.json SHARDS=4 SHADOWGEN="$shadowgen" "$@" \
    bash "$scripts/submit-slurm.sh" 2>&1 >submitted) || code=$?
  return "$code"
}

# Asking what the node cannot give: exit 1, one line naming what to lower, nothing queued.
expect_refused() {
  local expected=$1 code=0
  shift
  submit "$@" || code=$?
  if ((code != 1)); then
    fail "$*: submit-slurm.sh exited $code, not 1 ($said)"
  elif [[ $said != "$expected" ]]; then
    fail "$*: submit-slurm.sh said '$said', not '$expected'"
  elif [[ -n $(squeue -h) || -e shards ]]; then
    fail "$*: submit-slurm.sh refused, but queued a job or made the shards' folder"
  else
    echo "ok: $* is refused: $said"
  fi
}
expect_refused "submit-slurm.sh: CPUS_PER_TASK=$((cpus + 1)): no node of partition 'shards' has $((cpus + 1)) CPUs (the most is $cpus): lower CPUS_PER_TASK" \
  CPUS_PER_TASK=$((cpus + 1))
expect_refused "submit-slurm.sh: MEM_PER_TASK=$((memory + 1))M: no node of partition 'shards' has $((memory + 1)) MB of memory for a shard (the most is $memory MB): lower MEM_PER_TASK" \
  MEM_PER_TASK=$((memory + 1))M
expect_refused "submit-slurm.sh: MERGE_MEM=$((memory + 1)): no node of partition 'shards' has $((memory + 1)) MB of memory for the merge (the most is $memory MB): lower MERGE_MEM" \
  MERGE_MEM=$((memory + 1))
expect_refused "submit-slurm.sh: TIME_PER_TASK=4:00:00 asks 14400 s, and partition 'short' runs a job 60 s at the most (its time limit, 1:00): lower TIME_PER_TASK" \
  SBATCH_PARTITION=short
expect_refused "submit-slurm.sh: MERGE_TIME=1:00:00 asks 3600 s, and partition 'short' runs a job 60 s at the most (its time limit, 1:00): lower MERGE_TIME" \
  SBATCH_PARTITION=short TIME_PER_TASK=1
# A limit that only the scheduler knows (the partition uses 1 CPU of a node, which has
# more): sbatch --test-only's answer.
if ((cpus >= 2)); then
  expect_refused "submit-slurm.sh: Slurm would not run the shards (--array=1-4 --cpus-per-task=2 --mem=1G --time=1) in partition 'short': allocation failure: Requested node configuration is not available" \
    SBATCH_PARTITION=short TIME_PER_TASK=1 MERGE_TIME=1 CPUS_PER_TASK=2
else
  echo "not checked: a partition's limit that only sbatch --test-only sees (the node has 1 CPU)"
fi
expect_refused "submit-slurm.sh: SHARD_FORMAT=xml: expected json.gz (gzip) or json (plain text)" \
  SHARD_FORMAT=xml
expect_refused "submit-slurm.sh: CPUS_PER_TASK=0: expected a positive whole number" CPUS_PER_TASK=0
expect_refused "submit-slurm.sh: MEM_PER_TASK=2GB: expected a memory size such as 500M or 2G (sbatch --mem)" \
  MEM_PER_TASK=2GB
expect_refused "submit-slurm.sh: TIME_PER_TASK=soon: expected a time limit such as 90, 4:00:00 or 1-12:00:00 (sbatch --time)" \
  TIME_PER_TASK=soon

# The defaults fit the node: 4 shards and their merge run, and give one generate's file.
if ! submit; then
  fail "submit-slurm.sh exited non-zero with the defaults: $said"
  exit 1
fi
merge_job=$(sed -n 's/.*merge: job \([0-9]*\),.*/\1/p' submitted)
[[ -n $merge_job ]] || {
  fail "submit-slurm.sh did not name the merge job: $(cat submitted)"
  exit 1
}
start=$SECONDS
while [[ -n $(squeue -h) ]]; do
  if ((SECONDS - start > jobs_wait)); then
    fail "the jobs still queued after $jobs_wait s: $(squeue -h -o '%i %T %r' | paste -sd ';')"
    exit 1
  fi
  sleep 0.25
done
state=$(scontrol show job "$merge_job" -o | grep -o 'JobState=[A-Z_]*' || true)
if [[ $state != JobState=COMPLETED ]]; then
  fail "the merge job $merge_job ended with '$state'; the jobs' logs:"
  tail -n 20 -- shadowgen-*.log || true
  exit 1
fi
"$shadowgen" generate street.json -o one-run.json -q
if cmp -- one-run.json street.shadowed.json; then
  echo "ok: the 4 shards merged by Slurm (job $merge_job, in $((SECONDS - start)) s) are byte for byte one generate's database"
else
  fail "the database merged by Slurm differs from one generate's"
fi
# The shards as the recipe writes them by default: gzip, each with gzip's magic bytes.
for k in 1 2 3 4; do
  magic=$(od -An -tx1 -N2 -- "shards/shard-$k.json.gz" 2>/dev/null | tr -d ' ' || true)
  if [[ $magic != 1f8b ]]; then
    fail "shards/shard-$k.json.gz is not a gzip file (first bytes '$magic'): $(ls shards | paste -sd ' ')"
  fi
done
[[ $failed == 1 ]] || echo "ok: the shards were written as gzip (shards/shard-K.json.gz) and merged"
exit "$failed"
