"""
MODULE:    g.gui.sbrt
PURPOSE:   The profile of a column clicked in the view (issue 29): its
           classes and every property channel voxel by voxel down the
           column, read with r3.sbrt.what, drawn with matplotlib (the
           figure alone for files and tests, in a wx window in the viewer)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

import json
import re
import subprocess

from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

MAX_UNIT_PANELS = 3  # channels are grouped by unit, one panel each


class ProfileError(Exception):
    """r3.sbrt.what failed (its message)."""


def read_column(sbrt, x, y):
    """The json log of the column of SBRT `sbrt` under map point (x, y):
    its intervals and, with channels, its voxels."""
    run = subprocess.run(
        ["r3.sbrt.what", "input=" + sbrt, "coordinates=%r,%r" % (x, y), "format=json"],
        capture_output=True, text=True)
    if run.returncode:
        raise ProfileError(" ".join(run.stderr.split()) or "r3.sbrt.what failed")
    return json.loads(run.stdout)[0]


def channel_panels(channels):
    """The channels (view_client.Channel) grouped by unit, in their order,
    at most MAX_UNIT_PANELS groups: [(unit, [channel, ...]), ...]."""
    panels = []
    for channel in channels:
        for unit, members in panels:
            if unit == channel.unit:
                members.append(channel)
                break
        else:
            if len(panels) < MAX_UNIT_PANELS:
                panels.append((channel.unit, [channel]))
    return panels


def probability_classes(members, strata):
    """The class id of each channel of a panel where the panel holds the
    probabilities of classes, in %, named NAME_ID after the classes (as
    GeoTOP's kans_1 ... kans_9): then they are drawn stacked in the
    classes' colours, as DINOloket's column view does; else None."""
    ids = {s.id for s in strata}
    classes = []
    for channel in members:
        match = re.search(r"_(\d+)$", channel.name)
        if channel.unit != "%" or not match:
            return None
        classes.append(int(match.group(1)))
    # a class the model never has (GeoTOP's unused lithoclass 4) may have
    # its channel; most must be the model's classes
    known = sum(1 for c in classes if c in ids)
    return classes if len(classes) > 1 and 2 * known > len(classes) else None


def voxel_steps(voxels, name):
    """A channel down the column as a step line: (values, heights), two
    points a voxel (its top and bottom), None where it has no value."""
    values, heights = [], []
    for voxel in voxels:
        value = voxel["values"].get(name)
        values += [value, value]
        heights += [voxel["top"], voxel["bottom"]]
    return values, heights


def profile_figure(column, strata, channels, title=""):
    """A matplotlib Figure of `column` (read_column's): a strip of the
    classes (the strata's colours, labels beside) on the left, then a panel
    per unit with each channel's values against elevation."""
    colours = {s.id: tuple(c / 255.0 for c in s.rgb) for s in strata}
    labels = {s.id: s.label for s in strata}
    panels = channel_panels(channels) if column.get("voxels") else []
    figure = Figure(figsize=(2.2 + 3.2 * len(panels), 6.0), dpi=100)
    widths = [1.0] + [3.0] * len(panels)
    axes = figure.subplots(1, len(widths), sharey=True, squeeze=False,
                           gridspec_kw={"width_ratios": widths})[0]
    strip = axes[0]
    intervals = column.get("intervals", [])
    for interval in intervals:
        strip.add_patch(Rectangle((0, interval["bottom"]), 1, interval["thickness"],
                                  facecolor=colours.get(interval["class"], (0.6, 0.6, 0.6)),
                                  edgecolor="black", linewidth=0.4))
        # the class id (and label, where the layer is tall enough) on it
        share = interval["thickness"] / max(1e-9, intervals[0]["top"] - intervals[-1]["bottom"])
        if share >= 0.015:
            label = str(interval["class"])
            if share >= 0.05 and labels.get(interval["class"]):
                label += " " + labels[interval["class"]][:14]
            strip.text(0.5, (interval["top"] + interval["bottom"]) / 2, label, fontsize=7,
                       ha="center", va="center", clip_on=True,
                       bbox={"facecolor": "white", "alpha": 0.6, "linewidth": 0, "pad": 1})
    strip.set_xlim(0, 1)
    strip.set_xticks([])
    strip.set_ylabel("elevation (map units)")
    strip.set_title("class", fontsize=9)
    if intervals:
        top, bottom = intervals[0]["top"], intervals[-1]["bottom"]
        margin = 0.02 * max(top - bottom, 1e-9)
        strip.set_ylim(bottom - margin, top + margin)
    for ax, (unit, members) in zip(axes[1:], panels):
        classes = probability_classes(members, strata)
        if classes:
            draw_stacked(ax, column["voxels"], members, classes, colours)
        else:
            for channel in members:
                values, heights = voxel_steps(column["voxels"], channel.name)
                ax.plot([float("nan") if v is None else v for v in values], heights,
                        label=channel.name, linewidth=1.2)
        ax.set_xlabel(unit or "value")
        ax.grid(True, linewidth=0.3)
        if classes:  # below the panel: the stack fills it
            ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=3)
        else:
            ax.legend(fontsize=7, loc="best")
    where = "x %.2f, y %.2f" % (column["x"], column["y"])
    figure.suptitle(("%s: " % title if title else "") + where, fontsize=10)
    figure.tight_layout()
    return figure


def draw_stacked(ax, voxels, members, classes, colours):
    """Probabilities of classes stacked left to right, voxel by voxel, in
    the classes' colours (0 to 100 % where they sum to 100)."""
    heights = []
    for voxel in voxels:
        heights += [voxel["top"], voxel["bottom"]]
    left = [0.0] * len(heights)
    for channel, class_id in zip(members, classes):
        values, _heights = voxel_steps(voxels, channel.name)
        right = [a + (v or 0.0) for a, v in zip(left, values)]
        if any(v for v in values):
            ax.fill_betweenx(heights, left, right, color=colours.get(class_id, (0.6,) * 3),
                             linewidth=0, label=channel.name)
        left = right
    ax.set_xlim(0, max(100.0, max(left, default=0)))


def show_profile(parent, column, strata, channels, title):
    """A window with the profile (matplotlib in wx)."""
    import wx
    from matplotlib.backends.backend_wxagg import FigureCanvasWxAgg

    frame = wx.Frame(parent, title="Column profile: " + title)
    figure = profile_figure(column, strata, channels, title)
    canvas = FigureCanvasWxAgg(frame, wx.ID_ANY, figure)
    sizer = wx.BoxSizer(wx.VERTICAL)
    sizer.Add(canvas, proportion=1, flag=wx.EXPAND)
    frame.SetSizerAndFit(sizer)
    frame.Show()
    return frame
