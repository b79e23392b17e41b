"""
MODULE:    testsuite/test_g_gui_sbrt_state.py (r3.sbrt addon)
PURPOSE:   g.gui.sbrt's view as r3.sbrt.render options (view_state.py):
           the mouse's camera moves, the section, the option words and the
           command line
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import math
import shlex
import subprocess
import xml.etree.ElementTree as ET

from grass.gunittest.case import TestCase
from grass.gunittest.main import test

import viewer_fixture  # noqa: F401 (g.gui.sbrt's files on the path)
from view_client import Extent, Stratum
from view_state import (LIGHT_ELEVATION, LIGHT_FROM_CAMERA, NO_CLASS, ViewState,
                        ZexagScale, number)


def make_state():
    extent = Extent(north=2000, south=0, east=1000, west=0, bottom=-100, top=50)
    strata = [Stratum(NO_CLASS, (128, 128, 128), "EMPTY"), Stratum(1, (200, 0, 0), "sand"),
              Stratum(2, (0, 200, 0), "clay"), Stratum(3, (0, 0, 200), "chalk")]
    state = ViewState("model", extent, strata)
    state.distance, state.target = 3000.0, (500.0, 1000.0, -20.0)
    return state


def word(words, key):
    found = [w.split("=", 1)[1] for w in words if w.startswith(key + "=")]
    return found[0] if found else None


class TestViewState(TestCase):
    def test_strata_leave_out_the_empty_material(self):
        self.assertEqual([s.id for s in make_state().strata], [1, 2, 3])

    def test_orbit_wraps_and_clamps(self):
        state = make_state()
        state.orbit(-400, 0)  # 160 degrees on
        self.assertAlmostEqual(state.azimuth, 25.0)
        state.orbit(0, 1000)
        self.assertEqual(state.elevation, 89.0)
        state.orbit(0, -10000)
        self.assertEqual(state.elevation, -89.0)

    def test_pan_moves_across_the_view(self):
        """A drag moves the target at right angles to the view direction,
        by the image's share of the view's width at the target."""
        state = make_state()
        state.azimuth, state.elevation = 180.0, 0.0  # from the south, level
        state.pan(100, 0, 500)
        x, y, z = state.target
        per_pixel = 2 * 3000 * math.tan(math.radians(20)) / 500
        self.assertAlmostEqual(x, 500 - 100 * per_pixel, places=6)  # west
        self.assertAlmostEqual(y, 1000.0, places=6)
        self.assertAlmostEqual(z, -20.0, places=6)
        state.zexag = 2.0
        state.pan(0, 50, 500)  # up, unexaggerated
        self.assertAlmostEqual(state.target[2], -20 + 50 * per_pixel / 2, places=6)

    def test_exaggeration_is_the_fitted_one_and_always_said(self):
        extent = Extent(north=2000, south=0, east=1000, west=0, bottom=-100, top=50,
                        zexag=4.0)
        state = ViewState("model", extent, [])
        self.assertEqual(state.zexag, 4.0)
        self.assertEqual(word(state.words(80, 60), "zexag"), "4")
        state.zexag = 1.0  # the command must still say it: 1 is not the default
        self.assertEqual(word(state.words(80, 60), "zexag"), "1")

    def test_voxel_models_are_shaded_smooth_when_still(self):
        voxels = Extent(north=2000, south=0, east=1000, west=0, bottom=-100, top=50,
                        zexag=4.0, voxels=True)
        state = ViewState("model", voxels, [])
        self.assertEqual(word(state.words(80, 60), "normals"), "kernel")
        self.assertIsNone(word(state.words(40, 30, moving=True), "normals"))
        state.smooth_shading = False
        self.assertIsNone(word(state.words(80, 60), "normals"))
        horizons = voxels._replace(voxels=False)
        self.assertIsNone(word(ViewState("model", horizons, []).words(80, 60), "normals"))

    def test_exaggeration_slider_is_logarithmic(self):
        scale = ZexagScale(1500.0)
        self.assertEqual(scale.value(0), 1.0)
        self.assertEqual(scale.value(ZexagScale.STEPS), 1500.0)
        self.assertEqual(scale.value(ZexagScale.STEPS // 2), 39.0)  # sqrt(1500)
        for zexag in (1.0, 4.0, 50.0, 150.0, 1500.0):
            back = scale.value(scale.position(zexag))
            self.assertLess(abs(math.log(back / zexag)), 0.02, (zexag, back))

    def test_zoom(self):
        state = make_state()
        state.zoom(2)
        self.assertAlmostEqual(state.distance, 3000 * 0.85 ** 2)
        state.zoom(-2)
        self.assertAlmostEqual(state.distance, 3000)

    def test_section_crosses_the_model(self):
        state = make_state()
        self.assertIsNone(state.section_points())
        state.section = (0.0, 0.0)  # west-east through the centre
        x1, y1, x2, y2 = state.section_points()
        self.assertEqual((y1, y2), (1000.0, 1000.0))
        self.assertLess(x1, 0)
        self.assertGreater(x2, 1000)
        state.move_section(0.5)  # half way to the north edge
        self.assertAlmostEqual(state.section_points()[1], 1500.0)
        state.move_section(5)
        self.assertEqual(state.section[1], 0.98)
        state.section = (90.0, 0.0)  # south-north through the centre
        x1, y1, x2, y2 = state.section_points()
        self.assertAlmostEqual(x1, 500.0)
        self.assertAlmostEqual(x2, 500.0)

    def test_profile_of_the_section_across_the_model(self):
        state = make_state()
        state.section = (30.0, 0.2)
        x1, y1, x2, y2 = state.section_chord()
        # both ends on the model's edges, on the section's line
        for x, y in ((x1, y1), (x2, y2)):
            on_edge = min(abs(x - 0), abs(x - 1000), abs(y - 0), abs(y - 2000))
            self.assertAlmostEqual(on_edge, 0, places=6)
            self.assertTrue(-1e-6 <= x <= 1000 + 1e-6 and -1e-6 <= y <= 2000 + 1e-6)
        px1, py1, px2, py2 = state.section_points()
        cross = (px2 - px1) * (y2 - py1) - (py2 - py1) * (x2 - px1)
        self.assertAlmostEqual(cross / math.hypot(px2 - px1, py2 - py1), 0, places=6)
        self.assertAlmostEqual(math.degrees(math.atan2(y2 - y1, x2 - x1)), 30.0)
        args = shlex.split(state.profile_command("/tmp/p q.png", output="prof"))
        self.assertEqual(args[0], "r3.sbrt.profile")
        self.assertEqual(args[1], "input=model")
        self.assertEqual(word(args, "output"), "prof")
        self.assertEqual(word(args, "png"), "/tmp/p q.png")
        numbers = [float(v) for v in word(args, "coordinates").split(",")]
        for got, want in zip(numbers, (x1, y1, x2, y2)):
            self.assertAlmostEqual(got, want, delta=1e-3)
        state.section = None
        self.assertIsNone(state.section_chord())

    def test_words(self):
        state = make_state()
        words = state.words(320, 240)
        self.assertEqual(word(words, "size"), "320,240")
        self.assertEqual(word(words, "azimuth"), "225")
        self.assertEqual(word(words, "light"), "270,45")  # 45 degrees left of the camera
        self.assertEqual(word(words, "target"), "500,1000,-20")
        self.assertIsNone(word(words, "hide"))
        state.hidden = {3, 1}
        state.opacity = {1: 0.5, 2: 0.25}
        state.zexag = 2.5
        words = state.words(320, 240)
        self.assertEqual(word(words, "hide"), "1,3")
        self.assertEqual(word(words, "opacity"), "2:0.25")  # not of a hidden one
        self.assertEqual(word(words, "zexag"), "2.5")
        state.boreholes = "wells"
        state.log_columns = ("top", "bottom", "")
        words = state.words(320, 240)
        self.assertEqual(word(words, "boreholes"), "wells")
        self.assertIsNone(word(words, "log_top"))  # all three or none
        state.log_columns = ("top", "bottom", "lith")
        state.log_depths = True
        words = state.words(320, 240)
        self.assertEqual(word(words, "log_class"), "lith")
        self.assertEqual(word(words, "log_reference"), "depth")
        state.texture = "ortho"
        self.assertIsNone(word(state.words(10, 10), "texture"))  # drape off
        state.drape = True
        self.assertEqual(word(state.words(10, 10), "texture"), "ortho")
        self.assertIsNone(word(words, "memory"))  # the server's default
        state.memory = "2000"
        self.assertEqual(word(state.words(10, 10, moving=True), "memory"), "2000")

    def test_property_words(self):
        """Colour by a property, its selection threshold, a fade: each its
        own option; the selection names the property (a sum too)."""
        state = make_state()
        words = state.words(10, 10)
        for key in ("property", "select", "fade"):
            self.assertIsNone(word(words, key))
        state.property = "kans_5+kans_6"
        self.assertEqual(word(state.words(10, 10), "property"), "kans_5+kans_6")
        self.assertIsNone(word(state.words(10, 10), "select"))
        state.threshold = 60.0
        self.assertEqual(word(state.words(10, 10), "select"), "kans_5+kans_6>=60")
        state.color_by_property = False  # class colours, a probability shell
        words = state.words(10, 10)
        self.assertIsNone(word(words, "property"))
        self.assertEqual(word(words, "select"), "kans_5+kans_6>=60")
        state.fade = "onz_lk"
        self.assertEqual(word(state.words(10, 10), "fade"), "onz_lk")
        state.property = ""
        words = state.words(10, 10)
        self.assertIsNone(word(words, "select"))
        self.assertEqual(word(words, "fade"), "onz_lk")

    def test_profile_stacks_class_probabilities(self):
        """Channels NAME_ID in % of the model's classes are stacked in the
        classes' colours, voxel by voxel; other channels are lines."""
        from column_profile import probability_classes, profile_figure
        from view_client import Channel, Stratum

        strata = [Stratum(1, (255, 0, 0), "clay"), Stratum(2, (0, 0, 255), "sand")]
        kans = [Channel("kans_1", "%", "", 0, 100), Channel("kans_2", "%", "", 0, 100)]
        other = [Channel("onz_lk", "", "", 0, 100)]
        self.assertEqual(probability_classes(kans, strata), [1, 2])
        self.assertIsNone(probability_classes(other, strata))
        self.assertIsNone(probability_classes(kans[:1], strata))
        voxels = [{"level": 1, "top": 2.0, "bottom": 1.0, "class": 2,
                   "values": {"kans_1": 30.0, "kans_2": 70.0, "onz_lk": 40.0}},
                  {"level": 0, "top": 1.0, "bottom": 0.0, "class": 1,
                   "values": {"kans_1": 90.0, "kans_2": 10.0, "onz_lk": None}}]
        column = {"x": 1.0, "y": 2.0, "voxels": voxels, "intervals": [
            {"class": 2, "top": 2.0, "bottom": 1.0, "thickness": 1.0},
            {"class": 1, "top": 1.0, "bottom": 0.0, "thickness": 1.0}]}
        figure = profile_figure(column, strata, kans + other)
        strip, stacked, lines = figure.axes
        fills = stacked.collections
        self.assertEqual([f.get_label() for f in fills], ["kans_1", "kans_2"])
        self.assertEqual(tuple(fills[0].get_facecolor()[0][:3]), (1.0, 0.0, 0.0))
        # kans_2 spans from kans_1's value to 100 at each voxel
        xs = sorted({round(float(x), 6) for x in fills[1].get_paths()[0].vertices[:, 0]})
        self.assertEqual(xs, [30.0, 90.0, 100.0])
        line = lines.get_lines()[0]
        self.assertEqual([str(v) for v in line.get_xdata()], ["40.0", "40.0", "nan", "nan"])

    def test_command_line_is_the_words(self):
        state = make_state()
        state.sbrt = "model@other mapset"
        command = state.command(320, 240, output="saved", png="/tmp/a b.png")
        args = shlex.split(command)
        self.assertEqual(args[0], "r3.sbrt.render")
        self.assertEqual(args[1:], state.words(320, 240) + ["output=saved", "png=/tmp/a b.png"])

    def test_words_are_render_options_with_its_defaults(self):
        """The viewer writes r3.sbrt.render's options by hand: every key
        it writes, with every feature on, is one of the module's options,
        and the defaults it leaves out or starts from are the module's
        own (its interface description), so that a renamed option or a
        changed default fails here, not in the viewer's frames."""
        xml = subprocess.run(["r3.sbrt.render", "--interface-description"],
                             capture_output=True, check=True, timeout=60).stdout
        defaults = {}
        for p in ET.fromstring(xml).iter("parameter"):
            d = p.find("default")
            defaults[p.get("name")] = d.text.strip() if d is not None and d.text else None
        state = make_state()
        state.hidden, state.opacity = {1}, {2: 0.5}
        state.section = (30.0, 0.2)
        state.boreholes, state.borehole_radius = "wells", 12.0
        state.log_columns, state.log_depths = ("top", "bottom", "lith"), True
        state.texture, state.drape = "ortho", True
        state.property, state.threshold, state.fade = "kans_5", 50.0, "onz_lk"
        state.backend, state.smooth_shading = "egl", True
        state.memory = "500"
        words = state.words(320, 240) + state.words(320, 240, moving=True, reduced=True)
        keys = {w.split("=", 1)[0] for w in words}
        self.assertEqual(keys - set(defaults), set())
        self.assertGreaterEqual(len(keys), 24)
        # the camera the viewer starts from (and resets to) and the light
        # it leaves out where it is the module's
        fresh = ViewState("model", make_state().extent, [])
        self.assertEqual(defaults["azimuth"], number(fresh.azimuth))
        self.assertEqual(defaults["elevation"], number(fresh.elevation))
        self.assertEqual(defaults["fov"], number(fresh.fov))
        self.assertEqual(defaults["light"], "315," + number(LIGHT_ELEVATION))
        fresh.azimuth = 315.0 - LIGHT_FROM_CAMERA  # its light: the default
        self.assertIsNone(word(fresh.words(10, 10), "light"))
        self.assertEqual(defaults["backend"], fresh.backend)
        self.assertEqual(defaults["log_reference"], "elevation")  # log_depths off: none
        self.assertEqual(defaults["detail"], "exact")  # a frame not reduced: none
        self.assertEqual(defaults["normals"], "face")  # moving frames: none


if __name__ == "__main__":
    test()
