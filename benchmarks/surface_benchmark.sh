#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/surface_benchmark.sh (r3.sbrt addon)
# PURPOSE:   The thickness map of a class set (issue 30's targets: >= 100x
#            faster than the GRASS route, within 3x of reading the SBRT),
#            one run per figure, all in the same run: r3.sbrt.surface
#            thickness=; the GRASS route (r3.mapcalc of the set as 0/1,
#            r3.to.rast into one map per level, r.series method=sum, times
#            tbres with r.mapcalc); reading the SBRT (r3.sbrt.convert -p);
#            r3.sbrt.volume of every class. Checks that both thickness maps
#            are the same, prints the times and ratios; never fails on time.
# USAGE:     make && benchmarks/surface_benchmark.sh [MODELS]
#            MODELS: T S A B C (tools/make_geomodel.sh; C, 800 x 1000 x
#            800 voxels, takes ~10 min to make once) or national (a
#            GeoTOP-like model of 2647 x 2812 x 313 voxels, made, imported
#            and expanded into a 3D raster once: the GRASS route alone
#            takes about an hour on 2 cores). Default: C
#            CLASSES= the set (default 2,8,14: both sandstones and the
#            gravel aquifer of the demo geology; national: 5,6,7, the
#            fine, medium and coarse sand of GeoTOP's lithoclasses)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
data=${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}
classes=${CLASSES:-2,8,14}
sbrt_location "$data"

# the timed runs, inside GRASS in a mapset of their own:
# surface_one.sh MAP CLASSES (MAP: the 3D raster and its SBRT, same name)
cat >"$data/surface_one.sh" <<'EOS'
set -euo pipefail
name=$1 classes=$2
t() { /usr/bin/time -f "%e %M" -o /tmp/r3sbrt_surface_time "$@" >/dev/null 2>/tmp/r3sbrt_surface_err ||
      { cat /tmp/r3sbrt_surface_err >&2; exit 1; }; cat /tmp/r3sbrt_surface_time; }
g.region --q raster_3d="$name"
eval "$(g.region -3 -g)"
eval "$(r3.sbrt.convert -g input="$name")"
# the set as an r3.mapcalc condition: map == 2 || map == 8 || ...
condition=$(echo "$classes" | tr ',' '\n' | sed "s/.*/$name == &/" | paste -sd'|' | sed 's/|/ || /g')

read -r read_s read_kb < <(t r3.sbrt.convert -p input="$name")
read -r sbrt_s sbrt_kb < <(t r3.sbrt.surface --o input="$name" classes="$classes" thickness=sb_thickness)
read -r vol_s vol_kb < <(t r3.sbrt.volume --o input="$name" format=csv output=/tmp/r3sbrt_surface_volumes.csv)

# the GRASS route, each step timed
read -r mc_s _ < <(t r3.mapcalc --o "sb_set = if(isnull($name), 0, if($condition, 1, 0))")
read -r slice_s _ < <(t r3.to.rast --o input=sb_set output=sb_slice)
slices=$(g.list type=raster pattern="sb_slice_*" mapset=. separator=comma)
read -r series_s _ < <(t r.series --o input="$slices" method=sum output=sb_count)
read -r calc_s _ < <(t r.mapcalc --o "sb_reference = if(sb_count > 0, sb_count * $tbres, null())")
g.remove --q -f type=raster pattern="sb_slice_*"
g.remove --q -f type=raster_3d name=sb_set

# the same map both ways: no cell differs, nulls in the same cells
r.mapcalc --q --o "sb_differ = if(isnull(sb_thickness) != isnull(sb_reference) ||| sb_thickness != sb_reference, 1, 0)"
differ=$(r.univar -g sb_differ | sed -n 's/^sum=//p')
cells=$(r.univar -g sb_thickness | sed -n 's/^n=//p')
grass_s=$(echo "$mc_s $slice_s $series_s $calc_s" | awk '{ print $1 + $2 + $3 + $4 }')
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.1f", a / b; else print "inf" }'; }
printf "surface %s: model %d x %d x %d voxels, %d intervals, stacks file %d bytes; classes %s\n" \
    "$name" "$cols" "$rows" "$depths" "$intervals" "$file_bytes" "$classes"
echo "surface $name: r3.sbrt.surface thickness=: ${sbrt_s} s, peak RSS $((sbrt_kb / 1024)) MiB ($cells cells with the set)"
echo "surface $name: reading the SBRT (r3.sbrt.convert -p): ${read_s} s, peak RSS $((read_kb / 1024)) MiB"
echo "surface $name: GRASS route: ${grass_s} s (r3.mapcalc ${mc_s}, r3.to.rast ${slice_s}, r.series ${series_s}, r.mapcalc ${calc_s})"
echo "surface $name: r3.sbrt.volume of every class: ${vol_s} s"
echo "surface $name: cells that differ from the GRASS route: $differ"
echo "surface $name: GRASS route / r3.sbrt.surface = $(ratio "$grass_s" "$sbrt_s") (target >= 100)"
echo "surface $name: r3.sbrt.surface / reading the SBRT = $(ratio "$sbrt_s" "$read_s") (target <= 3)"
EOS

for model in ${*:-C}; do
    if [ "$model" = national ]; then
        name=geotop_2647x2812
        in_grass PERMANENT bash -c ". '$SBRT_ROOT/tools/bench_model.sh' &&
            geotop_bench_model 2647 2812 313 '$data' '$SBRT_ROOT/tools' 3d" >/dev/null 2>&1
        set_classes=${CLASSES:-5,6,7}
    else
        name=geo_$model
        in_grass PERMANENT bash -c ". '$SBRT_ROOT/tools/bench_model.sh' && bench_model $model '$SBRT_ROOT/tools'" >/dev/null 2>&1
        set_classes=$classes
    fi
    in_grass surface_bench bash "$data/surface_one.sh" "$name" "$set_classes" 2>&1 | grep "^surface \|ERROR"
done
