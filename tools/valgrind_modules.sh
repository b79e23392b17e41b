#!/usr/bin/env bash
############################################################################
# MODULE:    tools/valgrind_modules.sh (r3.sbrt addon)
# PURPOSE:   Runs the modules under valgrind's memcheck on the small T
#            model (convert both ways, list and copy the SBRT, render with
#            every operation on the CPU backend, a profile along a line,
#            support, what, surface, volume, and the view server that
#            g.gui.sbrt drives):
#            any invalid read or write, use of uninitialised memory or bad
#            free fails the run.
#            Leaks are not counted: GRASS modules leave their allocations
#            to process exit by design.
#            Prints "valgrind: N passed, N failed" (one per module run).
# USAGE:     tools/valgrind_modules.sh    (after make)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -uo pipefail
. "$(dirname "$0")/grass_env.sh"
sbrt_location "$(mktemp -d /tmp/r3sbrt_valgrind.XXXXXX)"
cat >"$SBRT_GISDBASE/valgrind_job.sh" <<'EOS'
set -uo pipefail
tools=$1
"$tools/make_geomodel.sh" T geo >/dev/null
printf '1|525|1225|a\n2|1475|1975|b\n' | v.in.ascii --q input=- output=wells separator=pipe \
    columns="cat int, x double precision, y double precision, name varchar(8)" x=2 y=3 cat=1
printf 'L 3\n 100 300\n 1000 1500\n 1900 1000\n' | v.in.ascii --q -n input=- output=fence format=standard
r.mapcalc --q expression="tex = col() * 5"
r.colors --q map=tex color=grey
memcheck() { # name module options...
    local name=$1; shift
    local log_file
    log_file="$(g.gisenv get=GISDBASE)/vg_$name.log"
    valgrind --tool=memcheck --error-exitcode=99 --leak-check=no --track-origins=yes \
        --log-file="$log_file" "$(command -v "$1")" "${@:2}" >"$log_file.out" 2>&1
    local rc=$?
    if [ "$rc" -eq 0 ]; then
        echo "valgrind $name: clean"
        return 0
    fi
    if [ "$rc" -eq 99 ]; then
        echo "valgrind $name: FAILED (memory errors)"
        grep -A12 -E "Invalid|uninitialised|Mismatched|free\(\)" "$log_file" | head -30
    else
        echo "valgrind $name: FAILED (the module exited with $rc)"
        tail -5 "$log_file.out"
    fi
    return 1
}
passed=0 failed=0
count() { if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); fi; }
count memcheck convert r3.sbrt.convert input=geo output=geo
count memcheck convert_back r3.sbrt.convert -r input=geo output=geo_back
count memcheck manage_list r3.sbrt.manage -l -m
count memcheck manage_copy r3.sbrt.manage copy=geo,geo_copy
count memcheck render r3.sbrt.render input=geo output=img size=64,48 material=m depth=d \
    hit_elevation=z backend=cpu normals=kernel kernel=5 smooth=1 png="$(g.gisenv get=GISDBASE)/vg.png"
count memcheck render_strata r3.sbrt.render input=geo output=img_strata size=64,48 backend=cpu \
    hide=13 opacity=12:0.5 plane=0,0,300,0,0,1 section=0,1200,2000,1500 texture=tex
count memcheck render_boreholes r3.sbrt.render input=geo output=img_wells size=64,48 backend=cpu \
    boreholes=wells borehole_radius=30 -b -m log_top=cat log_bottom=cat log_class=cat
count memcheck render_fence r3.sbrt.render input=geo output=img_fence size=64,48 backend=cpu fence=fence
count memcheck profile r3.sbrt.profile input=geo line=fence output=prof width=200 \
    png="$(g.gisenv get=GISDBASE)/vg_profile.png"
count memcheck support r3.sbrt.support sbrt=geo_copy color=viridis
count memcheck what r3.sbrt.what input=geo coordinates=525,1225,1475,1975 format=json
count memcheck surface r3.sbrt.surface input=geo classes=3 top=s_top thickness=s_thick
count memcheck volume r3.sbrt.volume input=geo format=csv
# g.gui.sbrt's native part: the view server it talks to, a frame and a pick
requests="$(g.gisenv get=GISDBASE)/vg_requests.txt"
printf 'render input=geo size=64,48 backend=cpu azimuth=30\npick 10 10 input=geo size=64,48 backend=cpu\nquit\n' >"$requests"
count memcheck view_server r3.sbrt.render --serve <"$requests"
echo "valgrind: $passed passed, $failed failed"
EOS
in_grass PERMANENT bash "$SBRT_GISDBASE/valgrind_job.sh" "$SBRT_ROOT/tools" 2>&1 |
    grep -vE "^(Starting|Cleaning|Executing|Execution) "
