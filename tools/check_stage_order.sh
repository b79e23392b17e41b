#!/usr/bin/env bash
############################################################################
# MODULE:    tools/check_stage_order.sh (r3.sbrt addon)
# PURPOSE:   Checks that every include of lib/sbrt points from a stage to
#            itself or a stage below it (the order of the README's Layout);
#            files at the top of lib/sbrt (the renderer, its memory model)
#            are the top stage. Prints each include that points upwards, or
#            a folder missing from the order; exit 1 if any
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -uo pipefail
cd "$(dirname "$0")/../lib/sbrt"
# lowest first; keep in step with README.md (Layout)
order=(util model format builders measure output frame scene tracing shading gpu)
rank() {
    local i
    for i in "${!order[@]}"; do
        [ "${order[$i]}" = "$1" ] && { echo "$i"; return; }
    done
    echo -1
}
bad=0
for dir in */; do
    stage=${dir%/}
    case $stage in OBJ.* | build*) continue ;; esac
    [ "$(rank "$stage")" -ge 0 ] || { echo "lib/sbrt/$stage/: not in the stage order"; bad=1; }
done
for file in $(ls -d */*.hpp */*.cpp | grep -v "^OBJ\\.\\|^build"); do
    stage=${file%%/*}
    own=$(rank "$stage")
    while IFS= read -r included; do
        target=${included%%/*}
        if [ "$target" = "$included" ]; then # a file at the top: the top stage
            echo "lib/sbrt/$file includes \"$included\": the top stage is above $stage"
            bad=1
            continue
        fi
        theirs=$(rank "$target")
        if [ "$theirs" -lt 0 ] || [ "$theirs" -gt "$own" ]; then
            echo "lib/sbrt/$file includes \"$included\": stage $target is above $stage"
            bad=1
        fi
    done < <(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$file")
done
[ "$bad" -eq 0 ] && echo "stage order: every include of lib/sbrt points to its stage or below"
exit "$bad"
