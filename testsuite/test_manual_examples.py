"""
MODULE:    testsuite/test_manual_examples.py (r3.sbrt addon)
PURPOSE:   Every manual's first example runs as a user copies it: the
           first code block of its EXAMPLES section, HTML entities
           unescaped, run by bash (set -e: every line must succeed) in a
           brand-new XY location; then the maps and SBRTs it names exist
           (g.list, r3.sbrt.manage -l), those it removes do not, and every
           png= file it writes is a PNG. g.gui.sbrt's example ends by
           starting the viewer: it runs under Xvfb until the viewer has
           shown a full frame of the model, then is stopped (issue 52,
           item 4)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import html
import json
import os
import re
import shutil
import signal
import subprocess
import tempfile
import time

from grass.gunittest.case import TestCase
from grass.gunittest.main import test

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
TIMEOUT = 120
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"

# what each first example leaves behind: maps by type (g.list -t), SBRTs,
# SBRTs it removed, and words its standard output holds
EXPECTED = {
    "r3.sbrt.convert": dict(maps=["raster_3d/geology", "raster_3d/geology_back"],
                            sbrt=["geology"], stdout=["SBRT:", "compression"]),
    "r3.sbrt.manage": dict(sbrt=["geology", "geology_2024"], gone=["geology_old"]),
    "r3.sbrt.support": dict(sbrt=["geology"], stdout=["Sandstone", "Topsoil"]),
    "r3.sbrt.render": dict(maps=["raster/view", "raster/view.red", "raster/map",
                                 "raster/map_class"], sbrt=["geology"]),
    "r3.sbrt.what": dict(sbrt=["geology"], stdout=["Point 1", "Point 2", '"intervals"']),
    "r3.sbrt.surface": dict(maps=["raster/topsoil_thickness", "raster/topsoil_top",
                                  "raster/topsoil_base"], sbrt=["geology"],
                            stdout=["mean="]),
    "r3.sbrt.volume": dict(sbrt=["geology"], stdout=["volume", "cells"]),
    "r3.sbrt.profile": dict(maps=["raster/profile"], sbrt=["geology"]),
    "g.gui.sbrt": dict(sbrt=["geology"]),
}


def first_example(module):
    """The text of the first code block after the manual's EXAMPLE(S)
    heading, as a reader's browser shows it (entities unescaped)."""
    with open(os.path.join(ROOT, module, module + ".html"), encoding="utf-8") as page:
        text = page.read()
    heading = re.search(r"<h2>EXAMPLES?</h2>", text)
    if not heading:
        raise AssertionError("%s.html has no EXAMPLES section" % module)
    block = re.search(r'<div class="code"><pre>(.*?)</pre></div>', text[heading.end():],
                      re.DOTALL)
    if not block:
        raise AssertionError("%s.html has no code block in EXAMPLES" % module)
    return html.unescape(block.group(1))


def grass_env(**extra):
    """The environment of a new GRASS session: the current one's variables
    (GRASS_ADDON_BASE: the addon's ./dist) less those that tie it to the
    session the test runs in."""
    env = dict(os.environ, **extra)
    for name in ("GISRC", "GISBASE", "WIND_OVERRIDE", "GRASS_REGION", "MAPSET",
                 "LOCATION_NAME", "GISDBASE", "GIS_LOCK"):
        env.pop(name, None)
    return env


class ManualExampleCase(TestCase):
    """Runs one manual's first example in a location of its own."""

    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="r3sbrt_manual_")
        self.addCleanup(shutil.rmtree, self.work, ignore_errors=True)
        self.location = os.path.join(self.work, "xy")

    def run_example(self, module):
        """Runs the example by bash in a new XY location, in an empty
        working folder; gives the finished process."""
        script = "set -e\n" + first_example(module)
        return subprocess.run(
            ["grass", "-c", "XY", self.location, "--exec", "bash", "-c", script],
            cwd=self.work, env=grass_env(), capture_output=True, text=True,
            timeout=TIMEOUT)

    def in_location(self, *command):
        """Output of a command in the example's location (PERMANENT)."""
        run = subprocess.run(
            ["grass", os.path.join(self.location, "PERMANENT"), "--exec"] + list(command),
            cwd=self.work, env=grass_env(), capture_output=True, text=True,
            timeout=TIMEOUT)
        self.assertEqual(run.returncode, 0, run.stderr[-2000:])
        return run.stdout.split()

    def check_outputs(self, module, stdout=""):
        expected = EXPECTED[module]
        for word in expected.get("stdout", []):
            self.assertIn(word, stdout, "%s's first example printed no %r" % (module, word))
        if expected.get("maps"):
            maps = self.in_location("g.list", "-t", "type=raster,raster_3d,vector")
            for name in expected["maps"]:
                self.assertIn(name, maps, "%s's first example made no %s" % (module, name))
        sbrts = self.in_location("r3.sbrt.manage", "-l")
        for name in expected.get("sbrt", []):
            self.assertIn(name, sbrts, "%s's first example made no SBRT %s" % (module, name))
        for name in expected.get("gone", []):
            self.assertNotIn(name, sbrts, "%s's first example left %s" % (module, name))
        pngs = re.findall(r"\bpng=(\S+)", first_example(module))
        for name in pngs:
            path = os.path.join(self.work, name)
            self.assertTrue(os.path.isfile(path), "%s's example wrote no %s" % (module, name))
            with open(path, "rb") as png:
                self.assertEqual(png.read(8), PNG_MAGIC, "%s is not a PNG" % name)

    def check_module(self, module):
        run = self.run_example(module)
        self.assertEqual(run.returncode, 0,
                         "%s's first example failed:\n%s" % (module, run.stderr[-3000:]))
        self.check_outputs(module, run.stdout)


class TestManualExamples(ManualExampleCase):
    """One test a manual: its first example, in a new XY location."""

    def test_r3_sbrt_convert(self):
        self.check_module("r3.sbrt.convert")

    def test_r3_sbrt_manage(self):
        self.check_module("r3.sbrt.manage")

    def test_r3_sbrt_support(self):
        self.check_module("r3.sbrt.support")

    def test_r3_sbrt_render(self):
        self.check_module("r3.sbrt.render")

    def test_r3_sbrt_what(self):
        self.check_module("r3.sbrt.what")

    def test_r3_sbrt_surface(self):
        self.check_module("r3.sbrt.surface")

    def test_r3_sbrt_volume(self):
        self.check_module("r3.sbrt.volume")

    def test_r3_sbrt_profile(self):
        self.check_module("r3.sbrt.profile")

    def test_g_gui_sbrt(self):
        """The example ends by starting the viewer, which runs until a
        person closes it: under Xvfb, until it logs a full frame of the
        model (GRASS_SBRT_VIEWER_LOG), then stopped."""
        for tool in ("Xvfb",):
            if not shutil.which(tool):
                self.fail("%s is missing (make setup installs it)" % tool)
        log_path = os.path.join(self.work, "viewer.log")
        xvfb = subprocess.Popen(
            ["Xvfb", "-displayfd", "1", "-screen", "0", "1280x900x24", "-nolisten", "tcp",
             "-noreset"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
        self.addCleanup(xvfb.wait, timeout=10)
        self.addCleanup(xvfb.terminate)
        display = ":" + xvfb.stdout.readline().decode().strip()
        script = "set -e\n" + first_example("g.gui.sbrt")
        with open(os.path.join(self.work, "example.err"), "w") as err:
            example = subprocess.Popen(
                ["grass", "-c", "XY", self.location, "--exec", "bash", "-c", script],
                cwd=self.work, stdout=subprocess.DEVNULL, stderr=err,
                env=grass_env(DISPLAY=display, GRASS_SBRT_VIEWER_LOG=log_path,
                              NO_AT_BRIDGE="1"),
                start_new_session=True)
        frame = None
        deadline = time.monotonic() + TIMEOUT
        try:
            while frame is None and time.monotonic() < deadline:
                if example.poll() is not None:
                    break
                frame = self.full_frame(log_path)
                if frame is None:
                    time.sleep(0.2)  # polling the log, not a measure of time
        finally:
            if example.poll() is None:
                os.killpg(example.pid, signal.SIGTERM)
            example.wait(timeout=30)
        with open(os.path.join(self.work, "example.err")) as err:
            messages = err.read()[-3000:]
        self.assertIsNotNone(frame, "g.gui.sbrt's example showed no full frame:\n" + messages)
        self.assertIn("input=geology", frame["words"])
        self.check_outputs("g.gui.sbrt")

    @staticmethod
    def full_frame(log_path):
        if not os.path.exists(log_path):
            return None
        with open(log_path) as log:
            for line in log:
                if line.endswith("\n"):
                    event = json.loads(line)
                    if event.get("event") == "frame" and event.get("full"):
                        return event
        return None


if __name__ == "__main__":
    test()
