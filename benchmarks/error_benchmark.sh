#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/error_benchmark.sh (r3.sbrt addon)
# PURPOSE:   Time against error on the synthetic models with the peers'
#            camera at 1056 x 884: the exact method (CPU, and GL where a
#            context opens), the sampled one (steps 1..1/16 cell), the
#            adaptive one, kernel normals k = 3..11, each against the exact
#            CPU reference; then the plot (PNG), with ParaView's volume
#            rendering of the same voxels as one point where
#            peers_benchmark.sh has left its image (/tmp/peers/out).
# USAGE:     make && benchmarks/error_benchmark.sh [SIZES]  (A)
#            PLOT=path.png (default /tmp/r3sbrt_time_error_A.png)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
make -s -C "$here/trace_bench" >/dev/null
bench=$here/trace_bench/build/trace_bench
for s in ${*:-A}; do
    in_grass PERMANENT bash -c "[ -n \"\$(g.list type=raster_3d pattern=geo_$s)\" ] || $SBRT_ROOT/tools/make_geomodel.sh $s geo_$s >/dev/null
        g.region --q raster_3d=geo_$s && r3.sbrt.convert --o --q input=geo_$s output=geo_$s" >/dev/null 2>&1
    dir=$SBRT_GISDBASE/loc/PERMANENT/sbrt/geo_$s
    lines=/tmp/r3sbrt_time_error_$s.txt
    "$bench" error "$dir" position=4375,5000,2500 target=1000,1250,320 fov=25 zexag=2 \
        repeat=3 classes=/tmp/r3sbrt_classes_$s.i32 | tee "$lines"
    plot=${PLOT:-/tmp/r3sbrt_time_error_$s.png}
    pv=()
    pv_png=/tmp/peers/out/pv_${s}_volume.png
    if [ -e "$pv_png" ] && [ -e "/tmp/peers/pv_$s.txt" ]; then
        later=$(awk '/mode=volume frame=[12] /{ split($0, a, "seconds="); v = a[2] + 0; if (m == "" || v < m) m = v } END { print m }' "/tmp/peers/pv_$s.txt")
        pv=(--classes "/tmp/r3sbrt_classes_$s.i32" --paraview "$pv_png" --paraview-seconds "$later")
    fi
    /usr/bin/python3 "$here/plot_time_error.py" "$lines" "$plot" "${pv[@]}"
    echo "plot $plot"
done
