#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/channels_benchmark.sh (r3.sbrt addon)
# PURPOSE:   Property channels (issue 29) of a GeoTOP-like model: generate
#            it with kans_1..9, onz_lk, onz_ls; read the twelve variables
#            once through the netCDF library (the baseline); import lithok
#            alone and with the eleven channels (-a); bytes per valid voxel
#            on disk, time and peak RSS of each, in one run; then -r of one
#            channel (SBRT_BENCH_NO_EXPORT=1 leaves -r out: at national
#            size it writes a 3D raster of 2.3 billion voxels).
# USAGE:     make && benchmarks/channels_benchmark.sh [NX NY NZ]
#            (default 1000 1000 313; national size: 2647 2812 313)
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
file=$data/geotop_channels_${nx}x${ny}x${nz}.nc
if [ ! -s "$file" ]; then
    start=$(date +%s.%N)
    "$gen" write "$file.part" "$nx" "$ny" "$nz" properties && mv "$file.part" "$file"
    echo "generate: $(echo "$(date +%s.%N) - $start" | bc) s, $(stat -c %s "$file") bytes"
fi
sync
variables="lithok kans_1 kans_2 kans_3 kans_4 kans_5 kans_6 kans_7 kans_8 kans_9 onz_lk onz_ls"
echo "baseline, lithok once: $("$gen" read "$file" lithok)"
echo "baseline, the twelve variables once: $("$gen" read "$file" $variables)"

cat >"$data/channels_one.sh" <<'EOS'
set -euo pipefail
file=$1
t() { /usr/bin/time -f "%e %M" -o /tmp/r3sbrt_time "$@" >/dev/null 2>/tmp/r3sbrt_err ||
      { cat /tmp/r3sbrt_err >&2; exit 1; }; cat /tmp/r3sbrt_time; }
read -r cls_s cls_kb < <(t r3.sbrt.convert --o -o file="$file" variable=lithok output=classes)
read -r all_s all_kb < <(t r3.sbrt.convert --o -o -a file="$file" variable=lithok output=channels)
echo "import lithok alone:            ${cls_s} s, peak RSS $((cls_kb / 1024)) MiB"
echo "import lithok + 11 channels:    ${all_s} s, peak RSS $((all_kb / 1024)) MiB"
r3.sbrt.convert -p sbrt=channels | sed -n '/^Property channels/,$p'
eval "$(r3.sbrt.convert -g sbrt=channels | grep -v '|')"
dir=$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/$(g.gisenv get=MAPSET)/sbrt/channels
member=$(stat -c %s "$dir/channels")
valid=$(r3.sbrt.convert -g sbrt=channels | grep '^channel=kans_1|' | sed 's/.*|valid=\([0-9]*\)|.*/\1/')
awk -v b=$member -v v=$valid 'BEGIN { printf "channels member: %d bytes = %.3f bytes per valid voxel for all eleven, header, directory and block tables included\n", b, b / v }'
r3.sbrt.convert -s sbrt=channels
[ -n "${SBRT_BENCH_NO_EXPORT:-}" ] && exit 0
read -r exp_s exp_kb < <(t r3.sbrt.convert --o -r sbrt=channels property=kans_5 output=kans_5_back)
echo "-r property=kans_5:             ${exp_s} s, peak RSS $((exp_kb / 1024)) MiB"
EOS
SBRT_BENCH_NO_EXPORT=${SBRT_BENCH_NO_EXPORT:-} in_grass bench bash "$data/channels_one.sh" "$file" 2>&1 | grep -v '^Starting GRASS\|^Cleaning up\|^Executing\|^Execution of'
