#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/device_run.sh (r3.sbrt addon)
# PURPOSE:   On the device machine (see device_bundle.sh): the GPU figures
#            of issues 15, 19 and 32 and the CPU's scaling, printed:
#            - per model and view (the peers' oblique, the worst view,
#              grazing), 1056 x 884 and 800 x 600: the GPU's whole frame
#              (traced, shaded, RGB in host memory) against its dispatch and
#              the same machine's CPU frame on all cores; kernel normals;
#              where its time goes (gpu_parts: GL time of each pass, the
#              host's time after the GPU's last band against a memcpy of the
#              RGB, the bytes the host touched per pixel);
#            - model B at 4224 x 3536 and 1056 x 884, the bands written
#              by the shader across PCIe (SBRT_GPU_BANDS=direct) against
#              the default (staged: GPU memory, then the copy engine);
#            - model B with 100 boreholes drawn with the model;
#            - the CPU on 1, 2, 4, 8, 16 cores (taskset), B at 1056 x 884
#              and 2112 x 1768, C at 1056 x 884, with each worker's busy
#              share (frame_parts), and on one core the rows in the order
#              one of 16 threads meets them (row_order);
#            - the machine's own limit: what it gives 1, 2, 4, 8, 16
#              threads of arithmetic, streaming and dependent random reads
#              (machine_probe: machine); B's single-thread frame alone and
#              with one such process on every core at once, for 1-16
#              cores, against the threads of one process (contention);
#              each core beside core 0, two single-thread frames at once
#              (pairs);
#              B on 1 and on all cores in turns, three rounds, with the
#              cores' clock read while each runs (alternate);
#            - with trace_bench_base in the bundle (another build, e.g. the
#              last main), the same figures of that build, in the same run;
#            - with sbrt_unit_tests in the bundle, the GL unit tests on EGL;
#            - with the national model in the bundle (NATIONAL=1), issue
#              49's GPU pages: its blocks brought up as rays reach them,
#              cold and warm, at gpu_memory= 1024, 256 and 160 MB, against
#              the model uploaded whole and the CPU (trace_bench gpu_pages);
#              and with its columns in pages (the pyramid from level 2 on,
#              as the 16x model goes up within 1 GB);
#            - what building the GPU's programs costs from empty caches
#              (ours and the driver's): B's class view, with 100
#              boreholes, and the property view (programs_ms);
#            - issue 29's property view (paint_gt with its channels): the
#              class view against property= (a sum of three percentages)
#              and fade= on the GPU, cold (a fresh renderer, the colours
#              by voxel made and uploaded, or coloured on the host) and
#              warm, and the GPU's pixels against the CPU's.
#            Runs here too (llvmpipe), which checks the script.
# USAGE:     [SECTIONS="programs unit paint pages gpu large boreholes scaling
#            machine contention pairs alternate"] [UNIT_FILTER=a GoogleTest filter] [BOREHOLE_FRAMES=200]
#            bash .device/device_run.sh [SIZES] (A B C)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
bundle=$(cd "$(dirname "$0")" && pwd)
export LD_LIBRARY_PATH=$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export SBRT_PROGRAM_CACHE=off # every run compiles: figures of a first run
data=$(mktemp -d /tmp/sbrt_device.XXXXXX)
trap 'rm -rf "$data"' EXIT
sizes=${*:-A B C}
views=(
    "best position=4375,5000,2500 target=1000,1250,320 fov=25 zexag=2"
    "worst position=2600,1250,640 target=1000,1250,560 fov=40 zexag=2"
    "grazing position=-1500,-1000,700 target=1000,1250,550 fov=40 zexag=2"
)
best=${views[0]#best }
cores=$(nproc)
builds=(new)
[ -x "$bundle/trace_bench_base" ] && builds+=(base)
bench_of() { [ "$1" = base ] && echo "$bundle/trace_bench_base" || echo "$bundle/trace_bench"; }
sections=" ${SECTIONS:-programs unit paint pages gpu large boreholes scaling machine contention pairs alternate} "
run() { [[ "$sections" == *" $1 "* ]]; }
# the frame_ms of trace_bench frame's output (files, or standard input)
frame_ms_of() { grep "^frame " "$@" | grep -oE "frame_ms=[0-9.]+" | cut -d= -f2; }

# the models, unpacked once for every section
for size in $sizes; do
    tar -C "$data" -xzf "$bundle/sbrt/geo_$size.tar.gz"
done

# 0. the programs compiled from nothing: neither our program cache nor the
# driver's (NVIDIA's __GL_SHADER_DISK_CACHE; Mesa's MESA_SHADER_CACHE_DISABLE)
# (an H100 took 100 s for the boreholes' program while it had a copy of
# the shading at each place a walk ends)
if run programs && [ -d "$data/geo_B" ]; then
    for drilled in 0 100; do
        status=0
        SBRT_PROGRAM_CACHE=off __GL_SHADER_DISK_CACHE=0 MESA_SHADER_CACHE_DISABLE=true \
            timeout 300 "$bundle/trace_bench" gpu_frame "$data/geo_B" $best label=B/programs \
            repeat=1 cpu=0 threads="$cores" boreholes=$drilled radius=20 >"$data/programs.txt" ||
            status=$?
        echo "device programs cold boreholes=$drilled exit=$status" \
            "$(grep -oE "programs_ms=[0-9.]+" "$data/programs.txt" || echo programs_ms=?)"
    done
fi

# 1. the GL unit tests on this GPU (EGL; the OSMesa ones need libOSMesa): on
# a fresh machine every program is compiled, about 2.5 minutes on an H100
if run unit && [ -x "$bundle/sbrt_unit_tests" ]; then
    "$bundle/sbrt_unit_tests" \
        --gtest_filter="${UNIT_FILTER:-*egl*:*GpuPaint*:*GpuBands*/0:*OverlayTiles*:*GpuBandLayout*:Renderer*:BandFlow*:WorkerPool*}" 2>&1 |
        grep -E "^\[  (PASSED|FAILED) |Failure|^\[ stress" | sed "s/^/device unit /" || true
fi

# property views (issue 29): the model with channels at r3.sbrt.render's
# view of the benchmark (azimuth 200, elevation 35, zexag 20), on all
# cores and on one; the GL programs cached as a user's are
if run paint && [ -f "$bundle/sbrt/paint_gt.tar.gz" ]; then
    tar -C "$data" -xzf "$bundle/sbrt/paint_gt.tar.gz"
    for n in "$cores" 1; do
        for px in "cols=1056 rows=884" "cols=800 rows=600"; do
            SBRT_PROGRAM_CACHE=$data/programs "$bundle/trace_bench" paint_frame "$data/paint_gt" \
                azimuth=200 elevation=35 zexag=20 $px property=kans_5+kans_6+kans_7 fade=onz_lk \
                repeat=5 threads="$n" label=paint_gt | sed "s/^/device threads=$n /"
        done
    done
fi

# the national model read block by block on the GPU (issue 49): its blocks
# brought up as the rays reach them within gpu_memory=, cold and warm,
# against the model uploaded whole and the CPU (national.tar.gz: the bundle
# made with NATIONAL=1)
if run pages && [ -f "$bundle/sbrt/national.tar.gz" ]; then
    tar -C "$data" -xzf "$bundle/sbrt/national.tar.gz"
    for px in "cols=1056 rows=884" "cols=800 rows=600"; do
        "$bundle/trace_bench" gpu_pages "$data/national" azimuth=225 elevation=30 zexag=600 \
            $px gpu_memory=1024,256,160 whole=1 repeat=5 threads="$cores" label=national |
            sed "s/^/device /"
        "$bundle/trace_bench" gpu_pages "$data/national" azimuth=225 elevation=30 zexag=600 \
            $px gpu_memory=1024,64 columns=2 cpu=0 repeat=5 threads="$cores" \
            label=national_columns | sed "s/^/device /"
    done
fi

# 2. GPU frames per model and view, each build
for build in "${builds[@]}"; do
    run gpu || break
    bench=$(bench_of "$build")
    for size in $sizes; do
        for view in "${views[@]}"; do
            set -- $view
            name=$1
            shift
            for px in "cols=1056 rows=884" "cols=800 rows=600"; do
                "$bench" gpu_frame "$data/geo_$size" "$@" $px label="$size/$name" repeat=5 \
                    threads="$cores" | sed "s/^/device build=$build size=$size view=$name /"
            done
        done
    done
done

# 3. model B: a large frame (the bands written by the shader across PCIe
# too), 100 boreholes
if [ -d "$data/geo_B" ]; then
    for build in "${builds[@]}"; do
        bench=$(bench_of "$build")
        run large && "$bench" gpu_frame "$data/geo_B" $best cols=4224 rows=3536 label=B/large \
            repeat=5 threads="$cores" | sed "s/^/device build=$build size=B view=best /"
        if run boreholes; then
            # the GPU's clock while its frames run (nvidia-smi where there is one)
            clocks=$data/gpu_clocks.txt
            sampler=
            for drilled in 0 100; do
                : >"$clocks"
                if command -v nvidia-smi >/dev/null; then
                    nvidia-smi --query-gpu=clocks.sm --format=csv,noheader,nounits -lms 20 >"$clocks" &
                    sampler=$!
                fi
                # the GPU's frames alone (cpu=0), many, while the clock is read
                "$bench" gpu_frame "$data/geo_B" $best label=B/boreholes repeat="${BOREHOLE_FRAMES:-200}" cpu=0 \
                    threads="$cores" boreholes=$drilled radius=20 |
                    sed "s/^/device build=$build size=B view=best /"
                [ -n "$sampler" ] && kill "$sampler" && wait "$sampler" 2>/dev/null
                sampler=
                sort -n "$clocks" | awk -v b=$drilled '{ v[NR] = $1 } END { if (NR) printf "device boreholes=%d gpu_clock_mhz samples=%d min=%d median=%d max=%d\n", b, NR, v[1], v[int((NR + 1) / 2)], v[NR] }'
            done
        fi
    done
    if run large; then
        for px in "cols=1056 rows=884" "cols=4224 rows=3536"; do
            SBRT_GPU_BANDS=direct "$bundle/trace_bench" gpu_frame "$data/geo_B" $best $px \
                label=B/direct repeat=5 threads="$cores" | sed "s/^/device build=new-direct size=B view=best /"
        done
    fi
fi

# 4. the CPU's scaling, each build; first, on one core, what a thread's
# cache loses when its rows lie apart as at 16 threads (row_order)
for build in "${builds[@]}"; do
    run scaling || break
    bench=$(bench_of "$build")
    for case in "B cols=1056 rows=884" "B cols=2112 rows=1768" "C cols=1056 rows=884"; do
        set -- $case
        size=$1
        shift
        [ -d "$data/geo_$size" ] || continue
        [ "$build" = new ] && taskset -c 0 "$bench" row_order "$data/geo_$size" $best "$@" \
            repeat=5 label="$size/$1" | sed "s/^/device /"
        for n in 1 2 4 8 16; do
            [ "$n" -le "$cores" ] || break
            taskset -c "0-$((n - 1))" "$bench" frame "$data/geo_$size" $best "$@" \
                threads="$n" repeat=5 reference=0 label="$size/$1" |
                sed "s/^/device build=$build scaling cores=$n /"
        done
    done
done

# the machine's limit without our code: each kind of work's rate a thread
# on n cores against one alone (a fall in arithmetic: the clock or shared
# cores; in streaming: bandwidth; in random reads: memory latency)
if run machine && [ -x "$bundle/machine_probe" ]; then
    for n in 1 2 4 8 16; do
        [ "$n" -le "$cores" ] || break
        taskset -c "0-$((n - 1))" "$bundle/machine_probe" threads="$n" | sed "s/^/device /"
    done
fi

# 5. the machine's limit on the tracer itself: in three rounds, for n = 1,
# 2, 4, 8, 16 cores (0..n-1), B's frame on n threads in one process, then
# n single-thread processes at once, one a core (nothing shared but the
# machine: each its own model and buffers). The summary, medians of the
# rounds: our efficiency at n (the 1-thread frame over n times the
# n-thread frame) beside the machine's (one process alone over the mean of
# n at once) and their ratio: where that ratio is near 1, the machine, not
# the tracer, sets the limit
if run contention && [ -d "$data/geo_B" ]; then
    log=$data/contention.txt
    : >"$log"
    for round in 1 2 3; do
        for px in "cols=1056 rows=884" "cols=2112 rows=1768"; do
            for n in 1 2 4 8 16; do
                [ "$n" -le "$cores" ] || break
                ms=$(taskset -c "0-$((n - 1))" "$bundle/trace_bench" frame "$data/geo_B" $best $px \
                    threads="$n" repeat=5 reference=0 label=B/threads | frame_ms_of)
                echo "device contention round=$round ${px%% *} n=$n kind=threads frame_ms=$ms" | tee -a "$log"
                for ((k = 0; k < n; ++k)); do
                    taskset -c "$k" "$bundle/trace_bench" frame "$data/geo_B" $best $px threads=1 \
                        repeat=5 reference=0 label="B/core$k" >"$data/contention_$k.txt" &
                done
                wait
                ms=$(for ((k = 0; k < n; ++k)); do frame_ms_of "$data/contention_$k.txt"; done |
                    awk '{ s += $1 } END { printf "%.2f", s / NR }')
                echo "device contention round=$round ${px%% *} n=$n kind=processes mean_frame_ms=$ms" |
                    tee -a "$log"
            done
        done
    done
    awk '{ for (i = 1; i <= NF; ++i) { split($i, kv, "="); f[kv[1]] = kv[2] }
           key = f["cols"] " " f["n"] " " f["kind"]
           v[key] = v[key] " " (f["kind"] == "threads" ? f["frame_ms"] : f["mean_frame_ms"])
           ns[f["cols"] " " f["n"]] = 1 }
         function median(list,    a, m, i, j, t) {
             m = split(list, a, " ")
             for (i = 1; i <= m; ++i) for (j = i + 1; j <= m; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
             return m % 2 ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2 }
         END { for (k in ns) { split(k, c, " "); cols = c[1]; n = c[2]
                   t1 = median(v[cols " 1 threads"]); tn = median(v[cols " " n " threads"])
                   p1 = median(v[cols " 1 processes"]); pn = median(v[cols " " n " processes"])
                   ours = t1 / (n * tn); machine = p1 / pn
                   printf "device contention summary cols=%s n=%d threads_frame_ms=%.1f processes_mean_frame_ms=%.1f ours=%.3f machine=%.3f ours/machine=%.3f\n", cols, n, tn, pn, ours, machine, ours / machine } }' \
        "$log" | sort -t= -k2,2n -k3,3n
fi

# what a second tracer on core k costs the one on core 0 (B's single-thread
# frame, each pair at once, against core 0 alone): cores that share a
# physical core (hyperthreads the guest is not told of) or a cache show
if run pairs && [ -d "$data/geo_B" ]; then
    taskset -c 0 "$bundle/trace_bench" frame "$data/geo_B" $best threads=1 repeat=5 reference=0 \
        label=B/alone >"$data/pair_0.txt"
    alone=$(frame_ms_of "$data/pair_0.txt")
    for ((k = 1; k < cores; ++k)); do
        taskset -c 0 "$bundle/trace_bench" frame "$data/geo_B" $best threads=1 repeat=5 \
            reference=0 label=B/with >"$data/pair_0.txt" &
        taskset -c "$k" "$bundle/trace_bench" frame "$data/geo_B" $best threads=1 repeat=5 \
            reference=0 label=B/other >"$data/pair_k.txt"
        wait
        awk -v k="$k" -v a="$alone" -v z="$(frame_ms_of "$data/pair_0.txt")" -v o="$(frame_ms_of "$data/pair_k.txt")" \
            'BEGIN { printf "device pairs core0_with=%d alone_ms=%s core0_ms=%s other_ms=%s core0_slowdown=%.3f\n", k, a, z, o, z / a }'
    done
fi

# 6. B on one core and on all, in turns (three rounds), each with the mean
# clock of the cores it runs on, read from /proc/cpuinfo halfway through:
# what a frame on n cores gains against what the clock loses
cpu_mhz() { # mean MHz of cores 0..$1-1
    awk -v n="$1" '/^processor/ { p = $3 } /^cpu MHz/ && p < n { s += $4; k += 1 }
                   END { if (k) printf "%.0f", s / k; else printf "?" }' /proc/cpuinfo
}
if run alternate && [ -d "$data/geo_B" ]; then
    for round in 1 2 3; do
        for px in "cols=1056 rows=884" "cols=2112 rows=1768"; do
            for n in 1 "$cores"; do
                taskset -c "0-$((n - 1))" "$bundle/trace_bench" frame "$data/geo_B" $best $px \
                    threads="$n" repeat=7 reference=0 label="B/round$round" >"$data/alt.txt" &
                pid=$!
                sleep 0.5
                mhz=$(cpu_mhz "$n")
                wait "$pid"
                grep -E "^frame" "$data/alt.txt" | sed "s/^/device alternate round=$round cores=$n mhz=$mhz /"
            done
        done
    done
fi
