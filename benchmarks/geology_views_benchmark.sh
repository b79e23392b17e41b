#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/geology_views_benchmark.sh (r3.sbrt addon)
# PURPOSE:   Figures of the geological-operations issue: the time per
#            frame of each demo view (tools/geology_scene.sh: the paper's
#            Figure 12 views, a fence diagram, the logged wells alone) at
#            1056 x 884 relative to the full model's, in one run, best of 3,
#            on the CPU ray caster and (where it draws the view) on EGL; the
#            bytes the borehole-only view traces against the full model's.
# USAGE:     make && benchmarks/geology_views_benchmark.sh [SIZE]  (A)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
. "$(dirname "$0")/../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
size=${1:-A}
cat >"$SBRT_GISDBASE/geology_views.sh" <<'EOS'
set -euo pipefail
size=$1 tools=$2
map=geology
[ -n "$(g.list type=raster_3d pattern=$map)" ] || "$tools/make_geomodel.sh" "$size" "$map" >/dev/null
r3.sbrt.convert --q --o input=$map output=$map
TMPDIR_SCENE=$(g.gisenv get=GISDBASE)
. "$tools/geology_scene.sh"
make_geology_inputs
g.region --q rows=884 cols=1056
run() { # backend view-options... -> "best_trace_ms wall_s" (best of 3)
    local backend=$1; shift
    local best="" wall=""
    for i in 1 2 3; do
        /usr/bin/time -f "%e" -o /tmp/r3sbrt_gtime r3.sbrt.render --o --verbose \
            input=$map output=g_$backend zexag=2 size=1056,884 backend=$backend "$@" 2>/tmp/r3sbrt_glog >/dev/null
        ms=$(sed -n 's/.*tracing: .* rays in \([0-9.]*\) ms.*/\1/p' /tmp/r3sbrt_glog)
        if [ -z "$best" ] || awk -v a="$ms" -v b="$best" 'BEGIN{exit !(a<b)}'; then
            best=$ms; wall=$(cat /tmp/r3sbrt_gtime)
        fi
    done
    echo "$best $wall"
}
printf "%-10s %10s %10s %8s %10s %10s\n" view cpu_ms cpu/full wall_s egl_ms egl/full
full_cpu="" full_egl=""
for entry in "${GEOLOGY_VIEWS[@]}"; do
    name=${entry%%|*}
    read -r -a opts <<<"${entry#*|}"
    read -r cpu_ms cpu_wall < <(run cpu "${opts[@]}")
    egl_ms="-"
    case " ${opts[*]} " in
        *" boreholes="*|*" fence="*) ;; # drawn by the CPU ray caster only
        *) read -r egl_ms _ < <(run egl "${opts[@]}") ;;
    esac
    [ -z "$full_cpu" ] && { full_cpu=$cpu_ms; full_egl=$egl_ms; }
    awk -v n="$name" -v c="$cpu_ms" -v fc="$full_cpu" -v w="$cpu_wall" -v g="$egl_ms" -v fg="$full_egl" 'BEGIN {
        gr = g == "-" ? "-" : sprintf("%.2f", g / fg)
        printf "%-10s %10.1f %10.2f %8.2f %10s %10s\n", n, c, c / fc, w, g, gr }'
done
# bytes: what the borehole-only view traces against the whole model
r3.sbrt.render --o --verbose input=$map output=g_bytes zexag=2 backend=cpu -b boreholes=wells \
    2>&1 >/dev/null | tr '\n' ' ' | sed -n 's/.*\(Boreholes: [^;]*\);.*/\1\n/p'
EOS
in_grass PERMANENT bash "$SBRT_GISDBASE/geology_views.sh" "$size" "$SBRT_ROOT/tools"
