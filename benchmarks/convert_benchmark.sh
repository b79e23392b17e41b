#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/convert_benchmark.sh (r3.sbrt addon)
# PURPOSE:   Conversion figures of the foundation issue, per model size:
#            conversion time vs one r3.univar read of the same map (same
#            run), SBRT bytes vs voxel bytes, peak memory of the conversion.
# USAGE:     make && benchmarks/convert_benchmark.sh [SIZES]  (A B)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
. "$(dirname "$0")/../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
sizes=${*:-A B}
cat >"$SBRT_GISDBASE/convert_one.sh" <<'EOS'
set -euo pipefail
size=$1
map=geo_$size
tools=$2
[ -n "$(g.list type=raster_3d pattern=$map)" ] || "$tools/make_geomodel.sh" "$size" "$map" >/dev/null
g.region raster_3d=$map
t() { /usr/bin/time -f "%e %M" -o /tmp/r3sbrt_time "$@" >/dev/null 2>&1; cat /tmp/r3sbrt_time; }
read -r univar_s univar_kb < <(t r3.univar map=$map)
read -r conv_s conv_kb < <(t r3.sbrt.convert --o input=$map output=$map)
read -r back_s back_kb < <(t r3.sbrt.convert --o -r input=$map output=${map}_back)
eval "$(r3.sbrt.convert -g input=$map)"
stacks=$(stat -c %s "$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/$(g.gisenv get=MAPSET)/sbrt/$map/stacks")
awk -v s=$size -v v=$voxels -v vb=$voxel_bytes -v sb=$sbrt_bytes -v fb=$stacks \
    -v iv=$intervals -v mx=$max_stack -v mn=$mean_stack -v c=$compression \
    -v us=$univar_s -v cs=$conv_s -v ck=$conv_kb -v bs=$back_s -v bk=$back_kb 'BEGIN {
  printf "convert size=%s voxels=%d intervals=%d max_stack=%d mean_stack=%.2f\n", s, v, iv, mx, mn
  printf "convert size=%s voxel_MiB=%.2f sbrt_MiB=%.2f file_MiB=%.2f compression=%.1f%%\n", s, vb/1048576, sb/1048576, fb/1048576, c
  printf "convert size=%s r3.univar_s=%.2f convert_s=%.2f ratio_convert/univar=%.2f convert_peak_MiB=%.1f peak/voxel_model=%.3f\n", s, us, cs, cs/us, ck/1024, ck*1024/vb
  printf "convert size=%s reverse_s=%.2f reverse_peak_MiB=%.1f\n", s, bs, bk/1024
}'
EOS
for s in $sizes; do
    in_grass PERMANENT bash "$SBRT_GISDBASE/convert_one.sh" "$s" "$SBRT_ROOT/tools" 2>&1 | grep "^convert"
done
