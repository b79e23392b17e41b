#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/pipeline_benchmark.sh (r3.sbrt addon)
# PURPOSE:   The render pipeline's figures (issue 15), per model, in one
#            run, 1056 x 884, the peers' camera (position=4375,5000,2500
#            target=1000,1250,320 fov=25 zexag=2), backend=cpu:
#            - in process (trace_bench frame, warm, best of N): load,
#              prepare, the streamed frame (trace, shade, RGB bands to a
#              sink) on 1 and on all cores (parallel efficiency), and the
#              whole-image reference (trace_image, then shade);
#            - end to end: r3.sbrt.render writing the three RGB maps, a
#              fresh process (best of 3; cold: the first of them after the
#              page cache was dropped, where allowed), with its ratio to the
#              in-process frame (wall to the millisecond); the floor of
#              any GRASS raster module here (r.info -g, r3.sbrt.render
#              --help; g.version, which loads no raster library: the
#              libraries libgrass_raster brings in, GDAL's tree, are the
#              difference);
#            - the maps' compressor: GRASS_COMPRESSOR=LZ4 (our default)
#              against ZSTD (GRASS's), render stage and bytes;
#            - 4096 x 3456: wall time and peak RSS;
#            - backend=egl (llvmpipe without a GPU): end to end against its
#              own dispatch time;
#            - m.nviz.image drawing three slices of the same model
#              (../shared/peers, under Xvfb) where its data exist.
#            Figures only: never part of pass/fail.
# USAGE:     make && benchmarks/pipeline_benchmark.sh [SIZES] (A B)
#            SBRT_BENCH_REPEAT (5), SBRT_PEERS (../shared/peers)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
sizes=${*:-A B}
make -s -C "$here/trace_bench" >/dev/null
bench=$here/trace_bench/build/trace_bench
repeat=${SBRT_BENCH_REPEAT:-5}
peers=${SBRT_PEERS:-$SBRT_ROOT/../shared/peers}
camera="position=4375,5000,2500 target=1000,1250,320 fov=25 zexag=2"

cat >"$SBRT_GISDBASE/pipeline_one.sh" <<'EOS'
set -euo pipefail
size=$1 tools=$2 bench=$3 repeat=$4 camera=$5
. "$tools/bench_model.sh"
bench_model "$size" "$tools" # sets map= and sbrt=
image=1056,884 # size= of the module's renders
loc=$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)
cores=$(nproc)
# in process
"$bench" frame "$sbrt" $camera repeat="$repeat" threads=1 label=$size | sed "s/^/pipeline size=$size /"
"$bench" frame "$sbrt" $camera repeat="$repeat" threads=0 label=$size | sed "s/^/pipeline size=$size /"
# a fresh process: wall and render stage (trace, shade and the maps)
one() { # label env... -- options...
    local label=$1; shift
    local envs=()
    while [ "$1" != "--" ]; do envs+=("$1"); shift; done
    shift
    # the wall time to the millisecond (time's %e has 10 ms steps), the
    # peak RSS from time
    local start end
    start=$(date +%s%N)
    env "${envs[@]}" /usr/bin/time -f "%M" -o /tmp/r3sbrt_pipe_time r3.sbrt.render --o --verbose \
        input=$map output=pipe_img size="$image" "$@" 2>/tmp/r3sbrt_pipe_log >/dev/null
    end=$(date +%s%N)
    wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", (b - a) / 1e9 }')
    read -r rss </tmp/r3sbrt_pipe_time
    # the whole streamed render: tracing, shading and the maps
    ms=$(tr '\n' ' ' </tmp/r3sbrt_pipe_log | sed -n 's/.*held; \([0-9.]*\) ms in all.*/\1/p')
    echo "$label $wall $rss $ms"
}
best() { # label env... -- options...: best of 3 (the first also reported: cold)
    local first="" b=""
    for i in 1 2 3; do
        r=$(one "$@")
        [ -z "$first" ] && first=$r
        if [ -z "$b" ] || awk -v a="$(echo "$r" | cut -d' ' -f2)" -v c="$(echo "$b" | cut -d' ' -f2)" 'BEGIN{exit !(a<c)}'; then b=$r; fi
    done
    echo "$b" | awk -v f="$(echo "$first" | cut -d' ' -f2)" -v s="$size" \
        '{ printf "pipeline size=%s scene=%s end_to_end_s=%s first_run_s=%s peak_rss_kb=%s render_stage_ms=%s\n", s, $1, $2, f, $3, $4 }'
}
sync; echo 3 >/proc/sys/vm/drop_caches 2>/dev/null || true
# shellcheck disable=SC2086
{
best rgb_lz4 A=1 -- backend=cpu $camera
best rgb_zstd GRASS_COMPRESSOR=ZSTD -- backend=cpu $camera
best rgb_egl A=1 -- backend=egl $camera
}
egl_ms=$(sed -n 's/.*GPU tracing: .* rays in \([0-9.]*\) ms.*/\1/p' /tmp/r3sbrt_pipe_log)
echo "pipeline size=$size scene=rgb_egl dispatch_ms=$egl_ms"
for c in LZ4 ZSTD; do
    GRASS_COMPRESSOR=$c r3.sbrt.render --o --q input=$map output=pipe_$c size=1056,884 backend=cpu $camera
    bytes=$(du -cb "$loc/$(g.gisenv get=MAPSET)"/cell/pipe_$c.* | tail -1 | cut -f1)
    echo "pipeline size=$size compressor=$c rgb_map_bytes=$bytes"
done
floor() { # best of 5 wall of a command (to the millisecond)
    local b="" start end w
    for i in 1 2 3 4 5; do
        start=$(date +%s%N)
        "$@" >/dev/null 2>&1 || true
        end=$(date +%s%N)
        w=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", (b - a) / 1e9 }')
        if [ -z "$b" ] || awk -v a="$w" -v c="$b" 'BEGIN{exit !(a<c)}'; then b=$w; fi
    done
    echo "$b"
}
echo "pipeline size=$size floor r_info_s=$(floor r.info -g map=pipe_LZ4.red) render_help_s=$(floor r3.sbrt.render --help) g_version_s=$(floor g.version)"
image=4096,3456
# shellcheck disable=SC2086
best big_4096x3456 A=1 -- backend=cpu $camera
image=1056,884
echo "pipeline size=$size cores=$cores"
EOS
for s in $sizes; do
    in_grass pipeline bash "$SBRT_GISDBASE/pipeline_one.sh" "$s" "$SBRT_ROOT/tools" "$bench" \
        "$repeat" "$camera" 2>&1 | grep "^pipeline" | tee "$SBRT_GISDBASE/pipeline_$s.txt"
    nviz=""
    if [ -x "$peers/nviz.sh" ] && command -v Xvfb >/dev/null; then
        Xvfb :99 -screen 0 1280x1024x24 -noreset >/dev/null 2>&1 &
        xvfb=$!
        sleep 2
        # none where the peers' data are not made (nviz.sh then fails)
        nviz=$( (DISPLAY=:99 NVIZ_MODES=slices "$peers/nviz.sh" "$s" 2>/dev/null || true) |
            sed -n 's/.*mode=slices wall_s=\([0-9.]*\).*/\1/p')
        kill "$xvfb" 2>/dev/null || true
    fi
    awk -v nviz="${nviz:-0}" -v size="$s" '
        /frame label=.* threads=1 / { for (i = 1; i <= NF; ++i) if ($i ~ /^frame_ms=/) { split($i, a, "="); one = a[2] } }
        /frame label=.* threads=[0-9]+ / && !/threads=1 / { for (i = 1; i <= NF; ++i) {
            if ($i ~ /^frame_ms=/) { split($i, a, "="); all = a[2] }
            if ($i ~ /^threads=/) { split($i, a, "="); n = a[2] }
            if ($i ~ /^reference_ms=/) { split($i, a, "="); ref = a[2] } } }
        /scene=rgb_lz4 / { for (i = 1; i <= NF; ++i) if ($i ~ /^end_to_end_s=/) { split($i, a, "="); e2e = a[2] } }
        /scene=rgb_egl end_to_end/ { for (i = 1; i <= NF; ++i) if ($i ~ /^end_to_end_s=/) { split($i, a, "="); egl = a[2] } }
        /scene=rgb_egl dispatch_ms=/ { split($NF, a, "="); dispatch = a[2] }
        END {
            printf "ratio size=%s end_to_end/in_process_frame=%.2f streamed/reference=%.2f parallel_efficiency_1_to_%d=%.0f%%", size, e2e * 1000 / all, all / ref, n, 100 * one / (all * n)
            if (dispatch > 0) printf " egl_end_to_end/dispatch=%.1f", egl * 1000 / dispatch
            if (nviz > 0) printf " nviz_slices/ours_end_to_end=%.1f (m.nviz.image %s s)", nviz / e2e, nviz
            printf "\n"
        }' "$SBRT_GISDBASE/pipeline_$s.txt"
done
