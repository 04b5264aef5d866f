# shellcheck shell=bash
# A one-node Slurm cluster of its own, for tests: sourced by bash, it defines
#
#   slurm_cluster_start DIR   starts munged, slurmctld and slurmd with everything under
#                             DIR (made, in a folder searchable by all, as munged
#                             wants): the munge key and socket, slurm.conf,
#                             the state, spool, pid and log files; exports SLURM_CONF, so
#                             that sbatch, squeue, sinfo and scancel talk to this cluster
#                             alone; returns 0 once its node is idle. Otherwise returns 1
#                             with the reason in slurm_cluster_reason (the daemons' logs in
#                             DIR), having stopped whatever it started.
#   slurm_cluster_stop        cancels the cluster's jobs, stops its daemons and kills any
#                             process they or its jobs left (see below). Safe to call
#                             twice, or after a start that failed.
#   slurm_cluster_marked      prints the pids of the processes slurm_cluster_stop would
#                             kill: none once it has run.
#
# It leaves a machine's own Slurm and munge alone: its own ports (two free ones, picked at
# random), its own munge socket and key, its own files, a cluster named shadowgen-test.
# The node is this host as `slurmd -C` describes it (its CPUs and memory), at 127.0.0.1,
# in two partitions: shards (the default, no limit) and short (a 1-minute time limit, 1
# CPU of a node at the most). No cgroup (proctrack/linuxproc, task/none); memory is a
# consumable (CR_Core_Memory). Needs root (slurmd runs jobs as their user) and Debian's
# slurm-wlm and munge.
#
# Every process it starts has SHADOWGEN_SLURM_CLUSTER=DIR in its environment, and so do
# the daemons' children (slurmstepd) and, if the caller submits with that variable set
# (slurm_cluster_env), its jobs: slurm_cluster_stop finds them by it, so that nothing
# outlives a test, whether slurmd reaped them or not.

slurm_cluster_dir=
slurm_cluster_reason=
slurm_cluster_pids=()
slurm_cluster_logs=() # the output file of each of slurm_cluster_pids
# Bounds on the waits, in seconds.
slurm_cluster_start_wait=${slurm_cluster_start_wait:-60}

# Runs a command with the cluster's mark in its environment.
slurm_cluster_env() { SHADOWGEN_SLURM_CLUSTER=$slurm_cluster_dir "$@"; }

# True while process $1 runs (not yet exited: a child that exited stays as a zombie until
# waited for, and kill -0 still finds it).
slurm_alive() {
  local stat
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
  stat=${stat##*) }
  [[ ${stat%% *} != Z ]]
}

# True when nothing listens on 127.0.0.1 at port $1.
slurm_port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }

# Starts "$@" in the background, marked, its output in the file $1 of the cluster's
# folder; records its pid (the command's own: a simple command is executed, not wrapped).
slurm_cluster_spawn() {
  local log=$1
  shift
  SHADOWGEN_SLURM_CLUSTER=$slurm_cluster_dir "$@" >"$slurm_cluster_dir/$log" 2>&1 </dev/null &
  slurm_cluster_pids+=("$!")
  slurm_cluster_logs+=("$slurm_cluster_dir/$log")
}

# Fails the start with a reason, after stopping what was started.
slurm_cluster_fail() {
  slurm_cluster_reason=$1
  slurm_cluster_stop
  return 1
}

slurm_cluster_start() {
  slurm_cluster_dir=$1
  slurm_cluster_pids=()
  slurm_cluster_logs=()
  local d=$slurm_cluster_dir command
  if [[ $(id -u) != 0 ]]; then
    slurm_cluster_reason="needs root, to start slurmctld and slurmd"
    return 1
  fi
  for command in munged mungekey slurmctld slurmd sbatch squeue sinfo scancel scontrol; do
    if ! command -v "$command" >/dev/null; then
      slurm_cluster_reason="no $command (Debian's slurm-wlm and munge; .ci/install-deps installs them)"
      return 1
    fi
  done
  # munged wants every folder above its socket searchable by all: DIR's too.
  mkdir -p "$d/state" "$d/spool"
  chmod 755 "$d"
  mungekey --create --keyfile="$d/munge.key" >/dev/null 2>&1 || {
    slurm_cluster_reason="mungekey could not create a key in $d"
    return 1
  }
  slurm_cluster_spawn munged.out munged --foreground --key-file="$d/munge.key" \
    --socket="$d/munge.socket" --pid-file="$d/munged.pid" --log-file="$d/munged.log" \
    --seed-file="$d/munged.seed"

  # Two free ports in a row, away from Slurm's own 6817 and 6818.
  local port tries
  for ((tries = 0; tries < 20; tries++)); do
    port=$((20000 + RANDOM % 40000))
    if slurm_port_free "$port" && slurm_port_free $((port + 1)); then break; fi
  done
  local node
  node=$(slurmd -C 2>/dev/null | grep -m 1 '^NodeName=') ||
    slurm_cluster_fail "slurmd -C could not describe this host" || return 1
  cat >"$d/slurm.conf" <<EOF
ClusterName=shadowgen-test
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$d/munge.socket
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/slurmctld.log
SlurmdLogFile=$d/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=shards Nodes=ALL Default=YES MaxTime=INFINITE State=UP
PartitionName=short Nodes=ALL MaxTime=1 MaxCPUsPerNode=1 State=UP
EOF
  export SLURM_CONF=$d/slurm.conf

  # munged first: the daemons authenticate through it.
  local waited
  for ((waited = 0; waited < 50; waited++)); do
    [[ -S $d/munge.socket ]] && break
    sleep 0.1
  done
  [[ -S $d/munge.socket ]] ||
    slurm_cluster_fail "munged did not start: $(tail -n 1 "$d/munged.out")" || return 1

  slurm_cluster_spawn slurmctld.out slurmctld -D -f "$d/slurm.conf"
  slurm_cluster_spawn slurmd.out slurmd -D -f "$d/slurm.conf"
  local state=
  for ((waited = 0; waited < slurm_cluster_start_wait * 4; waited++)); do
    state=$(sinfo -h -N -p shards -o '%t' 2>/dev/null) || state=
    [[ $state == idle ]] && return 0
    local i
    for i in "${!slurm_cluster_pids[@]}"; do
      slurm_alive "${slurm_cluster_pids[i]}" ||
        slurm_cluster_fail "$(basename "${slurm_cluster_logs[i]}" .out) stopped at start: $(tail -n 1 "${slurm_cluster_logs[i]}")" ||
        return 1
    done
    sleep 0.25
  done
  slurm_cluster_fail "the node was not idle after ${slurm_cluster_start_wait} s (state '${state}'; logs in $d)"
}

slurm_cluster_marked() {
  [[ -n $slurm_cluster_dir ]] || return 0
  local entry
  for entry in /proc/[0-9]*; do
    if grep -qzxF "SHADOWGEN_SLURM_CLUSTER=$slurm_cluster_dir" "$entry/environ" 2>/dev/null; then
      echo "${entry#/proc/}"
    fi
  done
}

slurm_cluster_stop() {
  [[ -n $slurm_cluster_dir ]] || return 0
  local waited pid
  if [[ -n ${SLURM_CONF:-} && ${#slurm_cluster_pids[@]} -gt 1 ]]; then
    scancel --full --user=root >/dev/null 2>&1 || true
    for ((waited = 0; waited < 40; waited++)); do
      [[ -z $(squeue -h 2>/dev/null) ]] && break
      sleep 0.25
    done
  fi
  # slurmd and slurmctld, then munged (last, as they talk through it); a daemon still
  # there 10 s after SIGTERM is killed.
  local i
  for ((i = ${#slurm_cluster_pids[@]} - 1; i >= 0; i--)); do
    pid=${slurm_cluster_pids[i]}
    kill -TERM "$pid" 2>/dev/null || true
    for ((waited = 0; waited < 100; waited++)); do
      slurm_alive "$pid" || break
      sleep 0.1
    done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  slurm_cluster_pids=()
  slurm_cluster_logs=()
  # Whatever they left: job steps, jobs.
  for pid in $(slurm_cluster_marked); do
    kill -KILL "$pid" 2>/dev/null || true
  done
}
