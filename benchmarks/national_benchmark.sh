#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/national_benchmark.sh (r3.sbrt addon)
# PURPOSE:   A GeoTOP-like NetCDF model of any size end to end: generate it
#            (deterministic, tiled writing), read it once through the netCDF
#            library (the baseline), import it (r3.sbrt.convert file=), -g,
#            a top view, a 1056x884 perspective view and a cross section;
#            time, peak RSS and bytes of each, in one run.
# USAGE:     make && benchmarks/national_benchmark.sh [NX NY NZ]
#            (default 1000 1000 313; GeoTOP's national size: 2647 2812 313)
#            EXPAND=1 also expands the SBRT into a 3D raster (-r) and
#            compares its compressed grid3 size.
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
nx=${1:-1000} ny=${2:-1000} nz=${3:-313}
data=${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}
sbrt_location "$data"
make -s -C "$here/geotop_like" build/geotop_like
gen=$here/geotop_like/build/geotop_like
file=$data/geotop_like_${nx}x${ny}x${nz}.nc
if [ ! -s "$file" ]; then
    start=$(date +%s.%N)
    "$gen" write "$file.part" "$nx" "$ny" "$nz" && mv "$file.part" "$file"
    echo "generate: $(echo "$(date +%s.%N) - $start" | bc) s, $(stat -c %s "$file") bytes"
fi
sync
read_once=$("$gen" read "$file")
echo "baseline (netCDF library, read once): $read_once"

cat >"$data/national_one.sh" <<'EOS'
set -euo pipefail
file=$1 name=$2 expand=$3
t() { /usr/bin/time -f "%e %M" -o /tmp/r3sbrt_time "$@" >/dev/null 2>/tmp/r3sbrt_err ||
      { cat /tmp/r3sbrt_err >&2; exit 1; }; cat /tmp/r3sbrt_time; }
read -r imp_s imp_kb < <(t r3.sbrt.convert --o -o file="$file" variable=lithok output="$name")
read -r g_s g_kb < <(t r3.sbrt.convert -g sbrt="$name")
eval "$(r3.sbrt.convert -g sbrt="$name")"
dir=$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/$(g.gisenv get=MAPSET)/sbrt/$name
stacks=$(stat -c %s "$dir/stacks")
r3.sbrt.convert -s sbrt="$name" # 2D and 3D: -r (EXPAND=1) expands in the model's grid
read -r top_s top_kb < <(t r3.sbrt.render --o input="$name" view=top output="${name}_top" png="/tmp/${name}_top.png")
read -r per_s per_kb < <(t r3.sbrt.render --o input="$name" size=1056,884 zexag=30 output="${name}_view" png="/tmp/${name}_view.png")
y=$(echo "($north + $south) / 2" | bc -l)
read -r sec_s sec_kb < <(t r3.sbrt.render --o input="$name" size=1056,884 zexag=30 section=$west,$y,$east,$y output="${name}_section" png="/tmp/${name}_section.png")
printf "model: %d x %d x %d voxels, %d intervals (%.2f per column), %d materials\n" \
    "$cols" "$rows" "$depths" "$intervals" "$mean_stack" "$materials"
echo "import:            ${imp_s} s, peak RSS $((imp_kb / 1024)) MiB"
echo "describe (-g):     ${g_s} s, peak RSS $((g_kb / 1024)) MiB"
echo "top view ${cols}x${rows}: ${top_s} s, peak RSS $((top_kb / 1024)) MiB"
echo "perspective 1056x884: ${per_s} s, peak RSS $((per_kb / 1024)) MiB"
echo "cross section 1056x884: ${sec_s} s, peak RSS $((sec_kb / 1024)) MiB"
awk -v st=$stacks -v mem=$sbrt_bytes -v iv=$intervals -v v=$voxels -v fmt=$format \
    -v per_iv=$memory_bytes_per_interval -v per_cell=$memory_index_bytes_per_cell 'BEGIN {
  printf "stacks file (format %s): %.0f bytes = %.2f bytes per interval, index and materials included; 4-byte voxels: %.0f bytes (%.2f %% smaller)\n",
    fmt, st, st / iv, 4 * v, 100 * (1 - st / (4 * v))
  printf "in memory: %.0f bytes = %.2f bytes per interval, index and materials included (%.2f %% smaller than 4-byte voxels)\n",
    mem, mem / iv, 100 * (1 - mem / (4 * v))
  printf "in memory and on the GPU (5-SSBO): %.2f bytes per interval plus %.2f per cell (index)\n", per_iv, per_cell }'
if [ "$expand" = 1 ]; then
    read -r back_s back_kb < <(t r3.sbrt.convert --o -r sbrt="$name" output="${name}_voxels")
    grid3=$(du -sb "$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/$(g.gisenv get=MAPSET)/grid3/${name}_voxels" | cut -f1)
    echo "expand (-r):       ${back_s} s, peak RSS $((back_kb / 1024)) MiB; compressed grid3 $grid3 bytes (stacks file $(echo "scale=2; $stacks / $grid3" | bc)x of it)"
fi
EOS
in_grass PERMANENT bash "$data/national_one.sh" "$file" "geotop_${nx}x${ny}" "${EXPAND:-0}" 2>&1 |
    grep -v "^Starting GRASS\|^Cleaning up\|^Executing\|^Execution of"
