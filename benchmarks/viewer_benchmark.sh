#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/viewer_benchmark.sh (r3.sbrt addon)
# PURPOSE:   g.gui.sbrt's frame rates (issue 19) on a demo model (default
#            B) or the national one, 800 x 600: the renderer alone through
#            the view server, and the viewer under Xvfb driven by xdotool
#            (viewer_benchmark.py)
# USAGE:     make && benchmarks/viewer_benchmark.sh [SIZE|national] (B)
#            national: the SBRT ${NAT_SBRT:-nat}@PERMANENT of the GRASS
#            database ${NAT_GISDBASE:-/tmp/nat/grass} (location loc), read
#            from its mapset viewer_benchmark (issue 49)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../tools/grass_env.sh"
size=${1:-B}
if [ "$size" = national ]; then
    nat_db=${NAT_GISDBASE:-/tmp/nat/grass} nat=${NAT_SBRT:-nat}
    [ -e "$nat_db/loc/PERMANENT/sbrt/$nat" ] ||
        { echo "viewer_benchmark.sh: no SBRT $nat in $nat_db/loc/PERMANENT (NAT_GISDBASE, NAT_SBRT)" >&2; exit 1; }
    sbrt_location "$nat_db"
    in_grass viewer_benchmark python3 "$here/viewer_benchmark.py" "$nat@PERMANENT" 800 600
    exit
fi
sbrt_location "${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}"
cat >"$SBRT_GISDBASE/viewer_one.sh" <<'EOS'
set -euo pipefail
size=$1 tools=$2 here=$3
. "$tools/bench_model.sh"
bench_model "$size" "$tools" # sets map=
python3 "$here/viewer_benchmark.py" "$map" 800 600
EOS
in_grass PERMANENT bash "$SBRT_GISDBASE/viewer_one.sh" "$size" "$here/../tools" "$here"
