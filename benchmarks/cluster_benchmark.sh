#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/cluster_benchmark.sh (r3.sbrt addon)
# PURPOSE:   The speed-up of the manual's poster recipe on a one-node Slurm
#            cluster (tools/slurm_cluster.sh; issue 52's target: >= 1.8x
#            from 1 to 2 CPUs on render-bound tasks, each task several
#            seconds of rendering): a 4224 x 3536 poster of model C (a
#            close view, eight strata translucent) cut into TILES tiles,
#            rendered as a Slurm job array (a tile a task, one CPU a task:
#            --cpus-per-task=1 and nprocs=$SLURM_CPUS_PER_TASK, each task in
#            a GRASS session and mapset of its own) on a node of 1 CPU, then
#            of 2 CPUs (the node's CPUs= in slurm.conf: Slurm runs as many
#            tasks at once as the node has CPUs); beside the whole poster in
#            one process on 1 and on 2 threads (what the machine gives).
#            Prints, all from one run: each task's render seconds (the
#            render's own "Streamed: ... ms in all"), its process and its
#            GRASS session; Slurm's launch overhead (the gaps between tasks
#            on one CPU; the CPU time a task costs beyond its own script);
#            the wall times and the 1 -> 2 CPU ratios; the command and the
#            load before and after. Checks that the two job arrays' mosaics
#            and both whole-poster renders are the same pixels (exit 1 if
#            not); never fails on time. Stops the cluster it started.
# USAGE:     make && benchmarks/cluster_benchmark.sh [MODEL] (C)
#            MODEL: T S A B C (tools/bench_model.sh; C, 800 x 1000 x 800
#            voxels, takes 10-20 min to make once, kept in SBRT_BENCH_DATA)
#            SIZE=4224,3536 the poster; TILES=1x8 its tiles, rows x
#            columns (strips of 528 x 3536 pixels: each crosses the same
#            mix of near and far model, so the tasks take about as long);
#            VIEW= the render options of the view; TIMEOUT=3600 seconds at
#            most for each render and each job array. Small settings check
#            the script itself: SIZE=640,480 TILES=2x2 ... S
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
model=${1:-C}
size=${SIZE:-4224,3536}
grid=${TILES:-1x8}
# a close view that the model fills, its upper eight strata translucent:
# each ray walks hundreds of cells (the opaque view of the whole poster
# takes about 3 s on one thread: tiles of well under a second)
look=${VIEW:-elevation=60 distance=2000 opacity=13:0.01,12:0.01,11:0.01,10:0.01,9:0.01,8:0.01,7:0.01,6:0.01}
limit=${TIMEOUT:-3600}
data=${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}
IFS=, read -r width height <<<"$size"
IFS=x read -r tile_rows tile_cols <<<"$grid"
tasks=$((tile_rows * tile_cols))
cluster=$SBRT_ROOT/tools/slurm_cluster.sh
say() { echo "cluster geo_$model: $*"; }
say "command: SIZE=$size TILES=$grid VIEW='$look' TIMEOUT=$limit SBRT_BENCH_DATA=$data $0 $model"
say "load before: $(uptime)"

sbrt_location "$data"
timeout "$limit" grass "$data/loc/PERMANENT" --exec bash -c \
    ". '$SBRT_ROOT/tools/bench_model.sh' && bench_model $model '$SBRT_ROOT/tools'" >/dev/null 2>&1 ||
    { echo "cluster: model $model could not be made (tools/bench_model.sh)" >&2; exit 1; }
# a short path: Slurm's sockets lie in it (108 bytes at most)
work=$(mktemp -d /tmp/r3sbrt_cluster.XXXXXX)
trap '"$cluster" stop "$work/slurm" >/dev/null 2>&1 || true
      rm -rf "$work" "$data"/loc/cjob* "$data"/loc/cluster_bench' EXIT
trap 'exit 130' INT TERM
view="input=geo_$model@PERMANENT size=$size backend=cpu $look"

# one render inside a GRASS session: render.sh PNG THREADS [TASK]; with a
# task, only that tile (row by row, as the manual's recipe numbers them);
# prints when the render started and ended, and its own time
cat >"$work/render.sh" <<EOS
#!/bin/bash
png=\$1 threads=\$2 task=\${3:-}
tile=; plain=-n
if [ -n "\$task" ]; then
    r=\$((task / $tile_cols)) c=\$((task % $tile_cols))
    y=\$((r * $height / $tile_rows)) x=\$((c * $width / $tile_cols))
    tile=tile=\$y,\$x,\$(((r + 1) * $height / $tile_rows - y)),\$(((c + 1) * $width / $tile_cols - x))
    plain=
fi
echo "render_start \$(date +%s.%N)"
timeout -k 30 $limit r3.sbrt.render --verbose $view \$tile \$plain nprocs=\$threads png=\$png \\
    >"\$png.log" 2>&1 || { tail -5 "\$png.log"; exit 1; }
echo "render_end \$(date +%s.%N)"
# "Streamed: ... 1234.5 ms in all": the tracing, shading and writing (GRASS
# wraps its messages: the lines joined first)
tr -s '\n ' '  ' <"\$png.log" | sed -n 's/.*; \([0-9.]*\) ms in all.*/render_ms \1\n/p'
EOS
# a task of the job array: the manual's recipe, with times
cat >"$work/task.sh" <<EOS
#!/bin/bash
#SBATCH --cpus-per-task=1
echo "start \$(date +%s.%N)"
mapset=$data/loc/cjob\$SLURM_ARRAY_TASK_ID
new=; [ -d \$mapset ] || new=-c
grass \$new \$mapset --exec $work/render.sh \$1/tile_\$SLURM_ARRAY_TASK_ID.png \\
    \$SLURM_CPUS_PER_TASK \$SLURM_ARRAY_TASK_ID || exit 1
echo "end \$(date +%s.%N)"
EOS
chmod +x "$work/render.sh" "$work/task.sh"
seconds() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }
ratio() { awk -v a="$1" -v b="$2" -v k="${3:-1}" 'BEGIN { printf "%.2f", k * a / b }'; }

# the whole poster in one process, on 1 and 2 threads
declare -A whole whole_render
for threads in 1 2; do
    start=$(date +%s.%N)
    in_grass cluster_bench "$work/render.sh" "$work/whole$threads.png" "$threads" \
        >"$work/whole$threads.out" 2>&1 ||
        { cat "$work/whole$threads.out" >&2; echo "cluster: the whole poster failed" >&2; exit 1; }
    whole[$threads]=$(seconds "$start" "$(date +%s.%N)")
    whole_render[$threads]=$(awk '$1 == "render_start" { s = $2 } $1 == "render_end" { e = $2 }
                                  END { printf "%.2f", e - s }' "$work/whole$threads.out")
done

# the job array on a node of 1 CPU, then of 2
declare -A wall first_last submitted
for cpus in 1 2; do
    "$cluster" start "$work/slurm" "$cpus" >/dev/null
    mkdir -p "$work/array$cpus"
    rm -rf "$data"/loc/cjob*
    submitted[$cpus]=$(date +%s.%N)
    job=$(SLURM_CONF=$work/slurm/slurm.conf sbatch --parsable --array=0-$((tasks - 1)) \
        --export=PATH,HOME,GRASS_ADDON_BASE,GRASS_SKIP_MAPSET_OWNER_CHECK \
        --output="$work/array$cpus/task_%a.out" "$work/task.sh" "$work/array$cpus")
    SLURM_CONF=$work/slurm/slurm.conf timeout "$limit" "$cluster" wait "$work/slurm" "${job%%;*}" || {
        tail -n 5 "$work/array$cpus"/task_*.out >&2
        echo "cluster: the job array on $cpus CPUs failed or took over $limit s" >&2
        exit 1
    }
    "$cluster" stop "$work/slurm"
    # a line a task: start end render_start render_end render_ms
    for t in $(seq 0 $((tasks - 1))); do
        awk '{ v[$1] = $2 } END { print v["start"], v["end"], v["render_start"], v["render_end"], v["render_ms"] }' \
            "$work/array$cpus/task_$t.out"
    done >"$work/times$cpus"
    wall[$cpus]=$(awk -v s="${submitted[$cpus]}" '$2 > e { e = $2 } END { printf "%.2f", e - s }' "$work/times$cpus")
    first_last[$cpus]=$(awk '!s || $1 < s { s = $1 } $2 > e { e = $2 } END { printf "%.2f", e - s }' "$work/times$cpus")
done

# the same poster every time: the tiles' mosaics and the whole renders
check=$(python3 - "$width" "$height" "$tile_rows" "$tile_cols" "$work" <<'EOF'
import sys
from PIL import Image

width, height, rows, cols = map(int, sys.argv[1:5])
work = sys.argv[5]

def pixels(image):
    return image.size, image.convert("RGBA").tobytes()

def mosaic(folder):
    whole = Image.new("RGBA", (width, height))
    for t in range(rows * cols):
        r, c = divmod(t, cols)
        with Image.open(f"{folder}/tile_{t}.png") as tile:
            whole.paste(tile.convert("RGBA"), (c * width // cols, r * height // rows))
    return pixels(whole)

want = mosaic(f"{work}/array1")
differ = []
if mosaic(f"{work}/array2") != want:
    differ.append("the 2-CPU job array's mosaic")
for threads in (1, 2):
    with Image.open(f"{work}/whole{threads}.png") as image:
        if pixels(image) != want:
            differ.append(f"the whole poster on {threads} thread(s)")
print("; ".join(differ) if differ else "same")
EOF
)

# per task: render (its own time), process, GRASS session, script
stats() { # FILE CPUS WALL
    awk -v cpus="$2" -v wall="$3" '
        { ms = $5 / 1000; proc = $4 - $3; task = $2 - $1
          render += ms; procs += proc; tasks += task; n++
          if (!lo || ms < lo) lo = ms; if (ms > hi) hi = ms }
        END { printf "%.2f %.2f %.2f %.2f %.2f %.2f %.2f\n", lo, render / n, hi, procs / n,
                     (tasks - procs) / n, tasks / n, (cpus * wall - tasks) / n }' "$1"
}
read -r lo1 mean1 hi1 proc1 session1 task1 lost1 < <(stats "$work/times1" 1 "${wall[1]}")
read -r lo2 mean2 hi2 proc2 session2 task2 lost2 < <(stats "$work/times2" 2 "${wall[2]}")
# on one CPU the tasks run one after another: Slurm's launch is the gap
# from sbatch, or from a task's end, to the next task's start
gaps=$(sort -n -k1 "$work/times1" | awk '
    NR > 1 { g = $1 - e; sum += g; if (g > hi) hi = g; n++ } { e = $2 }
    END { printf "%.2f %.2f", n ? sum / n : 0, hi }')
read -r gap_mean gap_hi <<<"$gaps"
first_wait() { awk -v s="${submitted[$1]}" 'BEGIN { m = 1e18 } $1 < m { m = $1 } END { printf "%.2f", m - s }' "$work/times$1"; }

say "poster $width x $height in $tasks tiles ($grid) of about $((width / tile_cols)) x $((height / tile_rows)) pixels, $(nproc) cores here"
say "one process, whole poster: 1 thread ${whole[1]} s (render ${whole_render[1]} s); 2 threads ${whole[2]} s (render ${whole_render[2]} s): $(ratio "${whole[1]}" "${whole[2]}")x"
say "per task, 1-CPU node: render $lo1 / $mean1 / $hi1 s (least / mean / most), the render's process $proc1 s, its GRASS session $session1 s more: $task1 s a task's script"
say "per task, 2-CPU node: render $lo2 / $mean2 / $hi2 s, process $proc2 s, GRASS session $session2 s more: $task2 s (two at once: $(ratio "$mean1" "$mean2" 2)x the throughput of one)"
say "Slurm's launch overhead: 1-CPU node: $gap_mean s mean, $gap_hi s most from a task's end to the next task's start; CPU time a task costs beyond its script: $lost1 s (1 CPU), $lost2 s (2 CPUs, the last tasks' imbalance included); sbatch to the first task's start: $(first_wait 1) s and $(first_wait 2) s"
say "job array (sbatch to the last task's end): 1-CPU node ${wall[1]} s; 2-CPU node ${wall[2]} s (first start to last end: ${first_last[1]} s and ${first_last[2]} s)"
say "speed-up from 1 to 2 CPUs: job array $(ratio "${wall[1]}" "${wall[2]}")x (target >= 1.8); one process $(ratio "${whole[1]}" "${whole[2]}")x"
say "job array on 2 CPUs / one process on 2 threads: $(ratio "${wall[2]}" "${whole[2]}")"
say "load after: $(uptime)"
if [ "$check" = same ]; then
    say "check: both job arrays' mosaics and both whole-poster renders are the same $width x $height pixels"
else
    say "ERROR: differs from the 1-CPU job array's mosaic: $check"
    exit 1
fi
