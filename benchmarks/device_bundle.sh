#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/device_bundle.sh (r3.sbrt addon)
# PURPOSE:   Readies the GPU figures of issues 15, 19 and 32 for the device
#            machine (an NVIDIA GPU, 16 cores, no GRASS, no network): puts
#            into .device/ trace_bench and the unit tests (GRASS-free;
#            BASE_BENCH=path adds another build's trace_bench as
#            trace_bench_base, measured in the same run), machine_probe,
#            the shared libraries
#            it needs beyond the C/C++ runtime, the SBRTs of the sizes
#            given (gzipped), a GeoTOP-like model with its eleven
#            property channels (200 x 200 x 160, paint_gt: issue 29's GPU
#            property view) and device_run.sh, and Debian's glvnd
#            packages into .gl/; both folders are ignored by git
#            (.git/info/exclude). Prints the command for the device tool
#            (carry .device and .gl).
# USAGE:     make && [BASE_BENCH=path] [NATIONAL=1] benchmarks/device_bundle.sh [SIZES] (A B C)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
. "$root/tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
sizes=${*:-A B C}
cd "$root"
mkdir -p .git/info
for folder in .device .gl; do
    grep -qx "/$folder/" .git/info/exclude 2>/dev/null || echo "/$folder/" >>.git/info/exclude
done
rm -rf .device && mkdir -p .device/lib .device/sbrt .gl
make -s -C benchmarks/trace_bench >/dev/null
make -s -C testsuite/unit build/sbrt_unit_tests >/dev/null
make -s -C benchmarks/machine_probe >/dev/null
cp benchmarks/trace_bench/build/trace_bench testsuite/unit/build/sbrt_unit_tests \
    benchmarks/machine_probe/build/machine_probe benchmarks/device_run.sh \
    .device/
# another build's trace_bench for figures of both in one run (BASE_BENCH=path)
[ -n "${BASE_BENCH:-}" ] && cp "$BASE_BENCH" .device/trace_bench_base
strip --strip-debug .device/trace_bench* .device/sbrt_unit_tests .device/machine_probe
# what the binary links beyond the C/C++ runtime and GL (the debs bring GL)
ldd .device/trace_bench | awk '/=> \// { print $3 }' |
    grep -vE '/(libc|libm|libstdc\+\+|libgcc_s|ld-linux[^/]*|libEGL|libGL[^/]*|libOpenGL|libGLdispatch|libdl|libpthread)\.so' |
    xargs -r -I{} cp -L {} .device/lib/
# the models, made and converted where the data lack them
cat >"$SBRT_GISDBASE/device_models.sh" <<'EOS'
set -euo pipefail
. "$1/bench_model.sh"
shift
for size in "$@"; do
    bench_model "$size" "$TOOLS" >/dev/null
    tar -C "$(dirname "$sbrt")" -czf "$OUT/geo_$size.tar.gz" "geo_$size"
done
EOS
TOOLS=$root/tools OUT=$root/.device/sbrt in_grass PERMANENT bash "$SBRT_GISDBASE/device_models.sh" \
    "$root/tools" $sizes
# a GeoTOP-like model with property channels (issue 29)
make -s -C benchmarks/geotop_like build/geotop_like
paint_nc=$SBRT_GISDBASE/geotop_channels_200x200x160.nc
[ -s "$paint_nc" ] || benchmarks/geotop_like/build/geotop_like write "$paint_nc" \
    200 200 160 properties >/dev/null
[ -d "$SBRT_GISDBASE/loc/PERMANENT/sbrt/paint_gt" ] ||
    in_grass PERMANENT r3.sbrt.convert --q -a -o file="$paint_nc" variable=lithok output=paint_gt
tar -C "$SBRT_GISDBASE/loc/PERMANENT/sbrt" -czf .device/sbrt/paint_gt.tar.gz paint_gt
# the national GeoTOP-like model, with its column members, without its
# coarse level (NATIONAL=1: issue 49's GPU pages; about 35 MB gzipped)
if [ "${NATIONAL:-0}" = 1 ]; then
    national=$SBRT_GISDBASE/loc/PERMANENT/sbrt/geotop_2647x2812
    [ -d "$national" ] || in_grass PERMANENT bash -c \
        ". '$root/tools/bench_model.sh'; geotop_bench_model 2647 2812 313 '$SBRT_GISDBASE' '$root/tools'"
    staged=$(mktemp -d)
    mkdir "$staged/national"
    find "$national" -maxdepth 1 -type f ! -name stacks_lod -exec cp {} "$staged/national/" \;
    tar -C "$staged" -czf .device/sbrt/national.tar.gz national
    rm -rf "$staged"
fi
(cd .gl && apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null)
du -sh .device .gl
echo "device command (carry .device and .gl):"
echo "for f in .gl/*.deb; do dpkg -x \$f /; done; ldconfig; bash .device/device_run.sh $sizes"
