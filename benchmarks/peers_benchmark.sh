#!/usr/bin/env bash
############################################################################
# MODULE:    benchmarks/peers_benchmark.sh (r3.sbrt addon)
# PURPOSE:   The speed figures against the peers, all in one run on the
#            same data and image size (1056 x 884) and camera
#            (position=4375,5000,2500 target=1000,1250,320 fov=25 zexag=2):
#            - m.nviz.image, three slices (one process per image, Xvfb);
#            - ParaView pvbatch, volume rendering with stepped class
#              colours: whole process (read + setup + first frame), later
#              frames;
#            - r3.sbrt.render: one image end to end (a fresh process, as a
#              GRASS user runs it, best of 3), its render stage, and the
#              render stage with empty-space skipping off (-e);
#            - r3.sbrt.convert once (the SBRT is built once per model).
#            Data and peer scripts: ../shared/peers (SBRT_PEERS moves them).
# USAGE:     make && benchmarks/peers_benchmark.sh [SIZES]  (A B)
#            needs: apt-get install xvfb mesa-utils paraview
#                   python3-paraview bc
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
peers=${SBRT_PEERS:-$root/../shared/peers}
sizes=${*:-A B}
P=/tmp/peers
. "$root/tools/grass_env.sh" # puts the built modules on the path
dims() { case $1 in A) echo 200,250,320 ;; B) echo 400,500,400 ;; C200) echo 800,1000,200 ;; esac; }
if [ -z "${DISPLAY:-}" ]; then
    Xvfb :99 -screen 0 1920x1080x24 +extension GLX -nolisten tcp -noreset >/tmp/r3sbrt_xvfb.log 2>&1 &
    xpid=$!
    trap 'kill $xpid 2>/dev/null' EXIT
    export DISPLAY=:99
    sleep 2
fi
G() { grass "$P/loc/PERMANENT" --exec "$@" 2>/dev/null; }
for s in $sizes; do
    [ -d "$P/loc/PERMANENT/grid3/geo_$s" ] || "$peers/make_data.sh" "$s" >/dev/null 2>&1
    if [ ! -e "$P/data/geo_$s.f32" ]; then
        mkdir -p "$P/data"
        G bash -c "g.region raster_3d=geo_$s && r3.out.bin -r --o --q input=geo_$s output=$P/data/geo_$s.f32 bytes=4 null=0"
    fi
    # ours: the SBRT, once
    cat >"$P/ours.sh" <<EOS
g.region --q raster_3d=geo_$s
/usr/bin/time -f "%e" -o $P/convert.time r3.sbrt.convert --o --q input=geo_$s output=geo_$s
g.region --q rows=884 cols=1056
for flag in "" -e; do
    for i in 1 2 3; do
        /usr/bin/time -f "%e" -o $P/render.time r3.sbrt.render \$flag --o --v input=geo_$s output=ours_$s size=1056,884 \
            position=4375,5000,2500 target=1000,1250,320 fov=25 zexag=2 2>$P/render.log
        echo "run flag=\${flag:-none} wall=\$(cat $P/render.time) render_ms=\$(sed -n 's/.*tracing: .* rays in \([0-9.]*\) ms.*/\1/p' $P/render.log)"
    done
done
echo "convert wall=\$(cat $P/convert.time)"
EOS
    G bash "$P/ours.sh" >"$P/ours_$s.txt"
    best() { awk -v f="$1" -v k="$2" '$2 == "flag=" f { split($0, a, k "="); split(a[2], b, " "); v = b[1] + 0; if (m == "" || v < m) m = v } END { print m }' "$P/ours_$s.txt"; }
    ours_wall=$(best none wall)
    ours_ms=$(best none render_ms)
    noskip_ms=$(best -e render_ms)
    convert_s=$(sed -n 's/^convert wall=//p' "$P/ours_$s.txt")
    # m.nviz.image: three slices, one process per image
    nviz=$(NVIZ_MODES=slices "$peers/nviz.sh" "$s" 2>/dev/null | sed -n 's/.*mode=slices wall_s=\([0-9.]*\).*/\1/p')
    # ParaView: the whole pvbatch process, and its later frames
    /usr/bin/time -f "%e" -o "$P/pv.time" pvbatch "$peers/vtk_render.py" --paraview \
        --raw "$P/data/geo_$s.f32" --dims "$(dims "$s")" --modes volume --frames 3 --tag "$s" \
        --out "$P/out" >"$P/pv_$s.txt" 2>/dev/null
    pv_process=$(cat "$P/pv.time")
    pv_later=$(awk '/mode=volume frame=[12] /{ split($0, a, "seconds="); v = a[2] + 0; if (m == "" || v < m) m = v } END { print m }' "$P/pv_$s.txt")
    echo "peers size=$s ours_end_to_end_s=$ours_wall ours_render_ms=$ours_ms ours_render_no_skipping_ms=$noskip_ms ours_convert_once_s=$convert_s nviz_slices_s=${nviz:-?} paraview_process_s=$pv_process paraview_later_frame_s=${pv_later:-?}"
    awk -v o="$ours_wall" -v r="$ours_ms" -v n="${nviz:-0}" -v p="$pv_process" -v l="${pv_later:-0}" -v e="$noskip_ms" -v s="$s" 'BEGIN {
        printf "ratios size=%s nviz/ours_end_to_end=%.1f paraview_process/ours_end_to_end=%.1f paraview_later_frame/ours_render=%.1f skipping_off/on=%.2f\n",
            s, n / o, p / o, l * 1000 / r, e / r }'
done
