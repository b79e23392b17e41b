#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/national_views.sh (r3.sbrt addon)
# PURPOSE:   Every figure of issue 49's table in one run, per model: the
#            1056 x 884 default view (on the CPU, and on the GPU within the
#            default gpu_memory=) and the top view of every cell end to
#            end (r3.sbrt.render, a new process), r3.sbrt.convert -p and
#            -g, r3.sbrt.what (1000 points), r3.sbrt.profile (across the
#            model) and r3.sbrt.surface (a 400 x 400-cell region), each
#            cold (page cache dropped where permitted, a new process) and
#            warm (run again), with peak RSS; the view server
#            (r3.sbrt.render --serve: first frame, 400 x 300 orbit frames,
#            a stratum hidden + frame; cold and warm, server_frames.py);
#            g.gui.sbrt 800 x 600 under Xvfb (viewer_benchmark.py: full and
#            reduced frames, a stratum hidden as the viewer asks it (the
#            reduced frame, then the exact one), frames shown a second
#            while dragging, the exact frame after the mouse rests).
#            Prints a header (machine,
#            load, commit, caches) and one line per figure: what | model |
#            model ... (seconds or ms, peak RSS in MB); a figure that could
#            not be measured says why in its cell. Progress on stderr, the
#            table alone on stdout (write_performance.sh national_views.sh
#            puts it into docs/performance.md). Figures only: never
#            part of pass/fail.
# USAGE:     make && benchmarks/national_views.sh [MODEL...]
#            (or SIZES="MODEL..."; default: national B)
#            MODEL: national  the SBRT ${NAT_SBRT:-nat}@PERMANENT of
#                             ${NAT_GISDBASE:-/tmp/nat/grass} (location loc,
#                             read from its mapset national_views); where
#                             that is missing, the GeoTOP-like model of
#                             ${NATIONAL:-2647x2812x313} voxels made in
#                             SBRT_BENCH_DATA (as geotop:...)
#                   x16       the GeoTOP-like model 16 times national
#                             (geotop:10588x11248x313, 37 billion voxels;
#                             generated and imported once: long, and its
#                             NetCDF file is large)
#                   geotop:NXxNYxNZ  GeoTOP-like (benchmarks/geotop_like),
#                             made and imported once into
#                             SBRT_BENCH_DATA (/tmp/r3sbrt_bench)
#                   T S A B C or CxRxD  a demo model (tools/bench_model.sh)
#            LIMIT: seconds for any one measured command (1800)
#            ROUNDS: rounds of the default view on the CPU, cold and warm
#            (3; its rows give the median and the fastest-slowest, and
#            the national / B ratio of the cold medians follows the table)
#            MEMORY: adds memory=MEMORY to the r3.sbrt.render, convert,
#            what, profile and surface runs and to the viewer's requests (their rows say so where
#            refused); x16 runs with memory=2000 where MEMORY is not given
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
. "$root/tools/grass_env.sh"
if [ $# -gt 0 ]; then models=("$@"); else read -ra models <<<"${SIZES:-national B}"; fi
data=${SBRT_BENCH_DATA:-/tmp/r3sbrt_bench}
nat_db=${NAT_GISDBASE:-/tmp/nat/grass} nat=${NAT_SBRT:-nat}
limit=${LIMIT:-1800} rounds=${ROUNDS:-3}
work=$(mktemp -d /tmp/national_views.XXXXXX)
trap 'rm -rf "$work"' EXIT
load_start=$(cut -d' ' -f1-3 /proc/loadavg)

# One model's figures, inside a GRASS session: KIND (bench, geotop, sbrt),
# SPEC, then the folders. Each figure is a line "key<TAB>value" of
# $dir/figures (value: "seconds kB", or "! why"); the view server's and
# the viewer's figures are JSON files beside it.
cat >"$work/views_one.sh" <<'EOS'
set -uo pipefail # no -e: a figure that fails is written down, not fatal
kind=$1 spec=$2 tools=$3 here=$4 data=$5 dir=$6 limit=$7 memory=$8 rounds=$9
res=$dir/figures
note() { printf '%s\t%s\n' "$1" "$2" >>"$res"; }
case $kind in
    bench) . "$tools/bench_model.sh"; bench_model "$spec" "$tools" >&2 || { note model "! bench_model $spec failed"; exit 0; }; name=$map ;;
    geotop) . "$tools/bench_model.sh"; IFS=x read -r nx ny nz <<<"$spec"
            geotop_bench_model "$nx" "$ny" "$nz" "$data" "$tools" >&2 ||
                { note model "! geotop_bench_model $spec failed"; exit 0; }
            name=$map ;;
    sbrt) name=$spec ;;
esac
mem=()
[ -n "$memory" ] && mem=(memory="$memory")
drop() { # the page cache, where this user may: echo 3 > drop_caches
    sync
    if { echo 3 >/proc/sys/vm/drop_caches; } 2>/dev/null; then note caches dropped
    else note caches "not dropped (/proc/sys/vm/drop_caches not writable)"; fi
}
run() { # KEY CMD...: "seconds kB" of CMD (a new process), or why it failed
    local key=$1; shift
    if /usr/bin/time -f "%e %M" -o "$dir/time" timeout "$limit" "$@" >"$dir/out" 2>"$dir/err"; then
        note "$key" "$(tail -1 "$dir/time")"
    else
        local why
        why=$(grep -v '^ *$' "$dir/err" | tail -1 | tr '|\t' '/ ' | cut -c1-120)
        [ "$(head -1 "$dir/time" 2>/dev/null)" = "Command exited with non-zero status 124" ] &&
            why="over LIMIT=$limit s"
        note "$key" "! ${why:-exit status not 0}"
    fi
}
cold_warm() { # KEY CMD...: cold (caches dropped, a new process), then warm
    local key=$1; shift
    drop
    run "${key}_cold" "$@"
    run "${key}_warm" "$@"
}
cold_warm_rounds() { # KEY ROUNDS CMD...: cold_warm ROUNDS times; each state's
    # median (by seconds; of an even count, the faster middle run) as
    # KEY_STATE, its fastest-slowest as KEY_STATE_spread
    local key=$1 rounds=$2 state r times; shift 2
    for ((r = 1; r <= rounds; ++r)); do cold_warm "${key}_round${r}" "$@"; done
    for state in cold warm; do
        times=$(grep -E "^${key}_round[0-9]+_${state}"$'\t' "$res" | cut -f2 | grep -v '^!' | sort -n) || true
        if [ -z "$times" ]; then
            note "${key}_$state" "$(grep -E "^${key}_round[0-9]+_${state}"$'\t' "$res" | cut -f2 | head -1)"
            continue
        fi
        note "${key}_$state" "$(sed -n "$(( ($(wc -l <<<"$times") + 1) / 2 ))p" <<<"$times")"
        note "${key}_${state}_spread" "$(head -1 <<<"$times" | cut -d' ' -f1)-$(tail -1 <<<"$times" | cut -d' ' -f1) s of $(wc -l <<<"$times")"
    done
}
describe=$(r3.sbrt.convert -g sbrt="$name" 2>"$dir/err") ||
    { note model "! r3.sbrt.convert -g: $(tail -1 "$dir/err")"; exit 0; }
eval "$describe"
note model "$name: $cols x $rows x $depths voxels, $intervals intervals"
note grid "${cols}x${rows}"
echo "national_views: $name: r3.sbrt.render 1056x884, top view, convert -p -g" >&2
# the figure issue 49's ratio target compares: the median of ROUNDS rounds
# (a single run on a shared 2-core machine moves by a fifth)
cold_warm_rounds render "$rounds" r3.sbrt.render --o input="$name" size=1056,884 \
    png="$dir/view.png" "${mem[@]}"
# the same on the GPU (EGL: Mesa's llvmpipe where there is no GPU), its
# blocks (and for the 16x model its columns) brought up within the
# default gpu_memory=1024
cold_warm render_gpu r3.sbrt.render --o input="$name" size=1056,884 png="$dir/view_gpu.png" \
    backend=egl "${mem[@]}"
r3.sbrt.convert -s sbrt="$name" # the top view's maps in the model's grid
cold_warm top r3.sbrt.render --o input="$name" view=top output=views_top png="$dir/top.png" "${mem[@]}"
cold_warm convert_p r3.sbrt.convert -p sbrt="$name" "${mem[@]}"
cold_warm convert_g r3.sbrt.convert -g sbrt="$name" "${mem[@]}"
echo "national_views: $name: r3.sbrt.what, r3.sbrt.profile, r3.sbrt.surface" >&2
# 1000 points spread over the extent (the same each run), a profile west to
# east across the middle, the thickness of one class in a 400 x 400-cell
# region at the centre
points=$(awk -v n="$north" -v s="$south" -v e="$east" -v w="$west" 'BEGIN {
    for (i = 0; i < 1000; i++) {
        fx = i * 0.6180339887; fy = i * 0.4142135624 + 0.5
        printf "%s%.1f,%.1f", i ? "," : "", w + (e - w) * (fx - int(fx)), s + (n - s) * (fy - int(fy))
    } }')
cold_warm what r3.sbrt.what --o input="$name" coordinates="$points" format=csv output="$dir/what.csv" "${mem[@]}"
middle=$(echo "($north + $south) / 2" | bc -l)
cold_warm profile r3.sbrt.profile --o input="$name" coordinates="$west,$middle,$east,$middle" \
    output=views_profile "${mem[@]}"
half_ns=$(echo "200 * $nsres" | bc -l) half_ew=$(echo "200 * $ewres" | bc -l)
centre_e=$(echo "($east + $west) / 2" | bc -l)
g.region n="$(echo "$middle + $half_ns" | bc -l)" s="$(echo "$middle - $half_ns" | bc -l)" \
    e="$(echo "$centre_e + $half_ew" | bc -l)" w="$(echo "$centre_e - $half_ew" | bc -l)" \
    nsres="$nsres" ewres="$ewres"
# the class most often met by the points above
set_class=$(awk -F, 'NR > 1 && $8 != "" { n[$8]++ } END { for (c in n) if (n[c] > most) { most = n[c]; best = c } print best }' "$dir/what.csv")
cold_warm surface r3.sbrt.surface --o input="$name" classes="${set_class:-1}" \
    thickness=views_thickness "${mem[@]}"
r3.sbrt.convert -s sbrt="$name"
echo "national_views: $name: view server" >&2
for state in cold warm; do
    [ $state = cold ] && drop
    SBRT_MEMORY=$memory timeout "$limit" python3 "$here/server_frames.py" "$name" 800 600 400 300 12 \
        >"$dir/server_$state.json" 2>"$dir/err" ||
        [ -s "$dir/server_$state.json" ] ||
        echo "{\"error\": $(tail -1 "$dir/err" | python3 -c 'import json, sys; print(json.dumps(sys.stdin.read().strip() or "exit status not 0"))')}" \
            >"$dir/server_$state.json"
done
echo "national_views: $name: g.gui.sbrt under Xvfb" >&2
if ! command -v Xvfb >/dev/null || ! command -v xdotool >/dev/null; then
    echo '{"error": "no Xvfb or xdotool on this machine"}' >"$dir/viewer.json"
else
    VIEWER_FIGURES=$dir/viewer.json timeout "$limit" python3 "$here/viewer_benchmark.py" "$name" 800 600 "${mem[@]}" \
        >"$dir/viewer.log" 2>&1 || true
    [ -s "$dir/viewer.json" ] ||
        echo "{\"error\": $(tail -1 "$dir/viewer.log" | python3 -c 'import json, sys; print(json.dumps(sys.stdin.read().strip() or "no figures"))')}" \
            >"$dir/viewer.json"
    sed 's/^/national_views:   /' "$dir/viewer.log" >&2
fi
EOS

# the models: their columns, names and where they run
for i in "${!models[@]}"; do
    model=${models[$i]} dir=$work/$i
    mkdir -p "$dir"
    kind=bench spec=$model db=$data mapset=PERMANENT
    case $model in
        national)
            if [ -e "$nat_db/loc/PERMANENT/sbrt/$nat" ]; then
                kind=sbrt spec=$nat@PERMANENT db=$nat_db mapset=national_views
            else
                kind=geotop spec=${NATIONAL:-2647x2812x313}
            fi ;;
        x16) kind=geotop spec=10588x11248x313 ;;
        geotop:*) kind=geotop spec=${model#geotop:} ;;
    esac
    # issue 49's budget for the model 16 times national
    memory=${MEMORY:-}
    [ "$model" = x16 ] && memory=${MEMORY:-2000}
    echo "national_views: $model ($kind $spec in $db, mapset $mapset)" >&2
    printf '%s\n' "$model" "$kind $spec ($db${memory:+; memory=$memory})" >"$dir/name"
    sbrt_location "$db"
    if ! in_grass "$mapset" bash "$work/views_one.sh" "$kind" "$spec" "$root/tools" "$here" "$data" \
        "$dir" "$limit" "$memory" "$rounds" 2>&1 |
        { grep -v "^Starting GRASS\|^Cleaning up\|^Executing\|^Execution of" || true; } >&2; then
        printf 'model\t! the GRASS session failed\n' >>"$dir/figures"
    fi
done

# the table
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
changed=$(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null | wc -l)
built=$(date -r "$root/dist/bin/r3.sbrt.render" '+%Y-%m-%d %H:%M' 2>/dev/null || echo "not built")
python3 - "$work" "${#models[@]}" "$cpu" "$(nproc)" "$load_start" "$(cut -d' ' -f1-3 /proc/loadavg)" \
    "$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)" "$changed" "$built" \
    "${models[*]}" <<'EOF'
import json
import os
import sys

work, count, cpu, cores, load_start, load_end, commit, changed, built, args = sys.argv[1:]
models = []
for i in range(int(count)):
    d = os.path.join(work, str(i))
    name, source = open(os.path.join(d, "name")).read().splitlines()[:2]
    figures, caches = {}, set()
    if os.path.exists(os.path.join(d, "figures")):
        for line in open(os.path.join(d, "figures")):
            key, _, value = line.rstrip("\n").partition("\t")
            if key == "caches":
                caches.add(value)
            else:
                figures.setdefault(key, value)
    figures["caches"] = "; ".join(sorted(caches)) or "not reached"
    for part in ("server_cold", "server_warm", "viewer"):
        path = os.path.join(d, part + ".json")
        try:
            figures[part] = json.load(open(path))
        except (OSError, ValueError):
            figures[part] = {"error": "not run (the model failed: %s)" % figures.get("model", "?")}
    models.append((name, source, figures))


def why(figures, key):
    """The reason a figure is missing."""
    value = figures.get(key)
    if value and value.startswith("!"):
        return "n/a: " + value[1:].strip()
    model = figures.get("model", "")
    return "n/a: " + (model[1:].strip() if model.startswith("!") else "not measured")


def timed(key):
    def cell(figures):
        value = figures.get(key, "")
        try:
            seconds, kb = value.split()
            return "%.2f s, %.0f MB" % (float(seconds), float(kb) / 1024)
        except ValueError:
            return why(figures, key)
    return cell


def spread(cell, key):
    """cell's figure, with the fastest-slowest of its rounds."""
    def with_spread(figures):
        value = figures.get(key)
        return cell(figures) + (" (%s)" % value if value else "")
    return with_spread


def seconds(figures, key):
    try:
        return float(figures.get(key, "").split()[0])
    except (ValueError, IndexError):
        return None


def from_json(part, fmt):
    def cell(figures):
        data = figures[part]
        try:
            return fmt(data)
        except (KeyError, IndexError, ValueError, TypeError, ZeroDivisionError):
            return "n/a: " + str(data.get("error", "not measured")).replace("|", "/")[:120]
    return cell


def span(values, fmt="%.1f", unit=""):
    """The lowest and highest of `values` (one where they round alike)."""
    low, high = fmt % min(values), fmt % max(values)
    return (low if low == high else low + "-" + high) + unit


def mb(kb):
    return "%.0f MB" % (kb / 1024)


rows = [("model", lambda f: f.get("model", "?").lstrip("! "))]
for state in ("cold", "warm"):
    rows.append(("r3.sbrt.render 1056x884 default view (png=), end to end, %s (median; fastest-slowest)"
                 % state, spread(timed("render_" + state), "render_%s_spread" % state)))
for state in ("cold", "warm"):
    rows.append(("r3.sbrt.render 1056x884 default view on the GPU (backend=egl, gpu_memory=1024), %s"
                 % state, timed("render_gpu_" + state)))
for state in ("cold", "warm"):
    rows.append(("r3.sbrt.render view=top of every cell (the model's grid), %s" % state,
                 timed("top_" + state)))
for flag in ("p", "g"):
    for state in ("cold", "warm"):
        rows.append(("r3.sbrt.convert -%s, %s" % (flag, state), timed("convert_%s_%s" % (flag, state))))
for key, label in (("what", "r3.sbrt.what, 1000 points spread over the model"),
                   ("profile", "r3.sbrt.profile, west to east across the middle"),
                   ("surface", "r3.sbrt.surface thickness= of a class, 400 x 400 cells at the centre")):
    for state in ("cold", "warm"):
        rows.append(("%s, %s" % (label, state), timed("%s_%s" % (key, state))))
for state in ("cold", "warm"):
    part = "server_" + state
    rows.append(("view server: first frame 800x600 (process, model read, scene), %s" % state,
                 from_json(part, lambda d: "%.2f s, %s" % (d["first_s"], mb(d["first_rss_kb"])))))
for state in ("cold", "warm"):
    part = "server_" + state
    rows.append(("view server: 400x300 orbit frame, camera moved (median of 12; server's own), %s" % state,
                 from_json(part, lambda d: "%.1f ms (%.1f ms), %s" % (
                     d["orbit_ms"], d["orbit_server_ms"], mb(d["orbit_rss_kb"])))))
for state in ("cold", "warm"):
    part = "server_" + state
    rows.append(("view server: a stratum hidden (hide= changed) + 800x600 frame, %s" % state,
                 from_json(part, lambda d: "%.3f s (hide=%d), %s" % (
                     d["hide_s"], d["hide_id"], mb(d["hide_rss_kb"])))))
rows += [
    ("viewer 800x600: full frame / reduced frame (orbit medians, viewer's client)",
     from_json("viewer", lambda d: "%.1f / %.1f ms, %s" % (
         d["renderer_full_ms"], d["renderer_reduced_ms"], mb(d["renderer_rss_kb"])))),
    ("viewer: a stratum hidden as the viewer asks (reduced frame / exact frame after the request)",
     from_json("viewer", lambda d: "%.1f / %.1f ms" % (
         d["renderer_hide_reduced_ms"], d["renderer_hide_exact_ms"]))),
    ("viewer: g.gui.sbrt started to first frame shown (its view server's peak RSS)",
     from_json("viewer", lambda d: "%.2f s (%s)" % (
         d["viewer_first_s"], mb(d.get("viewer_server_rss_kb", 0))))),
    ("viewer: frames shown a second while dragging (3 drags)",
     from_json("viewer", lambda d: span(d["viewer_fps"]))),
    ("viewer: exact frame after the mouse rests (3 drags; the server's time of it)",
     from_json("viewer", lambda d: span(d["viewer_refined_ms"], "%.0f", " ms") + (
         " (server %s)" % " ".join([span(d["viewer_refined_server_ms"], "%.0f", " ms")]
                                   + d.get("viewer_refined_options", [])))
         + (
         "" if len(d["viewer_refined_ms"]) == len(d["viewer_fps"]) else
         " (%d of %d drags refined within 30 s)" % (len(d["viewer_refined_ms"]), len(d["viewer_fps"]))))),
]

caches = sorted({f["caches"] for _, _, f in models})
print("national_views.sh %s: %s, nproc %s, load average %s at start, %s at the end" % (
    args, cpu or "unknown CPU", cores, load_start, load_end))
print("commit %s%s, ./dist/bin/r3.sbrt.render built %s; page cache before each cold run: %s" % (
    commit, " (%s tracked files changed in the tree)" % changed if changed != "0" else "",
    built, "; ".join(caches)))
print("models: " + "; ".join("%s = %s" % (n, s) for n, s, _ in models))
print("(cold: a new process after the page cache was dropped; warm: the same again; "
      "MB: peak RSS; viewer rows: one run after the view server's)")
print()
table = [["what"] + [n for n, _, _ in models]]
for label, cell in rows:
    table.append([label] + [cell(f) for _, _, f in models])
widths = [max(len(r[c]) for r in table) for c in range(len(table[0]))]
for r in table:
    print(" | ".join(v.ljust(w) for v, w in zip(r, widths)).rstrip())
# issue 49's first target: the national default view, cold, within 2x B's
names = [n for n, _, _ in models]
if "national" in names and "B" in names:
    national, b = (seconds(models[names.index(n)][2], "render_cold") for n in ("national", "B"))
    if national and b:
        print()
        print("default view, cold, median: national / B = %.2f / %.2f s = %.2fx" % (national, b, national / b))
EOF
