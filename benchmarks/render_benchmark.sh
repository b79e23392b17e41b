#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/render_benchmark.sh (r3.sbrt addon)
# PURPOSE:   Rendering figures of the renderer issue, per model size and
#            view, 1056 x 884 pixels: ms per frame and Mrays/s of the GPU
#            path (EGL; OSMesa too where built; llvmpipe on machines without
#            a GPU) and of backend=cpu, best of 3 runs in one go; the whole
#            module's wall time; and the agreement of each GL image with the
#            CPU one (material pixels that differ, largest depth error).
# USAGE:     make && benchmarks/render_benchmark.sh [SIZES]  (A B)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
. "$(dirname "$0")/../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
sizes=${*:-A B}
backends="egl"
[ -e /usr/include/GL/osmesa.h ] && backends="$backends osmesa"
cat >"$SBRT_GISDBASE/render_one.sh" <<'EOS'
set -euo pipefail
size=$1 tools=$2 backends=$3
map=geo_$size
[ -n "$(g.list type=raster_3d pattern=$map)" ] || "$tools/make_geomodel.sh" "$size" "$map" >/dev/null
[ -n "$(g.list type=sbrt pattern=$map 2>/dev/null)" ] || [ -e "$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/PERMANENT/sbrt/$map" ] ||
    r3.sbrt.convert --q input=$map output=$map
g.region --q raster_3d=$map
g.region --q rows=884 cols=1056 # the top view's pixels; 3D views: size=
size_m=$(r3.sbrt.convert -g input=$map | awk -F= '
    $1=="north"{n=$2} $1=="south"{s=$2} $1=="east"{e=$2} $1=="west"{w=$2} $1=="top"{t=$2} $1=="bottom"{b=$2}
    END { printf "%.6f", sqrt((n-s)^2 + (e-w)^2 + (t-b)^2) }')
tolerance=$(awk -v s="$size_m" 'BEGIN { printf "%.9f", 1e-4 * s }') # r.mapcalc reads no 1e-4
run() { # backend view-options... -> "best_ms best_mrays renderer wall_s"
    local backend=$1; shift
    local best="" renderer="cpu" wall=""
    for i in 1 2 3; do
        /usr/bin/time -f "%e" -o /tmp/r3sbrt_rtime r3.sbrt.render --o --verbose input=$map \
            output=b_$backend material=b_${backend}_m depth=b_${backend}_d backend=$backend \
            size=1056,884 "$@" \
            2>/tmp/r3sbrt_rlog >/dev/null
        ms=$(sed -n 's/.*tracing: .* rays in \([0-9.]*\) ms.*/\1/p' /tmp/r3sbrt_rlog)
        r=$(sed -n 's/^GL_RENDERER: \(.*\)/\1/p' /tmp/r3sbrt_rlog | cut -d'(' -f1 | tr -d ' ')
        [ -n "$r" ] && renderer=$r
        w=$(cat /tmp/r3sbrt_rtime)
        if [ -z "$best" ] || awk -v a="$ms" -v b="$best" 'BEGIN{exit !(a<b)}'; then best=$ms; wall=$w; fi
    done
    awk -v ms="$best" -v r="$renderer" -v w="$wall" 'BEGIN { printf "%.1f %.2f %s %.2f\n", ms, 1056*884/ms/1000, r, w }'
}
agreement() { # backend -> "disagreeing_pixels agree% depth_error_p99.9/size"
    # agree: both miss, or the same material at depths within 1e-4 of the size;
    # read in the image's own window (size= of a 3D view: square cells)
    g.region --q --o save=b_keep
    g.region --q raster=b_cpu_m
    r.mapcalc --q --o expression="b_dis = if(isnull(b_cpu_m) && isnull(b_$1_m), 0, if(isnull(b_cpu_m) || isnull(b_$1_m), 1, b_cpu_m != b_$1_m || abs(b_cpu_d - b_$1_d) >= $tolerance))"
    r.mapcalc --q --o expression="b_ddiff = abs(b_cpu_d - b_$1_d)"
    local diff p999
    diff=$(r.univar -g map=b_dis | sed -n 's/^sum=//p')
    p999=$(r.univar -ge map=b_ddiff percentile=99.9 | sed -n 's/^percentile_99_9=//p')
    g.region --q region=b_keep
    awk -v d="$diff" -v m="${p999:-0}" -v s="$size_m" 'BEGIN { printf "%d %.3f%% %.2e\n", d, 100*(1 - d/(1056*884)), m/s }'
}
for view in oblique top grazing; do
    case $view in
        oblique) opts=() ;;
        top) opts=(view=top) ;;
        grazing) opts=(azimuth=100 elevation=4) ;;
    esac
    read -r cms cmr _ cw < <(run cpu "${opts[@]}")
    echo "render size=$size view=$view backend=cpu ms=$cms Mrays/s=$cmr module_s=$cw"
    for b in $backends; do
        read -r gms gmr gr gw < <(run "$b" "${opts[@]}")
        read -r d agree derr < <(agreement "$b")
        echo "render size=$size view=$view backend=$b renderer=$gr ms=$gms Mrays/s=$gmr module_s=$gw gpu/cpu_time=$(awk -v a=$gms -v b=$cms 'BEGIN{printf "%.2f", a/b}') disagree=$d agree=$agree depth_error_p99.9/size=$derr"
    done
done
EOS
for s in $sizes; do
    in_grass PERMANENT bash "$SBRT_GISDBASE/render_one.sh" "$s" "$SBRT_ROOT/tools" "$backends" 2>&1 | grep "^render"
done
