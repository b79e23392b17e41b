#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/trace_bench/same_outputs.sh (r3.sbrt addon)
# PURPOSE:   Whether two trace_bench builds print the same lines but for
#            their timings: every mode once, small and with fixed
#            arguments, plus the usage and error cases; each output's
#            timing fields (ms, rates, time ratios, busy shares, gpu_frame's
#            checksum, which sums the frames of a 0.3 s warm-up) become T,
#            everything else (words, field names, labels, pixel counts,
#            bytes, errors, checksums, error's class ids file) must match.
#            For a change of trace_bench itself: the scripts parse its
#            lines (device_run.sh, *_benchmark.sh). Link both builds
#            against the same libraries. Exit 0: the same; 1: the diff.
# USAGE:     same_outputs.sh OLD_BIN NEW_BIN MODEL_DIR PROPERTY_MODEL_DIR
#            (MODEL_DIR: an SBRT of tools/bench_model.sh, e.g. geo_A, is
#            copied (format writes beside it); PROPERTY_MODEL_DIR one with
#            channels kans_5..7 and onz_lk, paint_gt of device_bundle.sh)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -uo pipefail
[ $# -eq 4 ] || { sed -n '/^# USAGE/,/^# COPYRIGHT/p' "$0" | head -4; exit 2; }
old=$1 new=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$3" "$work/model"
m=$work/model p=$4
v="azimuth=225 elevation=30 cols=160 rows=120 repeat=1 threads=1"
at="position=-1000,-1000,2000 target=1000,1250,300 fov=30 cols=160 rows=120 repeat=1"
pv="azimuth=200 elevation=35 zexag=20 cols=160 rows=120"

# every case of BIN into folder OUT, one NAME.out (stdout, stderr, rc) each
cases() {
    local bin=$1 out=$2
    mkdir -p "$out"
    run() {
        local name=$1
        shift
        timeout 300 "$bin" "$@" >"$out/$name.out" 2>"$out/$name.err"
        echo "rc=$?" >>"$out/$name.out"
        sed "s#^usage: [^ ]*#usage: BIN#" "$out/$name.err" >>"$out/$name.out"
    }
    run usage
    run usage_one frame
    run not_key_value frame "$m" foo
    run unknown_mode nomode "$m" $v
    run no_such_class skipping "$m" $v hide=999
    run format format "$m" repeat=1 label=A
    run skipping skipping "$m" $at label=A zexag=2
    run skipping_hide skipping "$m" $v hide=1,2 gpu=none label=A
    run frame frame "$m" $v label=A
    run frame_alone frame "$m" $v label=A reference=0 hide=3
    run gpu_frame gpu_frame "$m" $v label=A
    run gpu_frame_boreholes gpu_frame "$m" $v label=A boreholes=9 cpu=0
    run gpu_frame_no_gl gpu_frame "$m" $v label=A gpu=none
    run paint_frame paint_frame "$p" $pv repeat=1 threads=1 property=kans_5+kans_6+kans_7 \
        fade=onz_lk label=paint_gt
    run paint_frame_no_gl paint_frame "$p" $pv gpu=none label=paint_gt
    run error error "$m" $v label=A classes="$out/classes.bin"
    run compact compact "$m" $at label=A
    run row_order row_order "$m" $v as_threads=4 label=A
}

# the outputs of folder OUT, their timings T
untimed() {
    local f
    for f in "$1"/*.out; do
        echo "== $(basename "$f")"
        python3 -c '
import re, sys
timing = re.compile(r"(_ms|^ms|Mrays/s|mrays|frames_per_s|busy_mean_pct|busy_min_pct|"
                    r"sink_pct|busy_pct_each|/on|/cpu|/memcpy|/compact|/face_dispatch|"
                    r"first_frame|warm_frame)$")
for line in sys.stdin:
    words = []
    for w in re.findall(r"\S+=\"[^\"]*\"|\S+", line):
        key, eq, value = w.partition("=")
        if eq and timing.search(key):
            value = "T"
        elif re.fullmatch(r"\([0-9.]+x\)", w):
            w = "(Tx)"
        words.append(key + eq + value if eq else w)
    text = " ".join(words)
    if line.startswith("gpu_frame "):
        text = re.sub(r"\(checksum \d+\)", "(checksum T)", text)
    print(text)
' <"$f"
    done
    md5sum <"$1/classes.bin"
}

cases "$old" "$work/old"
cases "$new" "$work/new"
untimed "$work/old" >"$work/old.txt"
untimed "$work/new" >"$work/new.txt"
if diff "$work/old.txt" "$work/new.txt"; then
    echo "same: $(grep -c . "$work/new.txt") lines of $(ls "$work/new"/*.out | wc -l) cases"
    exit 0
fi
exit 1
