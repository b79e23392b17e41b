"""
MODULE:    testsuite/test_g_gui_sbrt_server.py (r3.sbrt addon)
PURPOSE:   The view server of g.gui.sbrt (r3.sbrt.render --serve) through
           the viewer's own client: each frame is the image the same
           options render on the command line (maps read cell for cell),
           after camera moves, hidden strata and a section seen from both
           sides (the prepared scene kept or rebuilt as it must); errors
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test

from geomodel_fixture import set_up_t_model
from viewer_fixture import read_rgb_maps
from view_client import ServerError, ViewServer


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
        for s in strata:
            self.assertEqual(len(s.rgb), 3)

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
        ]
        # no subTest: GRASS 8.2's gunittest drops failures inside one
        for word, message in refused:
            with self.assertRaisesRegex(ServerError, message, msg=word):
                self.server.render(["input=geo", word])
        with self.assertRaisesRegex(ServerError, "not found|No SBRT|does not exist"):
            self.server.render(["input=no_such_sbrt"])
        frame = self.server.render(["input=geo", "size=40,30"])
        self.assertEqual(len(frame.rgb), 40 * 30 * 3)


if __name__ == "__main__":
    test()
