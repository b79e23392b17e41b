#!/usr/bin/env bash
############################################################################
# MODULE:    testsuite/benchmark/cluster_benchmark.sh (r3.sbrt addon)
# PURPOSE:   The speed-up of the manual's orbit recipe on a one-node Slurm
#            cluster (tools/slurm_cluster.sh; issue 33's target: >= 1.8x
#            from 1 to 2 CPUs): a 24-frame orbit of model B at 800 x 600
#            as a job array of 4 tasks (6 frames each, one CPU a task, each
#            in a GRASS session and mapset of its own) on a cluster of 1 CPU
#            and of 2 CPUs, beside the same orbit in one process on 1 and on
#            2 threads; wall-clock times of one run each, as root (the
#            job array's from its first task's start to its last task's
#            end), and the tasks' own times summed, which leave out Slurm's
#            waits between tasks; and what this machine gives two
#            independent processes: the orbit on one thread alone, then two
#            such processes at once (each its own mapset), and the same for
#            GRASS sessions that run nothing (the start-up every task pays).
#            Checks that the frames equal the one-process frames; never
#            fails on time.
# USAGE:     make && testsuite/benchmark/cluster_benchmark.sh [MODEL] (B)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/grass_env.sh"
model=${1:-B}
data=${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}
sbrt_location "$data"
in_grass PERMANENT bash -c ". '$SBRT_ROOT/tools/bench_model.sh' && bench_model $model '$SBRT_ROOT/tools'" >/dev/null 2>&1
work=$(mktemp -d /tmp/r3sbrt_cluster.XXXXXX)
trap '"$SBRT_ROOT/tools/slurm_cluster.sh" stop "$work/slurm" >/dev/null 2>&1 || true
      rm -rf "$work" "$data"/loc/cjob*' EXIT
frames=24 tasks=4 size=800,600
view="input=geo_$model@PERMANENT frames=$frames size=$size backend=cpu"
seconds() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }

# one process, 1 and 2 threads
declare -A one
for threads in 1 2; do
    mkdir -p "$work/one$threads"
    start=$(date +%s.%N)
    in_grass cluster_bench r3.sbrt.render --q $view nprocs="$threads" \
        png="$work/one$threads/orbit_%04d.png" >/dev/null 2>&1
    one[$threads]=$(seconds "$start" "$(date +%s.%N)")
done

# the machine's own limit: one single-threaded orbit alone, then two at once
mkdir -p "$work/pair_a" "$work/pair_b"
start=$(date +%s.%N)
in_grass cluster_bench_a r3.sbrt.render --q $view nprocs=1 png="$work/pair_a/orbit_%04d.png" >/dev/null 2>&1 &
in_grass cluster_bench_b r3.sbrt.render --q $view nprocs=1 png="$work/pair_b/orbit_%04d.png" >/dev/null 2>&1 &
wait
pair=$(seconds "$start" "$(date +%s.%N)")

# what the tasks' GRASS start-up gets from two CPUs: a session that runs
# nothing (the grass launcher: Python and a dozen processes), 10 times
# alone, then 10 times in each of two mapsets at once
sessions() { for _ in $(seq 10); do grass "$data/loc/$1" --exec true >/dev/null 2>&1; done; }
start=$(date +%s.%N)
sessions cluster_bench_a
middle=$(date +%s.%N)
sessions cluster_bench_a &
sessions cluster_bench_b &
wait
startup_one=$(seconds "$start" "$middle")
startup_pair=$(seconds "$middle" "$(date +%s.%N)")
rm -rf "$data"/loc/cluster_bench_a "$data"/loc/cluster_bench_b

# the job array on a cluster of 1 CPU, then of 2
cat >"$work/orbit.sh" <<EOS
#!/bin/bash
#SBATCH --cpus-per-task=1
echo "start \$(date +%s.%N)"
first=\$((SLURM_ARRAY_TASK_ID * $((frames / tasks)) + 1))
mapset=$data/loc/cjob\$SLURM_ARRAY_TASK_ID
new=; [ -d \$mapset ] || new=-c
grass \$new \$mapset --exec r3.sbrt.render $view nprocs=\$SLURM_CPUS_PER_TASK \\
    range=\$first-\$((first + $((frames / tasks - 1)))) png=\$1/orbit_%04d.png
echo "end \$(date +%s.%N)"
EOS
declare -A array busy
for cpus in 1 2; do
    "$SBRT_ROOT/tools/slurm_cluster.sh" start "$work/slurm" "$cpus" >/dev/null
    mkdir -p "$work/array$cpus"
    rm -rf "$data"/loc/cjob*
    rm -f "$work"/task_*.out
    job=$(SLURM_CONF=$work/slurm/slurm.conf sbatch --parsable --array=0-$((tasks - 1)) \
        --export=PATH,HOME,GRASS_ADDON_BASE,GRASS_SKIP_MAPSET_OWNER_CHECK \
        --output="$work/task_%a.out" "$work/orbit.sh" "$work/array$cpus")
    "$SBRT_ROOT/tools/slurm_cluster.sh" wait "$work/slurm" "${job%%;*}"
    array[$cpus]=$(cat "$work"/task_*.out | awk '$1 == "start" && (!s || $2 < s) { s = $2 }
                                                 $1 == "end" && $2 > e { e = $2 }
                                                 END { printf "%.2f", e - s }')
    # each task's own time, start to end, summed
    busy[$cpus]=$(cat "$work"/task_*.out | awk '$1 == "start" { s += $2 } $1 == "end" { e += $2 }
                                                END { printf "%.2f", e - s }')
    "$SBRT_ROOT/tools/slurm_cluster.sh" stop "$work/slurm"
    for k in $(seq -f %04g 1 $frames); do
        cmp -s "$work/array$cpus/orbit_$k.png" "$work/one1/orbit_$k.png" ||
            echo "cluster: WARNING: frame $k of the $cpus-CPU job array differs from one process"
    done
done
ratio() { awk -v a="$1" -v b="$2" -v k="${3:-1}" 'BEGIN { printf "%.2f", k * a / b }'; }
echo "cluster geo_$model: orbit of $frames frames at $size, $(nproc) cores here"
echo "cluster geo_$model: one process, 1 thread: ${one[1]} s; 2 threads: ${one[2]} s ($(ratio "${one[1]}" "${one[2]}")x)"
echo "cluster geo_$model: two independent 1-thread processes at once: ${pair} s for twice the frames: $(ratio "${one[1]}" "$pair" 2)x the throughput of one"
echo "cluster geo_$model: GRASS start-up alone (10 sessions running nothing): ${startup_one} s; two at once: ${startup_pair} s for twice the sessions: $(ratio "$startup_one" "$startup_pair" 2)x"
echo "cluster geo_$model: job array of $tasks tasks, 1-CPU cluster: ${array[1]} s; 2-CPU cluster: ${array[2]} s"
echo "cluster geo_$model: speed-up from 1 to 2 CPUs: $(ratio "${array[1]}" "${array[2]}")x (target >= 1.8)"
echo "cluster geo_$model: the tasks' own time (start to end), summed: 1-CPU cluster ${busy[1]} s; 2-CPU cluster ${busy[2]} s: two CPUs give the tasks $(ratio "${busy[1]}" "${busy[2]}" 2)x; Slurm's waits between tasks: $(awk -v w="${array[1]}" -v b="${busy[1]}" 'BEGIN { printf "%.2f", w - b }') s and $(awk -v w="${array[2]}" -v b="${busy[2]}" 'BEGIN { printf "%.2f", w - b / 2 }') s"
echo "cluster geo_$model: job array on 2 CPUs / one process on 2 threads: $(ratio "${array[2]}" "${one[2]}")"
