#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/write_performance.sh (r3.sbrt addon)
# PURPOSE:   Writes docs/performance.md from the benchmarks: runs a
#            benchmark script of benchmarks/ with its arguments and
#            replaces its section of docs/performance.md (the lines
#            between "<!-- begin: NAME ARGS -->" and "<!-- end: NAME ARGS
#            -->") by the command, the date, the commit, the machine and
#            what the script printed; a section not there yet is added at
#            the end. Without arguments it runs every benchmark of the
#            list below in turn (hours: models C and national are made
#            once, ~10 min and more each).
# USAGE:     make && benchmarks/write_performance.sh [NAME [ARGS...]]
#            e.g. benchmarks/write_performance.sh convert_benchmark.sh T
#            PERFORMANCE_MD (docs/performance.md): the file written
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
doc=${PERFORMANCE_MD:-$root/docs/performance.md}

# the benchmarks run without arguments, with the arguments the manuals' and
# README's figures came from
ALL=(
    "convert_benchmark.sh A B"
    "what_benchmark.sh C national"
    "surface_benchmark.sh C national"
    "national_benchmark.sh 2647 2812 313"
    "national_views.sh national B"
    "channels_benchmark.sh 2647 2812 313"
    "animation_benchmark.sh B"
    "pipeline_benchmark.sh A B"
    "speed_benchmark.sh A B C"
    "peers_benchmark.sh A B"
    "error_benchmark.sh A"
    "viewer_benchmark.sh B"
    "cluster_benchmark.sh"
)

# The machine in one line: CPU, cores, memory, GPU where nvidia-smi names
# one, the GRASS the addon was built against.
machine() {
    local cpu cores mem gpu grass_version
    cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
    cores=$(nproc)
    mem=$(awk '/^MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo)
    gpu=$(nvidia-smi -L 2>/dev/null | head -1 | sed 's/ (UUID.*//') || true
    grass_version=$(grass --config version 2>/dev/null || echo unknown)
    echo "${cpu:-unknown CPU}, $cores cores, $mem memory${gpu:+, $gpu}, GRASS $grass_version, $(uname -sr)"
}

# Runs one benchmark and writes its section.
write_section() {
    local name=$1; shift
    local script=$here/$name
    [ -x "$script" ] || [ -f "$script" ] || { echo "write_performance: no benchmark $script" >&2; return 1; }
    local key="$name${*:+ $*}" out
    out=$(mktemp)
    echo "write_performance: running $key" >&2
    case $name in
        *.py) (cd "$root" && python3 "$script" "$@") >"$out" ;;
        *) (cd "$root" && bash "$script" "$@") >"$out" ;;
    esac
    local section
    section=$(mktemp)
    {
        echo "<!-- begin: $key -->"
        echo "\`benchmarks/$key\`, run $(date -u +%Y-%m-%d) at commit" \
            "$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown) on: $(machine)."
        echo
        echo '```'
        cat "$out"
        echo '```'
        echo "<!-- end: $key -->"
    } >"$section"
    python3 - "$doc" "$key" "$section" <<'EOF'
import sys

doc, key, section_file = sys.argv[1:]
section = open(section_file, encoding="utf-8").read()
begin, end = f"<!-- begin: {key} -->", f"<!-- end: {key} -->"
text = open(doc, encoding="utf-8").read()
if begin in text and end in text[text.index(begin):]:
    a = text.index(begin)
    b = text.index(end, a) + len(end) + 1  # and its line break
    text = text[:a] + section + text[b:]
else:
    text = text.rstrip("\n") + f"\n\n## {key.split()[0]}\n\n" + section
open(doc, "w", encoding="utf-8").write(text)
EOF
    rm -f "$out" "$section"
    echo "write_performance: $doc, section $key written" >&2
}

if [ $# -gt 0 ]; then
    write_section "$@"
else
    for entry in "${ALL[@]}"; do
        # shellcheck disable=SC2086 # the entry's words are its arguments
        write_section $entry
    done
fi
