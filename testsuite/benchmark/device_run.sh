#!/usr/bin/env bash
############################################################################
# MODULE:    testsuite/benchmark/device_run.sh (r3.sbrt addon)
# PURPOSE:   On the device machine (see device_bundle.sh): the GPU figures
#            of issues 15 and 19 and the CPU's scaling, printed:
#            - per model and view (the peers' oblique, the worst view,
#              grazing), 1056 x 884: the GPU's whole frame (traced, shaded,
#              RGB back in host memory) against its dispatch and against
#              the same machine's CPU frame on all cores; kernel normals
#              against face normals on the GPU;
#            - 800 x 600 frames per second (the viewer's renderer alone);
#            - model B, the peers' view with 100 boreholes drawn with the
#              model (GPU against CPU);
#            - model B, the peers' view on the CPU on 1, 2, 4, 8, 16 cores.
#            Runs here too (llvmpipe), which checks the script.
# USAGE:     bash .device/device_run.sh [SIZES] (A B C)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
bundle=$(cd "$(dirname "$0")" && pwd)
export LD_LIBRARY_PATH=$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export SBRT_PROGRAM_CACHE=off # every run compiles: figures of a first run
bench=$bundle/trace_bench
data=$(mktemp -d /tmp/sbrt_device.XXXXXX)
sizes=${*:-A B C}
views=(
    "best position=4375,5000,2500 target=1000,1250,320 fov=25 zexag=2"
    "worst position=2600,1250,640 target=1000,1250,560 fov=40 zexag=2"
    "grazing position=-1500,-1000,700 target=1000,1250,550 fov=40 zexag=2"
)
cores=$(nproc)
for size in $sizes; do
    tar -C "$data" -xzf "$bundle/sbrt/geo_$size.tar.gz"
    for view in "${views[@]}"; do
        set -- $view
        name=$1
        shift
        "$bench" gpu_frame "$data/geo_$size" "$@" label="$size/$name" repeat=5 \
            threads="$cores" | sed "s/^/device size=$size view=$name /"
        "$bench" gpu_frame "$data/geo_$size" "$@" label="$size/$name" repeat=5 \
            threads="$cores" cols=800 rows=600 | sed "s/^/device size=$size view=$name /"
    done
done
# the CPU's scaling, model B where it was bundled; 100 boreholes drawn
# with the model on the GPU
if [ -f "$bundle/sbrt/geo_B.tar.gz" ]; then
    [ -d "$data/geo_B" ] || tar -C "$data" -xzf "$bundle/sbrt/geo_B.tar.gz"
    "$bench" gpu_frame "$data/geo_B" ${views[0]#best } label=B/boreholes repeat=5 \
        threads="$cores" boreholes=100 radius=20 | sed "s/^/device size=B view=best /"
    for n in 1 2 4 8 16; do
        [ "$n" -le "$cores" ] || break
        taskset -c "0-$((n - 1))" "$bench" frame "$data/geo_B" ${views[0]#best } \
            threads="$n" repeat=5 reference=0 | sed "s/^/device scaling cores=$n /"
    done
fi
rm -rf "$data"
