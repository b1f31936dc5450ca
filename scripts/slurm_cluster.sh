#!/usr/bin/env bash
# A one-node Slurm cluster on localhost, for the tests of the Slurm recipes: Debian 12's munge,
# slurmctld and slurmd, started by hand (no systemd) with everything — configuration, keys,
# sockets, state, logs — in one folder that `stop` removes again.
#
#   scripts/slurm_cluster.sh start DIR   # prints the SLURM_CONF to export, once the node is idle
#   export SLURM_CONF=DIR/slurm.conf; sbatch --wait ...; squeue; scancel ...
#   scripts/slurm_cluster.sh stop DIR    # kills the daemons, removes DIR
#
# Needs root (the daemons run as root here) and the packages slurmctld, slurmd, slurm-client
# and munge. `start` exits 77 with a message when they cannot run here (what ctest counts as
# skipped), 1 when they could but the cluster did not come up (with the daemons' logs).
set -euo pipefail
command=${1:?usage: slurm_cluster.sh start|stop DIR}
dir=${2:?usage: slurm_cluster.sh start|stop DIR}

stop() {
  for pidfile in "$dir"/slurmd.pid "$dir"/slurmctld.pid "$dir"/munged.pid; do
    [ -s "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null || true
  done
  # The daemons remove their own pid files; give them a moment, then make sure.
  for _ in $(seq 50); do
    pgrep -f -- "$dir/" >/dev/null || break
    sleep 0.1
  done
  pkill -9 -f -- "$dir/" 2>/dev/null || true
  rm -rf "$dir"
}

skip() {
  echo "slurm_cluster: skipped: $*" >&2
  exit 77
}

case "$command" in
  stop) stop; exit 0 ;;
  start) ;;
  *) echo "usage: slurm_cluster.sh start|stop DIR" >&2; exit 2 ;;
esac

[ "$(id -u)" -eq 0 ] || skip "the daemons are started as root, and this is not root"
for tool in munged slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (apt-get install slurmctld slurmd slurm-client munge)"
done

mkdir -p "$dir"/state "$dir"/spool
chmod 700 "$dir"
dir=$(cd "$dir" && pwd)
node=$(hostname -s)
cpus=$(nproc)
# Free ports: a cluster of the machine's own (or another test's) may hold Slurm's defaults.
port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
ctld_port=$(port)
slurmd_port=$(port)

dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/munge.key"
cat >"$dir/slurm.conf" <<CONF
ClusterName=camcov-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
SwitchType=switch/none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf

fail() {
  echo "slurm_cluster: $*" >&2
  for log in "$dir"/munged.log "$dir"/slurmctld.log "$dir"/slurmd.log; do
    [ -f "$log" ] && { echo "--- $log" >&2; tail -n 20 "$log" >&2; }
  done
  stop
  exit 1
}

munged --force --socket="$dir/munge.socket" --key-file="$dir/munge.key" \
  --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" ||
  fail "munged did not start"
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" -N "$node" || fail "slurmd did not start"
for _ in $(seq 300); do
  state=$(sinfo -h -n "$node" -o %t 2>/dev/null || true)
  [ "$state" = idle ] && { echo "export SLURM_CONF=$SLURM_CONF"; exit 0; }
  sleep 0.1
done
fail "the node did not become idle in 30 s (state: ${state:-none})"
