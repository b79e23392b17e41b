#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/format_benchmark.sh (r3.sbrt addon)
# PURPOSE:   The stacks file in format 1 (8 bytes an interval) and format 2
#            (zstd blocks) on the demo models and, where the national
#            benchmark made it, the national-size model: bytes, bytes per
#            interval, load (warm) and write, best of N taken in turns
#            (trace_bench format). Figures only: never part of pass/fail.
# USAGE:     make && benchmarks/format_benchmark.sh [SIZES] (A B)
#            SBRT_BENCH_REPEAT (7)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
make -s -C "$here/trace_bench" >/dev/null
cat >"$SBRT_GISDBASE/format_one.sh" <<'EOS'
set -euo pipefail
tools=$1 bench=$2 repeat=$3
shift 3
. "$tools/bench_model.sh"
for size in "$@"; do
    bench_model "$size" "$tools" # sets sbrt=
    "$bench" format "$sbrt" repeat="$repeat" label="$size"
done
national=$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/PERMANENT/sbrt/geotop_2647x2812
[ ! -e "$national" ] || "$bench" format "$national" repeat=3 label=national
EOS
in_grass PERMANENT bash "$SBRT_GISDBASE/format_one.sh" "$SBRT_ROOT/tools" \
    "$here/trace_bench/build/trace_bench" "${SBRT_BENCH_REPEAT:-7}" ${*:-A B} 2>&1 |
    grep "^format"
