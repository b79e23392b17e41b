#!/usr/bin/python3
############################################################################
# MODULE:    benchmarks/plot_time_error.py (r3.sbrt addon)
# PURPOSE:   Plot of error against time per frame: one curve per method
#            from trace_bench's `error` lines, and ParaView's volume
#            rendering as one point (its class image read back from its
#            stepped colour map, compared with our reference class ids).
# USAGE:     plot_time_error.py LINES.txt OUT.png [--classes REF.i32
#            --paraview PV.png --paraview-seconds S --size 1056,884]
#            needs python3-matplotlib, python3-pil (Debian)
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
import argparse
import collections

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# the peers' class colours (../shared/peers/vtk_render.py, make_data.sh)
PEER_COLOURS = {1: (70, 50, 40), 2: (120, 90, 60), 3: (160, 120, 80), 4: (200, 170, 110),
                5: (110, 140, 90), 6: (80, 120, 160), 7: (170, 80, 70), 8: (230, 210, 140),
                9: (140, 160, 120), 10: (190, 140, 190), 11: (100, 100, 100),
                12: (220, 140, 60), 13: (150, 200, 90), 14: (30, 110, 230),
                15: (200, 40, 40), 16: (20, 20, 20)}
NULL = -(2**31)


def read_lines(path):
    """method -> [(setting, ms, material error %, colour rmse)]"""
    curves = collections.OrderedDict()
    for line in open(path):
        if not line.startswith("error "):
            continue
        kv = dict(item.split("=", 1) for item in line.split()[1:])
        curves.setdefault(kv["method"], []).append(
            (kv["setting"], float(kv["ms"]), float(kv["material_error_pct"]),
             float(kv["colour_rmse"])))
    return curves


def paraview_error(png, classes, size):
    """Share (%) of pixels whose class, read back from ParaView's colours
    (nearest class colour, or the white background), differs from ours."""
    from PIL import Image

    cols, rows = size
    ref = np.fromfile(classes, dtype=np.int32).reshape(rows, cols)
    img = np.asarray(Image.open(png).convert("RGB").resize((cols, rows)), dtype=float)
    ids = [NULL] + list(PEER_COLOURS)
    table = np.array([(255, 255, 255)] + list(PEER_COLOURS.values()), dtype=float)
    distance = ((img[:, :, None, :] - table[None, None, :, :]) ** 2).sum(axis=3)
    got = np.array(ids)[distance.argmin(axis=2)]
    return 100.0 * np.mean(got != ref)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("lines")
    ap.add_argument("out")
    ap.add_argument("--classes")
    ap.add_argument("--paraview")
    ap.add_argument("--paraview-seconds", type=float)
    ap.add_argument("--size", default="1056,884")
    a = ap.parse_args()
    curves = read_lines(a.lines)
    fig, (ax, ax_rgb) = plt.subplots(1, 2, figsize=(11, 4.8), dpi=100)
    floor = 1e-3  # zero errors drawn on the axis floor (log scale)
    for method, points in curves.items():
        points = sorted(points, key=lambda p: p[1])
        for axis, k in ((ax, 2), (ax_rgb, 3)):
            axis.plot([p[1] for p in points], [max(p[k], floor) for p in points], "o-",
                      label=method.replace("_", " "))
            for p in points:
                axis.annotate(p[0], (p[1], max(p[k], floor)), textcoords="offset points",
                              xytext=(4, 4), fontsize=7)
    if a.paraview and a.classes:
        size = tuple(int(v) for v in a.size.split(","))
        err = paraview_error(a.paraview, a.classes, size)
        ms = 1000 * a.paraview_seconds
        ax.plot([ms], [err], "s", color="black", label="ParaView volume (later frame)")
        ax.annotate(f"ParaView {err:.1f} %", (ms, err), textcoords="offset points",
                    xytext=(4, -10), fontsize=7)
        print(f"paraview material_error_pct={err:.3f} ms={ms:.1f}")
    for axis, what in ((ax, "pixels with the wrong class (%)"),
                       (ax_rgb, "colour RMSE (0-255) against exact, face normals")):
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel("time per frame (ms), this machine")
        axis.set_ylabel(what)
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=8)
    ax.set_title("Class error (zero drawn at 0.001 %)")
    ax_rgb.set_title("Colour error (zero drawn at 0.001)")
    fig.tight_layout()
    fig.savefig(a.out)


if __name__ == "__main__":
    main()
