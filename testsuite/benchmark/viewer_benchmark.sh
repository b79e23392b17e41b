#!/usr/bin/env bash
############################################################################
# MODULE:    testsuite/benchmark/viewer_benchmark.sh (r3.sbrt addon)
# PURPOSE:   g.gui.sbrt's frame rates (issue 19) on a demo model (default
#            B), 800 x 600: the renderer alone through the view server, and
#            the viewer under Xvfb driven by xdotool (viewer_benchmark.py)
# USAGE:     make && testsuite/benchmark/viewer_benchmark.sh [SIZE] (B)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/grass_env.sh"
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
size=${1:-B}
cat >"$SBRT_GISDBASE/viewer_one.sh" <<'EOS'
set -euo pipefail
size=$1 tools=$2 here=$3
. "$tools/bench_model.sh"
bench_model "$size" "$tools" # sets map=
python3 "$here/viewer_benchmark.py" "$map" 800 600
EOS
in_grass PERMANENT bash "$SBRT_GISDBASE/viewer_one.sh" "$size" "$here/../../tools" "$here"
