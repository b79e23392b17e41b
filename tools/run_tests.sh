#!/usr/bin/env bash
############################################################################
# MODULE:    tools/run_tests.sh (r3.sbrt addon)
# PURPOSE:   Runs the named test steps (after make) and ends with the line
#            "N passed, N failed" (test cases, all steps together):
#              unit       the C++ unit tests of lib/sbrt and lib/sbrt_gl
#              fuzz       the fuzz targets (libFuzzer, ASan+UBSan): the SBRT
#                         reader (FUZZ_SECONDS), the view server's request
#                         lines (REQUEST_SECONDS) and its rules files and
#                         legends (SERVER_SECONDS); 10, 5 and 5 s in `test`,
#                         60, 30 and 30 s in `check` and alone
#              stages     the stage order of lib/sbrt, and no function
#                         over 100 lines (tools/check_function_length.sh)
#              gunittest  each gunittest file of testsuite/ in a fresh mapset
#              notebook   docs/r3_sbrt.ipynb executed
#              unit-san   the unit tests again under ASan+UBSan
#              valgrind   all nine modules under valgrind's memcheck
#              grass84    the gunittest files on GRASS 8.4 in a Debian 13
#                         root (tools/grass84_root.sh)
#            `make test` runs the first five with short fuzzing
#            (tools/run_tests.sh test), `make check` the deep ones
#            (tools/run_tests.sh check): see the Makefile.
# USAGE:     tools/run_tests.sh [test|check|STEP...]   (default: test)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -uo pipefail
. "$(dirname "$0")/grass_env.sh"
cd "$SBRT_ROOT"
passed=0
failed=0
# the seconds a step took, for its line: lap sets $took (since the last lap)
step_start=$SECONDS
lap() { took=" ($((SECONDS - step_start)) s)"; step_start=$SECONDS; }
log=$(mktemp -d /tmp/r3sbrt_tests.XXXXXX)
# the unit tests' builds on every core (their libraries' sub-makes share
# make's job slots)
jobs=-j$(nproc)

# adds a GoogleTest log's counts: gtest_counts LOG (sets $p and $f)
gtest_counts() {
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$1")
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$1")
    p=${p:-0}; f=${f:-0}
}

# unit tests (GoogleTest)
step_unit() {
    if ! make -s "$jobs" -C testsuite/unit build/sbrt_unit_tests >"$log/unit_build.log" 2>&1; then
        cat "$log/unit_build.log"; failed=$((failed + 1)); return
    fi
    testsuite/unit/build/sbrt_unit_tests >"$log/unit.log" 2>&1
    local rc=$?
    gtest_counts "$log/unit.log"
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; tail -20 "$log/unit.log"; fi
    passed=$((passed + p)); failed=$((failed + f))
    grep -E "^\[  FAILED  \] [A-Z]|Failure" "$log/unit.log" | head -20
    lap
    echo "unit tests: $p passed, $f failed$took"
}

# the unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer
step_unit_san() {
    local san_flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
    if ! make -s "$jobs" -C testsuite/unit BUILD=build-san SAN_FLAGS="$san_flags" build-san/sbrt_unit_tests \
        >"$log/unit_san_build.log" 2>&1; then
        cat "$log/unit_san_build.log"; failed=$((failed + 1)); return
    fi
    LSAN_OPTIONS=suppressions=$SBRT_ROOT/testsuite/unit/lsan.supp \
        testsuite/unit/build-san/sbrt_unit_tests >"$log/unit_san.log" 2>&1
    local rc=$?
    gtest_counts "$log/unit_san.log"
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        f=1 # a sanitizer report ends the run
        grep -E "ERROR: |runtime error|SUMMARY" "$log/unit_san.log" | head -20
    fi
    passed=$((passed + p)); failed=$((failed + f))
    lap
    echo "unit tests under ASan+UBSan: $p passed, $f failed$took"
}

# one fuzz target for its seconds: one test.
# fuzz_target MAKE_TARGET SECONDS_VARIABLE SECONDS WHAT UNITS
fuzz_target() {
    local target=$1 variable=$2 seconds=$3 what=$4 units=$5
    if make -s -C testsuite/fuzz "$target" "$variable=$seconds" >"$log/$target.log" 2>&1; then
        passed=$((passed + 1))
        lap
        echo "fuzz ($what): passed, $(sed -n 's/^stat::number_of_executed_units: *//p' "$log/$target.log") $units in $seconds s$took"
    else
        failed=$((failed + 1))
        grep -E "ERROR|==[0-9]+==|crash-|leak-|timeout-|exited" "$log/$target.log" | head -20
        echo "fuzz ($what): failed (log $log/$target.log)"
    fi
}

# step_fuzz READER_SECONDS REQUEST_SECONDS SERVER_SECONDS: the defaults,
# which FUZZ_SECONDS, REQUEST_SECONDS and SERVER_SECONDS override
step_fuzz() {
    fuzz_target run FUZZ_SECONDS "${FUZZ_SECONDS:-$1}" "SBRT reader" inputs
    fuzz_target run-requests REQUEST_SECONDS "${REQUEST_SECONDS:-$2}" "view server requests" lines
    fuzz_target run-server-inputs SERVER_SECONDS "${SERVER_SECONDS:-$3}" \
        "view server rules files and legends" inputs
}

# house rules: lib/sbrt's stages include only themselves and the stages
# below; no function over 100 lines. Two tests
step_stages() {
    if tools/check_stage_order.sh >"$log/stage_order.log" 2>&1; then
        passed=$((passed + 1)); echo "stage order of lib/sbrt: passed"
    else
        failed=$((failed + 1)); cat "$log/stage_order.log"; echo "stage order of lib/sbrt: failed"
    fi
    if tools/check_function_length.sh >"$log/function_length.log" 2>&1; then
        passed=$((passed + 1)); echo "function lengths: passed ($(tail -1 "$log/function_length.log"))"
    else
        failed=$((failed + 1)); cat "$log/function_length.log"; echo "function lengths: failed"
    fi
    lap
}

# the modules under valgrind's memcheck on a small model: one test a run
step_valgrind() {
    tools/valgrind_modules.sh >"$log/valgrind.log" 2>&1
    local p f
    p=$(sed -n 's/^valgrind: \([0-9]*\) passed.*/\1/p' "$log/valgrind.log")
    f=$(sed -n 's/^valgrind: [0-9]* passed, \([0-9]*\) failed/\1/p' "$log/valgrind.log")
    [ -z "$p" ] && { p=0; f=1; tail -20 "$log/valgrind.log"; }
    [ "${f:-0}" -gt 0 ] && grep -v "clean$" "$log/valgrind.log" | head -30
    passed=$((passed + p)); failed=$((failed + ${f:-0}))
    lap
    echo "modules under valgrind: $p passed, ${f:-0} failed$took"
}

# gunittest files, each in a fresh mapset of a throw-away location
step_gunittest() {
    sbrt_location "$log/grassdata"
    local test name rc ran bad skipped good
    for test in testsuite/test_*.py; do
        name=$(basename "$test" .py)
        in_grass "$name" python3 "$test" >"$log/$name.log" 2>&1
        rc=$?
        ran=$(sed -n 's/^Ran \([0-9]*\) test.*/\1/p' "$log/$name.log" | tail -1)
        bad=$(grep -E "^FAILED \(" "$log/$name.log" | tail -1 |
            grep -oE "(failures|errors)=[0-9]+" | cut -d= -f2 | awk "{ s += \$1 } END { print s + 0 }")
        ran=${ran:-0}; bad=${bad:-0}
        if [ "$ran" -eq 0 ] || { [ "$rc" -ne 0 ] && [ "$bad" -eq 0 ]; }; then
            bad=$((bad + 1)) # the file itself broke
        fi
        [ "$bad" -gt 0 ] && { grep -E "^(FAIL|ERROR):|Error|ERROR" "$log/$name.log" | head -20; }
        grep -h "^SKIPPED: " "$log/$name.log" | sed "s/^/$name: /" # why a file's tests were skipped
        skipped=$(grep -oE "skipped=[0-9]+" "$log/$name.log" | tail -1 | cut -d= -f2)
        good=$((ran - bad - ${skipped:-0})); [ "$good" -lt 0 ] && good=0
        passed=$((passed + good)); failed=$((failed + bad))
        lap
        echo "$name: $good passed, $bad failed${skipped:+, $skipped skipped}$took"
    done
}

# docs/r3_sbrt.ipynb executed by nbconvert: one test, passed when it runs
# through and each cell that shows an image (its last line is Image(...) or
# ....show()) has a PNG among its outputs
step_notebook() {
    if jupyter nbconvert --to notebook --execute docs/r3_sbrt.ipynb --output-dir "$log" \
        >"$log/notebook.log" 2>&1 &&
        python3 - "$log/r3_sbrt.ipynb" >>"$log/notebook.log" 2>&1 <<'PY'
import base64, sys
import nbformat
cells = [c for c in nbformat.read(sys.argv[1], 4).cells if c.cell_type == "code"]
shows = [c for c in cells if c.source.strip() and (
    c.source.strip().splitlines()[-1].startswith("Image(")
    or c.source.strip().endswith(".show()"))]
pngs = [[base64.b64decode(o["data"]["image/png"]) for o in c.outputs
         if "image/png" in o.get("data", {})] for c in shows]
good = sum(1 for p in pngs if p and all(b.startswith(b"\x89PNG") for b in p))
print(f"notebook: {good} of {len(shows)} cells that show an image have one")
sys.exit(not (len(shows) >= 5 and good == len(shows)))
PY
    then
        passed=$((passed + 1))
        lap
        echo "notebook (docs/r3_sbrt.ipynb): passed$took"
    else
        failed=$((failed + 1))
        grep -E "Error|error|notebook:" "$log/notebook.log" | head -20
        echo "notebook (docs/r3_sbrt.ipynb): failed (log $log/notebook.log)"
    fi
}

# the gunittest files on GRASS 8.4 (Debian 13 root): its own counts
step_grass84() {
    tools/grass84_root.sh prepare >"$log/grass84_prepare.log" 2>&1 &&
        tools/grass84_root.sh test >"$log/grass84.log" 2>&1
    local rc=$? counts p f
    counts=$(grep -E "^[0-9]+ passed, [0-9]+ failed$" "$log/grass84.log" | tail -1)
    p=${counts%% passed*}; f=${counts#*passed, }; f=${f%% failed*}
    p=${p:-0}; f=${f:-0}
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        f=1; tail -20 "$log/grass84_prepare.log" "$log/grass84.log"
    fi
    grep -E ": [0-9]+ passed, [1-9][0-9]* failed" "$log/grass84.log"
    passed=$((passed + p)); failed=$((failed + f))
    lap
    echo "GRASS 8.4 (Debian 13 root): $p passed, $f failed$took"
}

steps=("$@")
[ ${#steps[@]} -eq 0 ] && steps=(test)
known=" test check unit unit-san fuzz stages valgrind gunittest notebook grass84 "
for step in "${steps[@]}"; do
    if [ "${known/ $step /}" = "$known" ]; then
        echo "run_tests.sh: no step '$step' (one of:$known)" >&2
        exit 2
    fi
done
for step in "${steps[@]}"; do
    case $step in
        test) step_unit; step_fuzz 10 5 5; step_stages; step_gunittest; step_notebook ;;
        check) step_unit_san; step_fuzz 60 30 30; step_valgrind; step_grass84 ;;
        unit) step_unit ;;
        unit-san) step_unit_san ;;
        fuzz) step_fuzz 60 30 30 ;;
        stages) step_stages ;;
        valgrind) step_valgrind ;;
        gunittest) step_gunittest ;;
        notebook) step_notebook ;;
        grass84) step_grass84 ;;
    esac
done

echo "logs in $log"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
