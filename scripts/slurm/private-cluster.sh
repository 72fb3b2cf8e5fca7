#!/usr/bin/env bash
# A private single-node Slurm cluster on this machine, for the tests and for trying a batch before
# a real cluster: slurmctld and slurmd without systemd or munge (auth/none, cred/none), state and
# logs in one folder, this host at 127.0.0.1 with all its cores.
#
#   scripts/slurm/private-cluster.sh start DIR   # prints: export SLURM_CONF=DIR/slurm.conf
#   scripts/slurm/private-cluster.sh stop DIR    # cancels its jobs, stops both daemons by PID
#
# start returns once the node is idle (or fails, naming the log to read, after 60 s). Every Slurm
# command (sbatch, squeue, scancel, sacct) reaches this cluster with SLURM_CONF set as printed.
# auth/none trusts any local user: it is for one machine and one user, never for a shared one.
set -euo pipefail

usage() {
  echo "usage: $0 start|stop DIR" >&2
  exit 2
}
[[ $# -eq 2 ]] || usage
action=$1
dir=$(realpath -m "$2")
conf=$dir/slurm.conf

free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

stop_daemon() {  # pid file, name
  [[ -f $1 ]] || return 0
  local pid
  pid=$(cat "$1")
  if kill "$pid" 2>/dev/null; then
    for _ in $(seq 100); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
  fi
  rm -f "$1"
  echo "stopped $2 (pid $pid)"
}

case $action in
  start)
    for tool in slurmctld slurmd sinfo; do
      command -v "$tool" >/dev/null || PATH=$PATH:/usr/sbin
      command -v "$tool" >/dev/null || {
        echo "$tool not found: install slurm-wlm (scripts/install-deps.sh does)" >&2
        exit 1
      }
    done
    [[ -f $dir/slurmctld.pid ]] && {
      echo "a private cluster already runs in $dir (stop it first)" >&2
      exit 1
    }
    mkdir -p "$dir/state" "$dir/spool"
    node=$(hostname -s)
    cpus=$(nproc)
    memory=$(($(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 * 9 / 10))
    user=$(id -un)
    cat >"$conf" <<EOF
# Written by $0: one node, no munge, no cgroups.
ClusterName=private
SlurmctldHost=$node(127.0.0.1)
SlurmUser=$user
SlurmdUser=root
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/none
CredType=cred/none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
ReturnToService=2
KillWait=10
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
    export SLURM_CONF=$conf
    # -i: ignore state a previous cluster in this folder left
    slurmctld -f "$conf" -i
    slurmd -f "$conf"
    for _ in $(seq 600); do
      state=$(sinfo -h -N -o %t 2>/dev/null || true)
      [[ $state == idle ]] && break
      sleep 0.1
    done
    if [[ ${state:-} != idle ]]; then
      echo "the node did not come up idle in 60 s (state '${state:-none}'); see $dir/slurmctld.log and $dir/slurmd.log" >&2
      stop_daemon "$dir/slurmd.pid" slurmd >&2
      stop_daemon "$dir/slurmctld.pid" slurmctld >&2
      exit 1
    fi
    echo "export SLURM_CONF=$conf"
    ;;
  stop)
    if [[ -f $dir/slurmctld.pid ]] && kill -0 "$(cat "$dir/slurmctld.pid")" 2>/dev/null; then
      # Jobs first: their slurmstepd processes outlive slurmd.
      export SLURM_CONF=$conf
      scancel --quiet --user "$(id -un)" || true
      for _ in $(seq 150); do
        [[ -z $(squeue -h -o %i 2>/dev/null) ]] && break
        sleep 0.1
      done
    fi
    stop_daemon "$dir/slurmd.pid" slurmd
    stop_daemon "$dir/slurmctld.pid" slurmctld
    ;;
  *) usage ;;
esac
