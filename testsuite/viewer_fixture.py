"""
MODULE:    testsuite/viewer_fixture.py (r3.sbrt addon)
PURPOSE:   What the tests of g.gui.sbrt share: its Python files on the
           path, and the RGB of r3.sbrt.render's maps read cell for cell
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import sys

import grass.script as gs

HERE = os.path.dirname(os.path.abspath(__file__))
VIEWER_DIR = os.path.join(HERE, "..", "g.gui.sbrt")
sys.path.insert(0, VIEWER_DIR)


def read_rgb_maps(base):
    """The bytes R, G, B per cell (rows from the north) of the maps
    <base>.red, .green and .blue, read in their own region."""
    channels = []
    for part in ("red", "green", "blue"):
        text = gs.read_command(
            "r.out.ascii", input="%s.%s" % (base, part), flags="h", null_value="-1"
        )
        channels.append([int(v) for v in text.split()])
    info = gs.raster_info(base + ".red")
    data = bytearray()
    for r, g, b in zip(*channels):
        data += bytes((r, g, b))
    return int(info["cols"]), int(info["rows"]), bytes(data)
