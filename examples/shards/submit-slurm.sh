#!/usr/bin/env bash
# Submits a sun-path run to Slurm: the shards as a job array (slurm.sh), then the merge
# (slurm-merge.sh) as a job that starts once every task of the array has succeeded.
#
# Usage: SCENE=city.json SHARDS=16 examples/shards/submit-slurm.sh
#
# Environment: SCENE, SHARDS, OUT, SHARD_FORMAT, DATABASE and SHADOWGEN as slurm.sh and
# slurm-merge.sh read them (exported here, so that both jobs see the same), and
#   CPUS_PER_TASK  CPUs of each shard and of the merge, their --threads (default: 1)
#   MEM_PER_TASK   memory of each shard, as sbatch --mem takes it: a whole number of
#                  megabytes, or with the suffix K, M, G or T (default: 1G)
#   MERGE_MEM      memory of the merge, which holds every shard at once (default:
#                  MEM_PER_TASK)
#   TIME_PER_TASK  time limit of each shard, as sbatch --time takes it: MINUTES,
#                  MINUTES:SECONDS, HOURS:MINUTES:SECONDS, DAYS-HOURS,
#                  DAYS-HOURS:MINUTES or DAYS-HOURS:MINUTES:SECONDS (default: 4:00:00)
#   MERGE_TIME     time limit of the merge (default: 1:00:00)
#   MAX_RUNNING    at most this many shards running at a time (default: no limit)
# These override the #SBATCH lines of the two scripts. The jobs go to SBATCH_PARTITION
# (sbatch's own variable), or to the cluster's default partition.
#
# Before submitting anything, it checks that a node of the partition has CPUS_PER_TASK
# CPUs and the memory asked, that the partition's time limit allows the time asked, and
# that Slurm would run both jobs (sbatch --test-only: a QOS's or a partition's other
# limits): a job asking what the partition cannot give would stay pending for ever. If
# not, it says which setting to lower and submits nothing.
#
# If a shard fails, the merge job is cancelled (--kill-on-invalid-dep=yes). Run the
# failed task again alone, then the merge:
#
#   sbatch --array=K --cpus-per-task=C --mem=M --time=T examples/shards/slurm.sh
#   sbatch --dependency=afterok:NEWJOBID --cpus-per-task=C --mem=M --time=T \
#     examples/shards/slurm-merge.sh
set -euo pipefail

here=$(cd -- "$(dirname -- "$0")" && pwd)
export SCENE=${SCENE:-scene.json}
export SHARDS=${SHARDS:-8}
export OUT=${OUT:-shards}
export SHARD_FORMAT=${SHARD_FORMAT:-json.gz}
export SHADOWGEN=${SHADOWGEN:-shadowgen}
if [[ -n ${DATABASE:-} ]]; then export DATABASE; fi
cpus=${CPUS_PER_TASK:-1}
mem=${MEM_PER_TASK:-1G}
merge_mem=${MERGE_MEM:-$mem}
time=${TIME_PER_TASK:-4:00:00}
merge_time=${MERGE_TIME:-1:00:00}

fail() {
  echo "submit-slurm.sh: $*" >&2
  exit 1
}

[[ $SHARD_FORMAT == json || $SHARD_FORMAT == json.gz ]] ||
  fail "SHARD_FORMAT=$SHARD_FORMAT: expected json.gz (gzip) or json (plain text)"
[[ $cpus =~ ^[1-9][0-9]*$ ]] || fail "CPUS_PER_TASK=$cpus: expected a positive whole number"
# Megabytes of a memory size as sbatch --mem reads it (no suffix: megabytes), rounded up.
megabytes() {
  local name=$1 size=$2
  [[ $size =~ ^([1-9][0-9]*)([KkMmGgTt]?)$ ]] ||
    fail "$name=$size: expected a memory size such as 500M or 2G (sbatch --mem)"
  local n=${BASH_REMATCH[1]}
  case ${BASH_REMATCH[2]} in
    K | k) echo $(((n + 1023) / 1024)) ;;
    G | g) echo $((n * 1024)) ;;
    T | t) echo $((n * 1024 * 1024)) ;;
    *) echo "$n" ;;
  esac
}
mem_mb=$(megabytes MEM_PER_TASK "$mem")
merge_mem_mb=$(megabytes MERGE_MEM "$merge_mem")
# Seconds of a time limit as sbatch --time and sinfo write it; "infinite", "unlimited"
# and 0 (no limit) give -1.
seconds() {
  local name=$1 limit=$2 d=0 f=()
  case ${limit,,} in infinite | unlimited | 0) echo -1 && return ;; esac
  if [[ $limit =~ ^([0-9]+)-([0-9]+(:[0-9]+){0,2})$ ]]; then
    d=${BASH_REMATCH[1]}
    IFS=: read -ra f <<<"${BASH_REMATCH[2]}"
    f+=(0 0) # DAYS-HOURS[:MINUTES[:SECONDS]]
    echo $((((10#$d * 24 + 10#${f[0]}) * 60 + 10#${f[1]}) * 60 + 10#${f[2]}))
  elif [[ $limit =~ ^[0-9]+(:[0-9]+){0,2}$ ]]; then
    IFS=: read -ra f <<<"$limit"
    case ${#f[@]} in
      1) echo $((10#${f[0]} * 60)) ;;
      2) echo $((10#${f[0]} * 60 + 10#${f[1]})) ;;
      *) echo $(((10#${f[0]} * 60 + 10#${f[1]}) * 60 + 10#${f[2]})) ;;
    esac
  else
    fail "$name=$limit: expected a time limit such as 90, 4:00:00 or 1-12:00:00 (sbatch --time)"
  fi
}
time_s=$(seconds TIME_PER_TASK "$time")
merge_time_s=$(seconds MERGE_TIME "$merge_time")

[[ -f $SCENE ]] || fail "$SCENE: no such file"

# The partition the jobs go to, and the CPUs and megabytes of each of its nodes.
partitions=$(sinfo -h -o '%P' 2>&1) ||
  fail "sinfo could not reach the cluster: $(tail -n 1 <<<"$partitions")"
partition=${SBATCH_PARTITION:-$(sed -n 's/\*$//p' <<<"$partitions" | head -n 1)}
[[ -n $partition ]] || fail "the cluster has no default partition: set SBATCH_PARTITION"
nodes=$(sinfo -h -N -p "$partition" -o '%c %m') ||
  fail "sinfo could not list the nodes of partition '$partition'"
[[ -n $nodes ]] || fail "partition '$partition': sinfo lists no node of it (sinfo -s lists the partitions)"

# Fails unless a node has `cpus` CPUs and $2 megabytes together, naming what to lower.
check_fits() {
  local what=$1 want_mb=$2 mem_name=$3 mem_size=$4
  awk -v c="$cpus" -v m="$want_mb" -v what="$what" -v part="$partition" \
    -v mem_name="$mem_name" -v mem_size="$mem_size" '
    { if ($1 > max_c) max_c = $1; if ($2 + 0 > max_m) max_m = $2 + 0
      if ($1 >= c) cpus_ok = 1; if ($2 >= m) mem_ok = 1; if ($1 >= c && $2 >= m) both = 1 }
    END {
      if (both) exit 0
      if (!cpus_ok) {
        printf "CPUS_PER_TASK=%d: no node of partition '\''%s'\'' has %d CPUs (the most is %d): lower CPUS_PER_TASK\n", c, part, c, max_c
      } else if (!mem_ok) {
        printf "%s=%s: no node of partition '\''%s'\'' has %d MB of memory for %s (the most is %d MB): lower %s\n", mem_name, mem_size, part, m, what, max_m, mem_name
      } else {
        printf "CPUS_PER_TASK=%d and %s=%s: no node of partition '\''%s'\'' has both %d CPUs and %d MB of memory for %s: lower CPUS_PER_TASK or %s\n", c, mem_name, mem_size, part, c, m, what, mem_name
      }
      exit 1
    }' <<<"$nodes"
}
if ! said=$(check_fits "a shard" "$mem_mb" MEM_PER_TASK "$mem"); then fail "$said"; fi
if ! said=$(check_fits "the merge" "$merge_mem_mb" MERGE_MEM "$merge_mem"); then fail "$said"; fi

# The partition's time limit (as sinfo writes it: [DAYS-]HOURS:MINUTES:SECONDS).
most=$(sinfo -h -p "$partition" -o '%l' | head -n 1)
most_s=$(seconds "the time limit of partition '$partition'" "$most")
if ((most_s >= 0)); then
  for setting in "TIME_PER_TASK $time $time_s" "MERGE_TIME $merge_time $merge_time_s"; do
    read -r name limit limit_s <<<"$setting"
    if ((limit_s < 0 || limit_s > most_s)); then
      asks=$([[ $limit_s -lt 0 ]] && echo "no time limit" || echo "$limit_s s")
      fail "$name=$limit asks $asks, and partition '$partition' runs a job $most_s s at the most (its time limit, $most): lower $name"
    fi
  done
fi

array=1-$SHARDS${MAX_RUNNING:+%$MAX_RUNNING}
shard_options=(--array="$array" --cpus-per-task="$cpus" --mem="$mem" --time="$time")
merge_options=(--cpus-per-task="$cpus" --mem="$merge_mem" --time="$merge_time")

# What else Slurm holds against the jobs (a partition's time or size limits, a QOS):
# sbatch --test-only asks the scheduler without submitting.
for job in shards merge; do
  if [[ $job == shards ]]; then
    options=("${shard_options[@]}") script=$here/slurm.sh
  else
    options=("${merge_options[@]}") script=$here/slurm-merge.sh
  fi
  if ! said=$(sbatch --test-only "${options[@]}" "$script" 2>&1); then
    fail "Slurm would not run the $job (${options[*]}) in partition '$partition': $(tail -n 1 <<<"$said")"
  fi
done

mkdir -p -- "$OUT"
# --parsable prints JOBID, or JOBID;CLUSTER on a federation.
shards_job=$(sbatch --parsable "${shard_options[@]}" "$here/slurm.sh")
shards_job=${shards_job%%;*}
merge_job=$(sbatch --parsable "${merge_options[@]}" --dependency=afterok:"$shards_job" \
  --kill-on-invalid-dep=yes "$here/slurm-merge.sh")
merge_job=${merge_job%%;*}

echo "shards: job array $shards_job, tasks $array, each ${shard_options[*]:1};" \
  "merge: job $merge_job, ${merge_options[*]}, once they all succeed"
