#!/usr/bin/env bash
# A single-node Slurm cluster in a temporary folder, for testing job arrays on this machine:
#   source scripts/slurm-local.sh start DIR   # writes DIR/slurm.conf, starts slurmctld and slurmd
#   source scripts/slurm-local.sh stop DIR    # stops them (by the pids they wrote)
# The daemons must run as root unless every job runs as the user who starts them (slurmd
# switches to the job's user).
# No munge and no cgroups: AuthType=auth/none, CredType=cred/none (Slurm 22.05 still ships them),
# proctrack/linuxproc, task/none; the daemons run as the current user (slurmd needs root to run
# jobs as other users only). Ports are picked free at start. Exports SLURM_CONF for the clients.

slurm_local_start() {
    local dir=$1
    mkdir -p "$dir/state" "$dir/spool"
    local host ports cpus user
    host=$(hostname)
    user=$(id -un)
    cpus=$(nproc)
    ports=$(python3 -c 'import socket
s=[socket.socket() for _ in range(2)]
[x.bind(("",0)) for x in s]
print(*[x.getsockname()[1] for x in s])')
    set -- $ports
    cat > "$dir/slurm.conf" <<CONF
ClusterName=hertzlocal
SlurmctldHost=$host
SlurmctldPort=$1
SlurmdPort=$2
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/none
CredType=cred/none
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF=$dir/slurm.conf
    # In the foreground of background jobs (-D), so that this shell reaps them when they stop.
    slurmctld -D -i -f "$dir/slurm.conf" > /dev/null 2>&1 &
    slurmd -D -f "$dir/slurm.conf" > /dev/null 2>&1 &
    # Wait (at most 30 s) for the node to be idle.
    local i
    for i in $(seq 1 60); do
        if sinfo -h -o %T 2>/dev/null | grep -q idle; then
            return 0
        fi
        sleep 0.5
    done
    echo "slurm-local: the node did not come up; logs in $dir" >&2
    return 1
}

slurm_local_stop() {
    local dir=$1 f
    local pid
    for f in slurmd slurmctld; do
        if [ -f "$dir/$f.pid" ]; then
            pid=$(cat "$dir/$f.pid")
            kill "$pid" 2>/dev/null || true
            wait "$pid" 2>/dev/null || true
        fi
    done
}

# Sourced without arguments: only the functions (scripts/slurm-map-check.sh).
if [ $# -gt 0 ]; then
    case "$1" in
        start) slurm_local_start "$2" ;;
        stop) slurm_local_stop "$2" ;;
        *) echo "usage: source scripts/slurm-local.sh start|stop DIR" >&2; return 2 2>/dev/null || exit 2 ;;
    esac
fi
