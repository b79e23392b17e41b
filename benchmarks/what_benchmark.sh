#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/what_benchmark.sh (r3.sbrt addon)
# PURPOSE:   The time of a 1000-point r3.sbrt.what (issue 30's target: under
#            a second at national size), one run per figure: 1000 points
#            scattered over the whole model (every block read), 1000 points
#            in a box of 1/20 of the extent (only the blocks under it read),
#            one point, and the 1000 scattered points from a vector map.
#            Prints the figures; never fails on time.
# USAGE:     make && benchmarks/what_benchmark.sh [MODELS]
#            MODELS: T S A B C (tools/make_geomodel.sh; C, 800 x 1000 x
#            800 voxels, takes ~10 min to make once) or national (a
#            GeoTOP-like NetCDF model of 2647 x 2812 x 313 voxels, made and
#            imported once as national_benchmark.sh does) or NXxNYxNZ for
#            a GeoTOP-like model of that size. Default: C
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
data=${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}
sbrt_location "$data"

# the timed queries, inside GRASS: what_one.sh SBRT
cat >"$data/what_one.sh" <<'EOS'
set -euo pipefail
name=$1
t() { /usr/bin/time -f "%e %M" -o /tmp/r3sbrt_what_time "$@" >/dev/null 2>/tmp/r3sbrt_what_err ||
      { cat /tmp/r3sbrt_what_err >&2; exit 1; }; cat /tmp/r3sbrt_what_time; }
eval "$(r3.sbrt.convert -g input="$name")"
# 1000 points at fixed random places (seed 42), all over the model and in
# a box of 1/20 of its width and height at its centre
points() { # FRACTION -> x,y,x,y,... on one line
    awk -v f="$1" -v n="$north" -v s="$south" -v e="$east" -v w="$west" 'BEGIN {
        srand(42); cx = (e + w) / 2; cy = (n + s) / 2
        for (i = 0; i < 1000; ++i) {
            x = cx + (rand() - 0.5) * f * (e - w); y = cy + (rand() - 0.5) * f * (n - s)
            printf "%s%.3f,%.3f", i ? "," : "", x, y } }'
}
scattered=$(points 1)
clustered=$(points 0.05)
one="$(echo "$scattered" | cut -d, -f1-2)"
echo "$scattered" | tr ',' '\n' | paste -d'|' - - |
    v.in.ascii --q --o input=- output=what_bench_points separator=pipe x=1 y=2
read -r all_s all_kb < <(t r3.sbrt.what --o input="$name" coordinates="$scattered" format=csv output=/tmp/r3sbrt_what.csv)
layers=$(($(wc -l </tmp/r3sbrt_what.csv) - 1))
read -r box_s box_kb < <(t r3.sbrt.what --o input="$name" coordinates="$clustered" format=csv output=/tmp/r3sbrt_what_box.csv)
read -r one_s one_kb < <(t r3.sbrt.what --o input="$name" coordinates="$one" format=csv output=/tmp/r3sbrt_what_one.csv)
read -r vec_s vec_kb < <(t r3.sbrt.what --o input="$name" points=what_bench_points format=csv output=/tmp/r3sbrt_what_vec.csv)
# the same logs both ways (the vector points have categories)
cmp -s <(cut -d, -f1-3,5- /tmp/r3sbrt_what.csv) <(cut -d, -f1-3,5- /tmp/r3sbrt_what_vec.csv) ||
    echo "what $name: WARNING: the vector points' logs differ from the coordinates'"
printf "what %s: model %d x %d x %d voxels, %d intervals, stacks file %d bytes\n" \
    "$name" "$cols" "$rows" "$depths" "$intervals" "$file_bytes"
echo "what $name: 1000 scattered points: ${all_s} s, peak RSS $((all_kb / 1024)) MiB ($layers layers logged)"
echo "what $name: 1000 points in 1/20 of the extent: ${box_s} s, peak RSS $((box_kb / 1024)) MiB"
echo "what $name: 1 point: ${one_s} s, peak RSS $((one_kb / 1024)) MiB"
echo "what $name: 1000 points from a vector map: ${vec_s} s, peak RSS $((vec_kb / 1024)) MiB"
EOS

# the GeoTOP-like model NXxNYxNZ, generated and imported once
geotop_sbrt() {
    in_grass what_bench bash -c ". '$SBRT_ROOT/tools/bench_model.sh' &&
        geotop_bench_model $1 $2 $3 '$data' '$SBRT_ROOT/tools'" >/dev/null 2>&1
    echo "geotop_${1}x${2}"
}

for model in ${*:-C}; do
    case $model in
    national) name=$(geotop_sbrt 2647 2812 313) ;;
    *x*x*) IFS=x read -r nx ny nz <<<"$model"; name=$(geotop_sbrt "$nx" "$ny" "$nz") ;;
    *)
        name=geo_$model
        in_grass PERMANENT bash -c ". '$SBRT_ROOT/tools/bench_model.sh' && bench_model $model '$SBRT_ROOT/tools'" >/dev/null 2>&1
        ;;
    esac
    # in a mapset of its own: models of PERMANENT are found through the
    # search path, and other benchmarks may hold PERMANENT meanwhile
    in_grass what_bench bash "$data/what_one.sh" "$name" 2>&1 | grep "^what \|ERROR"
done
