#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/animation_benchmark.sh (r3.sbrt addon)
# PURPOSE:   Animations (issue 17), per model, in one run, 1056 x 884,
#            backend=cpu: a 36-frame orbit (position=4375,5000,2500
#            target=1000,1250,320 fov=25 zexag=2, the peers' camera) in one
#            r3.sbrt.render process, PNG frames only (-n), against
#            - 36 separate r3.sbrt.render runs of the same 36 cameras
#              (position= turned as the orbit turns it);
#            - the in-process time of one frame of that camera (trace_bench
#              frame: trace, shade and the RGB bands, warm, best of N);
#            and the MP4 of the orbit (video=, ffmpeg), its frames counted
#            by ffprobe. Figures only: never part of pass/fail.
# USAGE:     make && benchmarks/animation_benchmark.sh [SIZES] (B)
#            SBRT_BENCH_REPEAT (5), SBRT_FRAMES (36)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
sizes=${*:-B}
make -s -C "$here/trace_bench" >/dev/null
bench=$here/trace_bench/build/trace_bench
repeat=${SBRT_BENCH_REPEAT:-5}
frames=${SBRT_FRAMES:-36}

cat >"$SBRT_GISDBASE/animation_one.sh" <<'EOS'
set -euo pipefail
size=$1 tools=$2 bench=$3 repeat=$4 frames=$5
. "$tools/bench_model.sh"
bench_model "$size" "$tools" # sets map= and sbrt=
out=$(mktemp -d /tmp/r3sbrt_anim.XXXXXX)
target=1000,1250,320
view="fov=25 zexag=2 size=1056,884 backend=cpu -n"
# in process: one frame of the first camera
inproc=$("$bench" frame "$sbrt" position=4375,5000,2500 target=$target fov=25 zexag=2 \
    repeat="$repeat" | sed -n 's/.*frame_ms=\([0-9.]*\).*/\1/p')
# one process, all frames, and the video
start=$(date +%s.%N)
r3.sbrt.render --q --o input=$map position=4375,5000,2500 target=$target $view \
    frames=$frames png="$out/orbit_%04d.png" video="$out/orbit.mp4" fps=12
orbit=$(echo "$(date +%s.%N) - $start" | bc)
video_start=$(date +%s.%N)
ffmpeg -y -loglevel error -framerate 12 -i "$out/orbit_%04d.png" \
    -vf "scale=trunc(iw/2)*2:trunc(ih/2)*2" -c:v libx264 -pix_fmt yuv420p "$out/again.mp4"
video=$(echo "$(date +%s.%N) - $video_start" | bc)
counted=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries \
    stream=nb_read_frames -of csv=p=0 "$out/orbit.mp4")
# the same cameras, one process each
start=$(date +%s.%N)
for k in $(seq 1 "$frames"); do
    position=$(awk -v k=$k -v n=$frames 'BEGIN {
        a = (k - 1) * 360 / n * atan2(0, -1) / 180; dx = 4375 - 1000; dy = 5000 - 1250
        printf "%.17g,%.17g,2500", 1000 + cos(a) * dx - sin(a) * dy, 1250 + sin(a) * dx + cos(a) * dy }')
    r3.sbrt.render --q --o input=$map position=$position target=$target $view \
        png="$out/single_$k.png"
done
separate=$(echo "$(date +%s.%N) - $start" | bc)
awk -v s=$size -v n=$frames -v o=$orbit -v v=$video -v sep=$separate -v ip=$inproc -v c=$counted 'BEGIN {
    per = (o - v) / n * 1000
    printf "animation size=%s frames=%d one_process_s=%.2f of_which_video_s~%.2f per_frame_ms=%.1f in_process_frame_ms=%.1f per_frame/in_process=%.2f separate_runs_s=%.2f separate/one_process_frames=%.2f separate/one_process_with_video=%.2f mp4_frames=%s\n",
        s, n, o, v, per, ip, per / ip, sep, sep / (o - v), sep / o, c }'
rm -rf "$out"
EOS
for s in $sizes; do
    in_grass PERMANENT bash "$SBRT_GISDBASE/animation_one.sh" "$s" "$SBRT_ROOT/tools" \
        "$bench" "$repeat" "$frames" 2>&1 | grep "^animation"
done
