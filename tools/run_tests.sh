#!/usr/bin/env bash
############################################################################
# MODULE:    tools/run_tests.sh (r3.sbrt addon)
# PURPOSE:   Runs every test: the C++ unit tests of lib/sbrt (also under
#            ASan+UBSan), the fuzz targets of the SBRT reader (FUZZ_SECONDS,
#            default 60), of the view server's request lines
#            (REQUEST_SECONDS, default 30) and of its rules files and
#            legends (SERVER_SECONDS, default 30), the stage order of lib/sbrt,
#            both modules under valgrind on a small model, and each
#            gunittest file of testsuite/ in its own fresh mapset; ends with the line "N passed, N failed" (test
#            cases, all kinds together)
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

# 1. unit tests (GoogleTest)
if make -s "$jobs" -C testsuite/unit build/sbrt_unit_tests >"$log/unit_build.log" 2>&1; then
    testsuite/unit/build/sbrt_unit_tests >"$log/unit.log" 2>&1
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log/unit.log")
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log/unit.log")
    passed=$((passed + ${p:-0})); failed=$((failed + ${f:-0}))
    grep -E "^\[  FAILED  \] [A-Z]|Failure" "$log/unit.log" | head -20
    lap
    echo "unit tests: ${p:-0} passed, ${f:-0} failed$took"
    if [ -z "$p" ] && [ -z "$f" ]; then failed=$((failed + 1)); tail -20 "$log/unit.log"; fi
else
    cat "$log/unit_build.log"; failed=$((failed + 1))
fi

# 2. the unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer
san_flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
if make -s "$jobs" -C testsuite/unit BUILD=build-san SAN_FLAGS="$san_flags" build-san/sbrt_unit_tests \
    >"$log/unit_san_build.log" 2>&1; then
    LSAN_OPTIONS=suppressions=$SBRT_ROOT/testsuite/unit/lsan.supp \
        testsuite/unit/build-san/sbrt_unit_tests >"$log/unit_san.log" 2>&1
    rc=$?
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log/unit_san.log")
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log/unit_san.log")
    p=${p:-0}; f=${f:-0}
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        f=1 # a sanitizer report ends the run
        grep -E "ERROR: |runtime error|SUMMARY" "$log/unit_san.log" | head -20
    fi
    passed=$((passed + p)); failed=$((failed + f))
    lap
    echo "unit tests under ASan+UBSan: $p passed, $f failed$took"
else
    cat "$log/unit_san_build.log"; failed=$((failed + 1))
fi

# 3. the SBRT reader fuzzed for FUZZ_SECONDS (libFuzzer, ASan+UBSan): one test
if make -s -C testsuite/fuzz run FUZZ_SECONDS="${FUZZ_SECONDS:-60}" >"$log/fuzz.log" 2>&1; then
    passed=$((passed + 1))
    lap
    echo "fuzz (SBRT reader): passed, $(sed -n 's/^stat::number_of_executed_units: *//p' "$log/fuzz.log") inputs in ${FUZZ_SECONDS:-60} s$took"
else
    failed=$((failed + 1))
    grep -E "ERROR|==[0-9]+==|crash-|leak-|timeout-" "$log/fuzz.log" | head -20
    echo "fuzz (SBRT reader): failed (log $log/fuzz.log)"
fi

# 3a. the view server's request lines fuzzed for REQUEST_SECONDS (default
# 30): one test
if make -s -C testsuite/fuzz run-requests REQUEST_SECONDS="${REQUEST_SECONDS:-30}" \
    >"$log/fuzz_requests.log" 2>&1; then
    passed=$((passed + 1))
    lap
    echo "fuzz (view server requests): passed, $(sed -n 's/^stat::number_of_executed_units: *//p' "$log/fuzz_requests.log") lines in ${REQUEST_SECONDS:-30} s$took"
else
    failed=$((failed + 1))
    grep -E "ERROR|==[0-9]+==|crash-|leak-|timeout-|exited" "$log/fuzz_requests.log" | head -20
    echo "fuzz (view server requests): failed (log $log/fuzz_requests.log)"
fi

# 3a'. what the view server reads besides its request lines (colour rules
# files, hostile legends) fuzzed for SERVER_SECONDS (default 30): one test
if make -s -C testsuite/fuzz run-server-inputs SERVER_SECONDS="${SERVER_SECONDS:-30}" \
    >"$log/fuzz_server_inputs.log" 2>&1; then
    passed=$((passed + 1))
    lap
    echo "fuzz (view server rules files and legends): passed, $(sed -n 's/^stat::number_of_executed_units: *//p' "$log/fuzz_server_inputs.log") inputs in ${SERVER_SECONDS:-30} s$took"
else
    failed=$((failed + 1))
    grep -E "ERROR|==[0-9]+==|crash-|leak-|timeout-|exited" "$log/fuzz_server_inputs.log" | head -20
    echo "fuzz (view server rules files and legends): failed (log $log/fuzz_server_inputs.log)"
fi

# 3b. lib/sbrt's stages include only themselves and the stages below: one test
if tools/check_stage_order.sh >"$log/stage_order.log" 2>&1; then
    passed=$((passed + 1)); echo "stage order of lib/sbrt: passed"
else
    failed=$((failed + 1)); cat "$log/stage_order.log"; echo "stage order of lib/sbrt: failed"
fi

# 4. both modules under valgrind's memcheck on a small model: one test a run
tools/valgrind_modules.sh >"$log/valgrind.log" 2>&1
p=$(sed -n 's/^valgrind: \([0-9]*\) passed.*/\1/p' "$log/valgrind.log")
f=$(sed -n 's/^valgrind: [0-9]* passed, \([0-9]*\) failed/\1/p' "$log/valgrind.log")
[ -z "$p" ] && { p=0; f=1; tail -20 "$log/valgrind.log"; }
[ "${f:-0}" -gt 0 ] && grep -v "clean$" "$log/valgrind.log" | head -30
passed=$((passed + p)); failed=$((failed + ${f:-0}))
lap
echo "modules under valgrind: $p passed, ${f:-0} failed$took"

# 5. gunittest files, each in a fresh mapset of a throw-away location
sbrt_location "$log/grassdata"
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

# 6. the notebook docs/r3_sbrt.ipynb executed by nbconvert: one test, passed
# when it runs through and each cell that shows an image (its last line is
# Image(...) or ....show()) has a PNG among its outputs
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

echo "logs in $log"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
