#!/usr/bin/env bash
############################################################################
# MODULE:    tools/log_picture.sh (r3.sbrt addon)
# PURPOSE:   The manual pages' picture of the numbers beside a render of the
#            same model: the S model with two wells (r3.sbrt.render
#            boreholes=), the isopach of its topsoil and till with the wells
#            (r3.sbrt.surface thickness=, drawn with d.rast, d.legend and
#            d.vect on the cairo driver) and the two wells' logs
#            (r3.sbrt.what format=json, drawn with matplotlib in the
#            model's own colours). Runs in a throw-away location.
# USAGE:     make && tools/log_picture.sh [OUT.png]
#            (default r3.sbrt.what/r3_sbrt_what_logs.png)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
. "$(dirname "$0")/grass_env.sh"
out=$(realpath -m "${1:-$SBRT_ROOT/r3.sbrt.what/r3_sbrt_what_logs.png}")
sbrt_location "$(mktemp -d /tmp/r3sbrt_logs.XXXXXX)"
work=$SBRT_GISDBASE
trap 'rm -rf "$work"' EXIT
cat >"$work/log_picture.sh" <<EOS
set -euo pipefail
"$SBRT_ROOT/tools/make_geomodel.sh" S geo >/dev/null
r3.sbrt.convert --q input=geo output=geo
r3.sbrt.convert -s input=geo
printf '1|700|1250\n2|1700|400\n' |
    v.in.ascii --q input=- output=wells separator=pipe cat=1 x=2 y=3
# the till hidden: the wells stand through it with their whole logs
r3.sbrt.render --q input=geo output=view size=640,480 hide="Topsoil and till" \\
    boreholes=wells borehole_radius=40 png="$work/view.png"
r3.sbrt.surface --q input=geo classes="Topsoil and till" thickness=till_thickness
rm -f "$work/map.png"
GRASS_RENDER_IMMEDIATE=cairo GRASS_RENDER_FILE="$work/map.png" GRASS_RENDER_WIDTH=580 \\
GRASS_RENDER_HEIGHT=480 GRASS_RENDER_FILE_READ=TRUE bash -c '
    d.rast -n map=till_thickness
    d.legend raster=till_thickness at=8,60,85,89 fontsize=13 title="Till (m)"
    d.vect map=wells icon=basic/circle size=14 color=black fill_color=white width=2 \\
        display=shape,cat label_size=16 label_color=black xref=left yref=bottom'
r3.sbrt.what input=geo points=wells format=json output="$work/logs.json"
r3.sbrt.convert -p input=geo >"$work/classes.txt"
EOS
in_grass PERMANENT bash "$work/log_picture.sh"
python3 - "$work" "$out" <<'EOP'
import json
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import Patch, Rectangle
from PIL import Image

work, out = sys.argv[1], sys.argv[2]
# the model's classes: "   13  150:200: 90  Topsoil and till"
colours = {}
for line in open(f"{work}/classes.txt"):
    m = re.match(r"\s+(\d+)\s+(\d+):\s*(\d+):\s*(\d+)\s+(.+)$", line)
    if m:
        colours[int(m.group(1))] = tuple(int(m.group(k)) / 255 for k in (2, 3, 4))
logs = json.load(open(f"{work}/logs.json"))
fig, ax = plt.subplots(figsize=(4.4, 4.8), dpi=100)
seen = {}
for k, log in enumerate(logs):
    for iv in log["intervals"]:
        ax.add_patch(Rectangle((k * 1.6, iv["bottom"]), 1, iv["thickness"],
                               facecolor=colours[iv["class"]], edgecolor="black", lw=0.5))
        seen[iv["class"]] = iv["label"]
    till = [iv for iv in log["intervals"] if iv["label"] == "Topsoil and till"]
    note = f"till {till[0]['thickness']:g} m" if till else "no till"
    ax.text(k * 1.6 + 0.5, log["intervals"][0]["top"] + 12, f"well {log['cat']}\n{note}",
            ha="center", va="bottom", fontsize=9)
ax.set_xlim(-0.3, 2.9)
ax.set_ylim(0, 700)
ax.set_xticks([])
ax.set_ylabel("elevation (m)")
ax.set_title("r3.sbrt.what: the wells' logs", fontsize=10)
handles = [Patch(facecolor=colours[c], edgecolor="black", lw=0.5, label=seen[c])
           for c in sorted(seen, reverse=True)]
ax.legend(handles=handles, loc="center left", bbox_to_anchor=(1.0, 0.5), fontsize=7,
          frameon=False)
fig.tight_layout()
fig.savefig(f"{work}/logs.png")
# side by side at the render's height
panels = [Image.open(f"{work}/{name}.png").convert("RGB") for name in ("view", "map", "logs")]
height = panels[0].height
panels = [p.resize((round(p.width * height / p.height), height)) for p in panels]
sheet = Image.new("RGB", (sum(p.width for p in panels) + 20 * (len(panels) - 1), height), "white")
x = 0
for p in panels:
    sheet.paste(p, (x, 0))
    x += p.width + 20
sheet.save(out)
print(out)
EOP
