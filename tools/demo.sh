#!/usr/bin/env bash
############################################################################
# MODULE:    tools/demo.sh (r3.sbrt addon)
# PURPOSE:   The main job on the built-in synthetic model: make the 3D
#            raster, convert it to an SBRT (printing the memory comparison),
#            render a perspective view and the geological map (top view),
#            and write PNGs. Runs in a throw-away location.
# USAGE:     make demo            (SIZE=S|A|B, default A; OUT=dir, default ./demo)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
. "$(dirname "$0")/grass_env.sh"
size=${SIZE:-A}
out=$(mkdir -p "${OUT:-$SBRT_ROOT/demo}" && cd "${OUT:-$SBRT_ROOT/demo}" && pwd)
sbrt_location "$(mktemp -d /tmp/r3sbrt_demo.XXXXXX)"
cat >"$SBRT_GISDBASE/demo_job.sh" <<EOS
set -euo pipefail
"$SBRT_ROOT/tools/make_geomodel.sh" $size geology
r3.sbrt.convert input=geology output=geology -p
TMPDIR_SCENE="$SBRT_GISDBASE"
. "$SBRT_ROOT/tools/geology_scene.sh"
make_geology_inputs
# the views from the south-west, 1056 x 884 pixels, vertical exaggeration 2:
# the paper's Figure 12 (full model, strata hidden, drape, boreholes with
# strata hidden, cross section), a fence diagram and the logged wells alone
for entry in "\${GEOLOGY_VIEWS[@]}"; do
    image=\${entry%%|*}
    r3.sbrt.render --q --o input=geology output=\$image size=1056,884 zexag=2 light=300,50 \\
        normals=kernel kernel=7 smooth=1 png="$out/r3_sbrt_demo_\$image.png" \${entry#*|}
done
# a turntable: 36 frames in one process, the MP4 and a strip of six frames
mkdir -p "$out/orbit"
r3.sbrt.render --q --o input=geology size=480,360 zexag=2 light=300,50 frames=36 -n \
    png="$out/orbit/orbit_%04d.png" video="$out/r3_sbrt_demo_orbit.mp4" fps=12
python3 - "$out" <<'EOP'
import sys
from PIL import Image
out = sys.argv[1]
frames = [Image.open(f"{out}/orbit/orbit_{k:04d}.png") for k in (1, 7, 13, 19, 25, 31)]
w, h = frames[0].size
strip = Image.new("RGB", (3 * w // 2, 2 * h // 2), "white")
for i, frame in enumerate(frames):
    strip.paste(frame.resize((w // 2, h // 2)), ((i % 3) * w // 2, (i // 3) * h // 2))
strip.save(f"{out}/r3_sbrt_demo_orbit_strip.png")
EOP
# a geological profile along a bent line A-B-C: the class profile map
# (distance along the line by elevation) and its figure with axes
r3.sbrt.profile --q --o input=geology coordinates=100,200,1200,1500,1900,900 \
    output=profile png="$out/r3_sbrt_demo_profile.png"
# the geological map: a top view in the model's own grid, and its legend
# from the labels and colours the material map carries (d.legend)
g.region raster_3d=geology
r3.sbrt.render --q --o input=geology output=map view=top material=map_class \\
    png="$out/r3_sbrt_demo_map.png"
rm -f "$out/r3_sbrt_demo_legend.png" # the commands below draw over it
GRASS_RENDER_IMMEDIATE=cairo GRASS_RENDER_FILE="$out/r3_sbrt_demo_legend.png" \\
GRASS_RENDER_WIDTH=900 GRASS_RENDER_HEIGHT=500 GRASS_RENDER_FILE_READ=TRUE \\
    bash -c 'd.rast -n map=map_class; d.legend -c -n raster=map_class at=5,95,71,75 fontsize=12'
r.stats -l -c -n map_class   # cells of each class at the surface
EOS
in_grass PERMANENT bash "$SBRT_GISDBASE/demo_job.sh"
echo "demo: images written to $out: r3_sbrt_demo_view.png (perspective), _hidden.png (upper strata hidden), _drape.png (orthophoto draped), _boreholes.png (wells, strata hidden), _section.png (cross section), _fence.png (fence diagram), _logs.png (wells alone: log and model halves), _map.png and _legend.png (geological map), _orbit.mp4 and _orbit_strip.png (a turntable of 36 frames), _profile.png (a geological profile along a bent line)"
