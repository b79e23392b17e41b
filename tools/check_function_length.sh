#!/usr/bin/env bash
############################################################################
# MODULE:    tools/check_function_length.sh (r3.sbrt addon)
# PURPOSE:   Checks that no function of r3.sbrt.render, lib/sbrt,
#            lib/sbrt_gl or shaders/ is longer than LIMIT lines (default
#            100; the house's rule, issue 50), lambdas included. Uses
#            universal-ctags' end lines (GLSL read as C). Prints each
#            function over the limit, longest first; exit 1 if any
# USAGE:     tools/check_function_length.sh [LIMIT]
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -uo pipefail
cd "$(dirname "$0")/.."
limit=${1:-100}
# Debian's universal-ctags (/usr/bin/ctags may be another ctags)
ctags=$(command -v ctags-universal || command -v universal-ctags) ||
    { echo "check_function_length: universal-ctags is not installed"; exit 2; }
# name <tab> file <tab> ... line:N ... end:M, one a function
lengths() {
    "$ctags" -R --fields=+ne -o - "$@" 2>/dev/null |
        awk -F'\t' '{ line = ""; end = ""
                      for (i = 4; i <= NF; i++) {
                          if ($i ~ /^line:/) line = substr($i, 6)
                          if ($i ~ /^end:/) end = substr($i, 5) }
                      if (line != "" && end != "") print end - line + 1 "\t" $2 ":" line "\t" $1 }'
}
# the sources, not build outputs (build/, OBJ.*/, generated shader_sources.cpp)
files=$(git ls-files 'r3.sbrt.render/*.cpp' 'r3.sbrt.render/*.hpp' 'lib/sbrt/*.cpp' \
            'lib/sbrt/*.hpp' 'lib/sbrt_gl/*.cpp' 'lib/sbrt_gl/*.hpp')
shaders=$(git ls-files 'shaders/*.comp' 'shaders/*.glsl')
[ -n "$files" ] && [ -n "$shaders" ] || { echo "check_function_length: no sources found"; exit 2; }
found=$({
    # shellcheck disable=SC2086
    lengths --languages=C++ --kinds-c++=f $files
    # shellcheck disable=SC2086
    lengths --langmap=C:+.glsl.comp --languages=C --kinds-c=f $shaders
} | sort -t$'\t' -k1,1 -rn)
[ -n "$found" ] || { echo "check_function_length: ctags found no functions"; exit 2; }
over=$(awk -F'\t' -v limit="$limit" '$1 > limit' <<<"$found")
if [ -n "$over" ]; then
    echo "functions over $limit lines (lines, where, name):"
    echo "$over"
    exit 1
fi
echo "no function over $limit lines ($(wc -l <<<"$found") functions; longest: $(head -1 <<<"$found" | tr '\t' ' ')"
