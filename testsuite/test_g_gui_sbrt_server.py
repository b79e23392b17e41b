"""
MODULE:    testsuite/test_g_gui_sbrt_server.py (r3.sbrt addon)
PURPOSE:   The view server of g.gui.sbrt (r3.sbrt.render --serve) through
           the viewer's own client: each frame is the image the same
           options render on the command line (maps read cell for cell),
           after camera moves, hidden strata and a section seen from both
           sides (the prepared scene kept or rebuilt as it must); errors
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import re
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test

from geomodel_fixture import CHANNEL_REGION, set_up_channel_model, set_up_t_model
from viewer_fixture import read_rgb_maps
from view_client import ServerError, ViewServer
from column_profile import profile_figure, read_column
import grass.script as gs

from shell_output import shell_records


class TestViewServer(TestCase):
    @classmethod
    def setUpClass(cls):
        set_up_t_model(cls)
        cls.server = ViewServer()

    @classmethod
    def tearDownClass(cls):
        cls.server.close()
        cls.del_temp_region()

    def command_line_rgb(self, words, name):
        """The RGB of `words` rendered by the command line as maps."""
        subprocess.run(["r3.sbrt.render"] + words + ["output=" + name, "--overwrite",
                                                     "--quiet"], check=True)
        self.use_temp_region()
        self.runModule("g.region", raster=name + ".red")
        return read_rgb_maps(name)

    def assertSameAsCommandLine(self, words, name):
        frame = self.server.render(words)
        cols, rows, rgb = self.command_line_rgb(words, name)
        self.assertEqual((frame.width, frame.height), (cols, rows))
        differing = sum(1 for i in range(0, len(rgb), 3) if rgb[i:i + 3] != frame.rgb[i:i + 3])
        self.assertEqual(differing, 0, "%d of %d pixels differ from %s" % (
            differing, cols * rows, " ".join(words)))
        return frame

    def test_frames_are_the_command_lines_images(self):
        """Camera moves (scene kept), hide= (rebuilt), back (rebuilt)."""
        base = ["input=geo", "size=120,90"]
        first = self.assertSameAsCommandLine(base + ["azimuth=225"], "vs_a")
        self.assertAlmostEqual(first.azimuth, 225, places=6)
        self.assertAlmostEqual(first.elevation, 30, places=6)
        self.assertGreater(first.distance, 0)
        self.assertSameAsCommandLine(base + ["azimuth=100", "elevation=50"], "vs_b")
        hidden = self.assertSameAsCommandLine(base + ["azimuth=100", "elevation=50",
                                                     "hide=3"], "vs_c")
        again = self.assertSameAsCommandLine(base + ["azimuth=100", "elevation=50"], "vs_d")
        self.assertNotEqual(hidden.rgb, again.rgb)
        # light and translucency: shading kept apart from the prepared scene
        self.assertSameAsCommandLine(base + ["azimuth=100", "light=190,30"], "vs_e")
        self.assertSameAsCommandLine(base + ["azimuth=100", "light=20,60", "ambient=0.5",
                                            "opacity=5:0.4"], "vs_f")
        self.assertSameAsCommandLine(base + ["azimuth=100", "normals=kernel"], "vs_g")

    def test_gpu_frames_are_the_command_lines_images(self):
        """backend=egl (llvmpipe here, a GPU where there is one): the
        server keeps the model on the GPU between frames, and each frame is
        the egl command line's image; kernel normals and a hidden stratum
        on the GPU too."""
        base = ["input=geo", "size=120,90", "backend=egl"]
        first = self.assertSameAsCommandLine(base + ["azimuth=225"], "vs_ga")
        self.assertSameAsCommandLine(base + ["azimuth=100", "elevation=50"], "vs_gb")
        self.assertSameAsCommandLine(base + ["azimuth=100", "elevation=50", "hide=3"],
                                     "vs_gc")
        self.assertSameAsCommandLine(base + ["azimuth=100", "normals=kernel"], "vs_gd")
        # the CPU's image but for float rounding on a few pixels
        cpu = self.server.render(["input=geo", "size=120,90", "azimuth=225"])
        differing = sum(1 for i in range(0, len(cpu.rgb), 3)
                        if max(abs(a - b) for a, b in zip(cpu.rgb[i:i + 3],
                                                          first.rgb[i:i + 3])) > 1)
        self.assertLessEqual(differing, 120 * 90 // 100)

    def test_section_faces_each_camera(self):
        """The section's removed side follows the camera: the scene is
        prepared again when the camera crosses the plane."""
        base = ["input=geo", "size=100,80", "section=0,31,63,31", "elevation=35"]
        self.assertSameAsCommandLine(base + ["azimuth=180"], "vs_s1")
        self.assertSameAsCommandLine(base + ["azimuth=0"], "vs_s2")
        self.assertSameAsCommandLine(base + ["azimuth=200"], "vs_s3")

    def test_reported_camera_reproduces_the_view(self):
        """azimuth=, elevation=, distance=, target= as answered frame the
        same image as the framed default (within rounding)."""
        framed = self.server.render(["input=geo", "size=80,60"])
        explicit = self.server.render([
            "input=geo", "size=80,60", "azimuth=%r" % framed.azimuth,
            "elevation=%r" % framed.elevation, "distance=%r" % framed.distance,
            "target=%r,%r,%r" % framed.target])
        differing = sum(1 for a, b in zip(framed.rgb, explicit.rgb) if abs(a - b) > 2)
        self.assertLess(differing, 0.01 * len(framed.rgb))

    def test_classes(self):
        extent, strata = self.server.strata("geo")
        self.assertLess(extent.south, extent.north)
        self.assertLess(extent.bottom, extent.top)
        ids = [s.id for s in strata]
        self.assertIn(3, ids)
        # the exaggeration the command line fits to the model and says
        run = subprocess.run(["r3.sbrt.render", "input=geo", "size=40,30",
                              "output=vs_z", "--overwrite"],
                             capture_output=True, text=True, check=True)
        said = re.search(r"Vertical exaggeration (\S+), fitted",
                         " ".join(run.stderr.split()))
        self.assertIsNotNone(said, run.stderr)
        self.assertEqual(float(said.group(1)), extent.zexag)
        self.assertTrue(extent.voxels)  # a 3D raster's tops are voxel boundaries
        for s in strata:
            self.assertEqual(len(s.rgb), 3)

    def test_classes_come_by_id(self):
        """The classes reply lists the classes by id, whatever order the
        model holds them in (a GeoTOP file: 3, 6, 2, 7, 8, 5, 0, 1)."""
        self.use_temp_region()
        self.runModule("g.region", n=40, s=0, w=0, e=40, b=0, t=30, res=10, res3=10,
                       tbres=10)
        # met top down 9, 2, 5 (and bottom up 5, 2, 9): neither is by id
        self.runModule("r3.mapcalc", overwrite=True,
                       expression="vs_order = if(depth() == 3, 9, if(depth() == 2, 2, 5))")
        subprocess.run(["r3.sbrt.convert", "input=vs_order", "output=vs_order",
                        "--overwrite", "--quiet"], check=True, timeout=120)
        try:
            _extent, strata = self.server.strata("vs_order")
        finally:
            self.runModule("g.remove", flags="f", type="raster_3d", name="vs_order")
            self.runModule("r3.sbrt.manage", flags="f", remove="vs_order")
        ids = [s.id for s in strata if s.id != -2**31]  # the empty material's
        self.assertEqual(ids, [2, 5, 9])

    def test_bad_requests(self):
        """A word the module does not know, and a value it refuses, are
        answered with the module's message and the server goes on
        (test_r3_sbrt_render_requests.py checks that the process stays)."""
        refused = [
            ("nonsense=1", "unknown option <nonsense>"),
            ("view=sideways", "not one of"),
            ("zexag=", "zexag=: give a value"),
            ("azimuth=400", "azimuth=400: not within 0-360"),
            ("frames=3", "for the command line"),
            ("hide=1\nrender", "line break"),
            ("fov=500", "fov=500"),  # the module's own check: answered, serving on
            # past the buffer GRASS 8.2's G_str_to_color copies it into
            # (the request fuzzer found it aborting the server)
            ("background=b" + "\u00fe" * 120 + "lacsik", "is not a colour"),
        ]
        # no subTest: GRASS 8.2's gunittest drops failures inside one
        for word, message in refused:
            with self.assertRaisesRegex(ServerError, message, msg=word):
                self.server.render(["input=geo", word])
        with self.assertRaisesRegex(ServerError, "not found|No SBRT|does not exist"):
            self.server.render(["input=no_such_sbrt"])
        frame = self.server.render(["input=geo", "size=40,30"])
        self.assertEqual(len(frame.rgb), 40 * 30 * 3)



class TestViewServerChannels(TestCase):
    """The channels the viewer offers, what a click hits (pick) and the
    column profile it then draws."""

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        set_up_channel_model(cls, "vlith", "vprob")
        cls.server = ViewServer()

    @classmethod
    def tearDownClass(cls):
        cls.server.close()
        cls.runModule("r3.sbrt.manage", flags="f", remove="vlith")
        cls.del_temp_region()

    def test_model_lists_the_channels(self):
        extent, strata, channels = self.server.model("vlith")
        self.assertEqual([s.id for s in strata if s.id > 0], [1, 2, 3])
        self.assertEqual(len(channels), 1)
        listing = gs.read_command("r3.sbrt.convert", flags="g", sbrt="vlith")
        fields = shell_records(listing, "channel")[-1]
        self.assertEqual(channels[0].name, "vprob")
        self.assertEqual(channels[0].unit, "%")
        self.assertEqual(channels[0].long_name, "P(sand)")
        self.assertEqual((channels[0].low, channels[0].high),
                         (float(fields["min"]), float(fields["max"])))

    def test_top_view_pick_is_the_cell_and_its_top_voxel(self):
        """A top view's pixel (row, col) is cell (row, col): the pick is its
        centre at the column's top, with the top layer's class and the
        channel's value at the top voxel (r3.sbrt.what's log)."""
        words = ["input=vlith", "view=top", "property=vprob"]
        for row, col in ((0, 0), (3, 7), (9, 11), (5, 2)):
            pick = self.server.pick(words, row, col)
            self.assertAlmostEqual(pick.x, 50 + 100 * col, places=6)
            self.assertAlmostEqual(pick.y, 950 - 100 * row, places=6)
            column = read_column("vlith", pick.x, pick.y)
            self.assertAlmostEqual(pick.z, column["intervals"][0]["top"], places=6)
            self.assertEqual(pick.class_id, column["intervals"][0]["class"])
            self.assertEqual(pick.value, column["voxels"][0]["values"]["vprob"])
        with self.assertRaisesRegex(ServerError, "outside the 12 x 10 view"):
            self.server.pick(words, 10, 0)
        with self.assertRaisesRegex(ServerError, "not a pixel index"):
            self.server.pick(words, -1, 0)

    def test_perspective_pick_lies_on_its_column(self):
        """A perspective click: the hit lies within its column's layers, on
        the layer of its class (a face between layers belongs to either)."""
        words = ["input=vlith", "size=160,120", "zexag=20", "azimuth=200",
                 "elevation=35"]
        hits = 0
        for row, col in ((60, 80), (50, 60), (70, 100), (40, 90)):
            pick = self.server.pick(words, row, col)
            if pick is None:
                continue
            hits += 1
            column = read_column("vlith", pick.x, pick.y)
            layers = [i for i in column["intervals"]
                      if i["bottom"] - 1e-6 <= pick.z <= i["top"] + 1e-6]
            self.assertIn(pick.class_id, [i["class"] for i in layers], (row, col, pick))
        self.assertGreaterEqual(hits, 3)
        # a pixel of the sky
        self.assertIsNone(self.server.pick(words, 0, 0))
        # the viewer's smooth shading: the same hit (lighting is not picked)
        smooth = self.server.pick(words + ["normals=kernel", "smooth=1"], 60, 80)
        self.assertEqual(smooth[:4], self.server.pick(words, 60, 80)[:4])  # value: nan

    def test_property_frames_are_the_command_lines(self):
        """What the viewer's property controls ask for: colour by a channel,
        a selection threshold, a fade; each frame as the command line's."""
        for extra, name in ((["property=vprob"], "vp_a"),
                            (["property=vprob", "select=vprob>=60"], "vp_b"),
                            (["fade=vprob", "fade_range=0,100"], "vp_c")):
            words = ["input=vlith", "size=90,70", "zexag=20"] + extra
            frame = self.server.render(words)
            subprocess.run(["r3.sbrt.render"] + words + ["output=" + name, "--overwrite",
                                                         "--quiet"], check=True)
            self.runModule("g.region", raster=name + ".red")
            cols, rows, rgb = read_rgb_maps(name)
            self.runModule("g.region", **CHANNEL_REGION)
            self.assertEqual(bytes(rgb), bytes(frame.rgb), name)

    def test_profile_draws_every_voxel(self):
        """The profile's channel line is the column's values voxel by voxel
        (a step: top and bottom of each), its class strip the layers."""
        _extent, strata, channels = self.server.model("vlith")
        column = read_column("vlith", 750, 350)
        figure = profile_figure(column, strata, channels, "vlith")
        strip, panel = figure.axes
        self.assertEqual(len(strip.patches), len(column["intervals"]))
        line = panel.get_lines()[0]
        self.assertEqual(line.get_label(), "vprob")
        expected = []
        for voxel in column["voxels"]:
            expected += [voxel["values"]["vprob"]] * 2
        self.assertEqual(list(line.get_xdata()), expected)
        self.assertEqual(panel.get_xlabel(), "%")
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "profile.png")
            figure.savefig(path)
            self.assertGreater(os.path.getsize(path), 5000)
        out = os.environ.get("SBRT_PROFILE_PNG")
        if out:  # for a person to look at
            figure.savefig(out)


if __name__ == "__main__":
    test()
