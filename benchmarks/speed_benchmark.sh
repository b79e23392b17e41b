#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/speed_benchmark.sh (r3.sbrt addon)
# PURPOSE:   The speed figures of empty-space skipping and scene pruning,
#            per model (A, B, C) and scene, 1056 x 884 pixels, in one run:
#            - in process (trace_bench, best of N, taken in turns): ms per
#              frame and Mrays/s of backend=cpu and of the GL path (EGL;
#              llvmpipe on machines without a GPU) in both memory layouts,
#              each with skipping off too (the ratio is the figure), and the
#              GPU bytes and waste of each layout;
#            - the module end to end (a fresh r3.sbrt.render, best of 3),
#              with and without skipping (-e);
#            - boreholes only (-b, 12 wells) against the full model.
#            Scenes, all with zexag=2: best (the peers' camera, rays hit
#            soon), worst (low from the east, rays cross the air over the
#            eastern plateau to the scarp: the fewest rays per second
#            without skipping, the paper's worst case), grazing (low over
#            the south-west corner: most rays hit a side wall or graze the
#            top), hidden (the peers' camera with strata 1-13 hidden: only
#            the lenses and the dike are left), boreholes.
#            The peers on the same data: peers_benchmark.sh (A, B).
# USAGE:     make && benchmarks/speed_benchmark.sh [SIZES]  (A B C)
#            Model C (800 x 1000 x 800 voxels) takes ~10 min to make once.
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
sizes=${*:-A B C}
make -s -C "$here/trace_bench" >/dev/null
bench=$here/trace_bench/build/trace_bench
repeat=${SBRT_BENCH_REPEAT:-3}

camera_best="position=4375,5000,2500 target=1000,1250,320 fov=25 zexag=2"
camera_worst="position=2600,1250,640 target=1000,1250,560 fov=40 zexag=2"
camera_grazing="position=-1500,-1000,700 target=1000,1250,550 fov=40 zexag=2"
hidden="1,2,3,4,5,6,7,8,9,10,11,12,13"

cat >"$SBRT_GISDBASE/speed_one.sh" <<'EOS'
set -euo pipefail
size=$1 tools=$2 bench=$3 repeat=$4 camera_best=$5 camera_worst=$6 camera_grazing=$7
hidden=$8
. "$tools/bench_model.sh"
bench_model "$size" "$tools" # sets map= and sbrt=
# twelve wells on a 4 x 3 grid over the model
[ -n "$(g.list type=vector pattern=speed_wells)" ] || {
    for x in 250 750 1250 1750; do for y in 400 1250 2100; do echo "$x|$y"; done; done |
        v.in.ascii --q --o input=- output=speed_wells x=1 y=2
}
# trace_bench: in process, CPU and GL, skipping on and off
in_process() { # scene camera [hide]
    local scene=$1 camera=$2 hide=${3:-}
    # shellcheck disable=SC2086
    "$bench" skipping "$sbrt" $camera label="$scene" repeat="$repeat" \
        ${hide:+hide=$hide} | sed "s/^skipping /speed size=$size scene=$scene /"
}
# the module, fresh processes: best wall time and render stage of 3
module() { # label options...
    local label=$1; shift
    local best_wall="" best_ms=""
    for i in 1 2 3; do
        /usr/bin/time -f "%e" -o /tmp/r3sbrt_speed_time r3.sbrt.render --o --verbose \
            input=$map output=speed_img size=1056,884 backend=cpu "$@" 2>/tmp/r3sbrt_speed_log >/dev/null
        local wall ms
        wall=$(cat /tmp/r3sbrt_speed_time)
        ms=$(sed -n 's/.*tracing: .* rays in \([0-9.]*\) ms.*/\1/p' /tmp/r3sbrt_speed_log)
        if [ -z "$best_wall" ] || awk -v a="$wall" -v b="$best_wall" 'BEGIN{exit !(a<b)}'; then best_wall=$wall; fi
        if [ -z "$best_ms" ] || awk -v a="$ms" -v b="$best_ms" 'BEGIN{exit !(a<b)}'; then best_ms=$ms; fi
    done
    echo "speed size=$size scene=$label module_s=$best_wall render_ms=$best_ms"
}
in_process best "$camera_best"
in_process worst "$camera_worst"
in_process grazing "$camera_grazing"
in_process hidden "$camera_best" "$hidden"
# shellcheck disable=SC2086
{
    module best $camera_best
    module best_no_skipping $camera_best -e
    module worst $camera_worst
    module worst_no_skipping $camera_worst -e
    module grazing $camera_grazing
    module grazing_no_skipping $camera_grazing -e
    module hidden $camera_best hide=$hidden
    module hidden_no_skipping $camera_best hide=$hidden -e
    module boreholes_only $camera_best boreholes=speed_wells -b
    module boreholes_only_no_skipping $camera_best boreholes=speed_wells -b -e
}
EOS
for s in $sizes; do
    # a mapset of its own: the models in PERMANENT may be in use
    in_grass speed bash "$SBRT_GISDBASE/speed_one.sh" "$s" "$SBRT_ROOT/tools" "$bench" \
        "$repeat" "$camera_best" "$camera_worst" "$camera_grazing" "$hidden" 2>&1 | grep "^speed" |
        awk -v size="$s" '
        { print }
        /scene=.* module_s=/ {
            split($3, a, "="); scene = a[2]
            split($4, w, "="); split($5, r, "=")
            wall[scene] = w[2]; ms[scene] = r[2]
        }
        END {
            for (s in wall) {
                if (s ~ /_no_skipping$/) continue
                n = s "_no_skipping"
                if (n in wall)
                    printf "ratio size=%s scene=%s module_off/on=%.2f render_off/on=%.2f\n",
                        size, s, wall[n] / wall[s], ms[n] / ms[s]
            }
            if (("boreholes_only" in ms) && ("best" in ms))
                printf "ratio size=%s full_model/boreholes_only render=%.2f module=%.2f\n",
                    size, ms["best"] / ms["boreholes_only"], wall["best"] / wall["boreholes_only"]
        }'
done
