#!/usr/bin/env bash
############################################################################
# MODULE:    tools/slurm_cluster.sh (r3.sbrt addon)
# PURPOSE:   A one-node Slurm cluster on this machine for the tests and
#            benchmarks of the manual's job-array recipes (Debian's
#            slurm-wlm and munge, run as root): `start DIR [CPUS]` writes
#            DIR/slurm.conf for this host (CPUS, default every core, as the
#            node's CPUs), starts munged, slurmctld and slurmd with their
#            sockets, state, logs and pid files in DIR, and waits until
#            sinfo shows the node idle; `stop DIR` cancels the jobs and
#            stops the daemons; `wait DIR JOB` returns once every task of
#            JOB (sbatch --parsable's id) has ended, 0 where each completed
#            with exit code 0, else 1 naming the others (sbatch --wait polls
#            every 2 to 10 s: tens of seconds lost a short job array).
#            Commands then need SLURM_CONF=DIR/slurm.conf. Exits 2, saying
#            why, where Slurm cannot start here.
# USAGE:     tools/slurm_cluster.sh start DIR [CPUS] | stop DIR | wait DIR JOB
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
action=${1:-} dir=${2:-}
[ -n "$action" ] && [ -n "$dir" ] || { echo "usage: $0 start DIR [CPUS] | stop DIR | wait DIR JOB" >&2; exit 1; }
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
export SLURM_CONF=$dir/slurm.conf
cannot() { echo "slurm_cluster: Slurm cannot start here: $*" >&2; exit 2; }

stop() {
    [ -f "$SLURM_CONF" ] && scancel --quiet --user=root 2>/dev/null || true
    for daemon in slurmd slurmctld munged; do
        [ -s "$dir/$daemon.pid" ] || continue
        pid=$(cat "$dir/$daemon.pid")
        kill "$pid" 2>/dev/null || true
        for _ in $(seq 50); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.1
        done
        kill -9 "$pid" 2>/dev/null || true # still there after 5 s
        rm -f "$dir/$daemon.pid"
    done
}

if [ "$action" = stop ]; then
    stop
    exit 0
fi
if [ "$action" = wait ]; then
    job=${3:?usage: $0 wait DIR JOB}
    # squeue lists the tasks still pending or running (an error: ask again)
    while ! queued=$(squeue --noheader --jobs="$job" --format=%i 2>/dev/null) || [ -n "$queued" ]; do
        sleep 0.2
    done
    # slurmctld keeps ended jobs' records for MinJobAge (300 s)
    tasks=$(scontrol --oneliner show job "$job" |
        grep -o -E 'ArrayTaskId=[0-9]+|JobState=[A-Z_]+|ExitCode=[0-9:]+' | paste -d ' ' - - -)
    failed=$(grep -v 'JobState=COMPLETED ExitCode=0:0' <<<"$tasks" || true)
    [ -z "$failed" ] && exit 0
    echo "slurm_cluster: tasks of job $job that did not complete:" >&2
    echo "$failed" >&2
    exit 1
fi
[ "$action" = start ] || { echo "usage: $0 start DIR [CPUS] | stop DIR | wait DIR JOB" >&2; exit 1; }
[ "$(id -u)" = 0 ] || cannot "the daemons run as root, and this is user $(id -un)"
for tool in munged slurmctld slurmd sinfo sbatch; do
    command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] ||
        cannot "$tool is missing (Debian: apt-get install slurm-wlm munge)"
done
[ -r /etc/munge/munge.key ] || cannot "no munge key (/etc/munge/munge.key; the munge package makes it)"
cpus=${3:-$(nproc)}
host=$(hostname -s)
# slurmd's sockets lie in DIR/spool: their paths must fit a Unix socket's
# 108 bytes (a step's socket fails the job's launch, and the job is held)
[ $((${#dir} + ${#host} + 32)) -le 107 ] ||
    cannot "DIR's path is ${#dir} characters long, too long for Slurm's sockets in it; give a shorter one (e.g. mktemp -d /tmp/slurm.XXXXXX)"
stop # a cluster left over in DIR
mkdir -p "$dir/state" "$dir/spool"
cat >"$SLURM_CONF" <<EOF
# one node, this host, made by tools/slurm_cluster.sh
ClusterName=sbrt
SlurmctldHost=$host
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$((6817 + 10 * (RANDOM % 100)))
SlurmdPort=$((6818 + 10 * (RANDOM % 100)))
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SchedulerType=sched/backfill
# a task starts as soon as a CPU is free: Slurm's default holds batch jobs
# back up to 3 s (batch_sched_delay), which on a one-node cluster of
# second-long tasks is most of the wall time
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=sbrt Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
PATH=$PATH:/usr/sbin
munged --force --socket="$dir/munge.socket" --pid-file="$dir/munged.pid" \
    --log-file="$dir/munged.log" --seed-file="$dir/munge.seed" 2>"$dir/munged.err" ||
    cannot "munged did not start: $(tail -1 "$dir/munged.err")"
slurmctld -f "$SLURM_CONF" 2>"$dir/slurmctld.err" ||
    { stop; cannot "slurmctld did not start: $(tail -1 "$dir/slurmctld.err")"; }
slurmd -f "$SLURM_CONF" 2>"$dir/slurmd.err" ||
    { stop; cannot "slurmd did not start: $(tail -1 "$dir/slurmd.err")"; }
for _ in $(seq 100); do
    [ "$(sinfo --noheader --format=%t 2>/dev/null)" = idle ] && {
        echo "slurm_cluster: node $host idle with $cpus CPUs; SLURM_CONF=$SLURM_CONF"
        exit 0
    }
    sleep 0.2
done
state=$(sinfo --noheader --format=%t 2>&1 || true)
stop
cannot "the node is not idle after 20 s (sinfo: $state; logs in $dir)"
