"""
MODULE:    testsuite/viewer_fixture.py (r3.sbrt addon)
PURPOSE:   What the tests of g.gui.sbrt share: its Python files on the
           path, the RGB of r3.sbrt.render's maps read cell for cell, and
           the viewer started under Xvfb and driven as a person would
           (xdotool, screenshots with ImageMagick's import)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

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


TIMEOUT = 60


class ViewerSession:
    """A mixin of gunittest cases: g.gui.sbrt under Xvfb, its event log
    (GRASS_SBRT_VIEWER_LOG), waits, clicks and screenshots."""

    @classmethod
    def start_viewer(cls, options):
        """Starts Xvfb and g.gui.sbrt with `options`; cls.widgets holds the
        screen rectangles of the widgets it logged."""
        for tool in ("Xvfb", "xdotool", "import"):
            if not shutil.which(tool):
                raise RuntimeError("%s is missing (make setup installs it)" % tool)
        cls.work = tempfile.mkdtemp(prefix="g_gui_sbrt_")
        cls.addClassCleanup(shutil.rmtree, cls.work, ignore_errors=True)
        cls.log_path = os.path.join(cls.work, "viewer.log")
        # -noreset: without it Xvfb resets when its last client leaves
        # (the readiness probe below), and a client connecting during
        # the reset is refused: wx's start failed so on a loaded machine
        # (reproduced here: 15 of 30 starts under load, 0 with -noreset)
        cls.xvfb = subprocess.Popen(
            ["Xvfb", "-displayfd", "1", "-screen", "0", "1280x900x24", "-nolisten", "tcp",
             "-noreset"],
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
        cls.addClassCleanup(cls.xvfb.wait, timeout=10)
        cls.addClassCleanup(cls.xvfb.terminate)
        cls.display = ":" + cls.xvfb.stdout.readline().decode().strip()
        cls.env = dict(os.environ, DISPLAY=cls.display, GRASS_SBRT_VIEWER_LOG=cls.log_path,
                       NO_AT_BRIDGE="1")
        # the server takes connections (a loaded machine may be slow to)
        for _ in range(100):
            if subprocess.run(["xdotool", "getdisplaygeometry"], env=cls.env,
                              capture_output=True).returncode == 0:
                break
            if cls.xvfb.poll() is not None:
                raise RuntimeError("Xvfb ended at once (display %s)" % cls.display)
            time.sleep(0.1)
        else:
            raise RuntimeError("Xvfb on %s takes no connections" % cls.display)
        cls.viewer = subprocess.Popen(
            ["g.gui.sbrt"] + list(options), cwd=cls.work, env=cls.env,
            stdout=subprocess.DEVNULL, stderr=open(os.path.join(cls.work, "viewer.err"), "w"))
        cls.addClassCleanup(cls.viewer.wait, timeout=10)
        cls.addClassCleanup(cls.viewer.terminate)
        cls.widgets = {e["name"]: e["rect"] for e in cls.wait_for(
            lambda e: e["event"] == "widget" and e["name"] == "toolbar", every=True)
            if e["event"] == "widget"}

    @classmethod
    def events(cls):
        if not os.path.exists(cls.log_path):
            return []
        with open(cls.log_path) as log:
            return [json.loads(line) for line in log if line.endswith("\n")]

    @classmethod
    def wait_for(cls, condition, after=0, every=False):
        """The first event after `after` (a count) that meets `condition`
        (with every=True: all events up to it)."""
        deadline = time.time() + TIMEOUT
        while time.time() < deadline:
            events = cls.events()
            for k in range(after, len(events)):
                if condition(events[k]):
                    return events[: k + 1] if every else events[k]
            if cls.viewer.poll() is not None:
                raise RuntimeError("g.gui.sbrt ended: " +
                                   open(os.path.join(cls.work, "viewer.err")).read())
            time.sleep(0.1)
        with open(os.path.join(cls.work, "viewer.err")) as err:
            messages = err.read()[-2000:]
        raise RuntimeError("g.gui.sbrt did not get there in %d s; its messages: %s"
                           % (TIMEOUT, messages))

    def xdotool(self, *words):
        subprocess.run(["xdotool"] + [str(w) for w in words], env=self.env, check=True)

    def click(self, name, x_offset=None):
        """A click on widget `name`: its middle, or `x_offset` pixels from
        its left edge."""
        x, y, width, height = self.widgets[name]
        self.xdotool("mousemove", x + (width // 2 if x_offset is None else x_offset),
                     y + height // 2, "click", 1)

    def screenshot(self):
        """RGB bytes of the canvas as on screen."""
        time.sleep(0.5)  # the frame painted
        x, y, width, height = self.widgets["canvas"]
        ppm = subprocess.run(
            ["import", "-display", self.display, "-window", "root", "-crop",
             "%dx%d+%d+%d" % (width, height, x, y), "+repage", "-depth", "8", "ppm:-"],
            capture_output=True, check=True).stdout
        header_end = 0
        for _ in range(4):  # P6, width, height, maximum: blank-separated
            while ppm[header_end:header_end + 1].isspace():
                header_end += 1
            while not ppm[header_end:header_end + 1].isspace():
                header_end += 1
        return ppm[header_end + 1:]

    def full_frame_after(self, count, word=None, smooth=False):
        """The first full-size frame after event `count` (with `word` among
        its options where given): face normals at once, or with `smooth`
        the smooth frame (kernel normals) that follows once the view rests
        (voxel models, smooth shading on)."""
        return self.wait_for(
            lambda e: e["event"] == "frame" and e["full"] and
            (word is None or word in e["words"]) and
            (not smooth or e.get("smooth")), after=count)
