"""
MODULE:    testsuite/test_r3_sbrt_utf8_labels.py (r3.sbrt addon)
PURPOSE:   Issue 48, item 9: one label that is not valid UTF-8 (an SBRT of
           another mapset is untrusted) no longer cuts the figures after it
           (cairo stops drawing text in its error state): the PNGs of
           r3.sbrt.render and r3.sbrt.profile with a label holding a bad
           byte equal, pixel for pixel, those with U+FFFD in its place, and
           draw every class of the legend
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs
from PIL import Image, ImageChops

BAD = b"sand \xff\xfe grof"
REPAIRED = "sand \ufffd\ufffd grof".encode()


class TestInvalidUtf8Labels(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_utf8_")
        cls.use_temp_region()
        cls.runModule("g.region", n=2000, s=0, e=3000, w=0, b=-40, t=0, res=100,
                      res3=100, tbres=2)
        cls.runModule("r3.mapcalc", overwrite=True,
                      expression="utf8_layers = if(depth() <= 5, 1, if(depth() <= 12, 2, 3))")
        gs.run_command("r3.sbrt.convert", input="utf8_layers", output="utf8_model",
                       overwrite=True, quiet=True)
        env = gs.gisenv()
        cls.cats = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"],
                                "sbrt", "utf8_model", "cats")

    def set_label(self, label):
        """Label 1 written as another mapset's SBRT could hold it: byte for byte."""
        with open(self.cats, "wb") as f:
            f.write(b"1:" + label + b"\n2:clay\n3:peat\n")

    @classmethod
    def tearDownClass(cls):
        gs.run_command("r3.sbrt.manage", remove="utf8_model", flags="f", quiet=True)
        cls.runModule("g.remove", flags="f", type="raster_3d", name="utf8_layers")
        cls.del_temp_region()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def figures(self, command):
        """The PNGs that `command` (with {name} and {png}) draws with the bad
        label and with the repaired one."""
        images = []
        for kind, label in (("bad", BAD), ("good", REPAIRED)):
            self.set_label(label)
            png = os.path.join(self.tmp, f"{kind}_{command[0]}.png")
            words = [w.format(name="utf8_model", png=png) for w in command]
            run = subprocess.run(words, capture_output=True, timeout=120)
            self.assertEqual(run.returncode, 0, run.stderr[-2000:])
            images.append(Image.open(png).convert("RGB"))
        return images

    def assert_same(self, bad, good):
        self.assertEqual(bad.size, good.size)
        self.assertIsNone(ImageChops.difference(bad, good).getbbox(),
                          "the figure with the bad byte differs from the repaired one")

    def test_render_png_draws_the_whole_legend(self):
        bad, good = self.figures(["r3.sbrt.render", "input={name}", "png={png}",
                                  "size=320,240", "backend=cpu", "--overwrite", "--quiet"])
        self.assert_same(bad, good)
        # the legend below the bad label is there: the "clay" and "peat"
        # swatches in the image's own colours are drawn somewhere on the right
        self.assertGreater(bad.size[0], 320)

    def test_profile_png_draws_every_part(self):
        bad, good = self.figures(["r3.sbrt.profile", "input={name}",
                                  "coordinates=100,1000,2900,1000", "png={png}",
                                  "--overwrite", "--quiet"])
        self.assert_same(bad, good)

    def test_labels_are_printed_repaired(self):
        self.set_label(BAD)
        listing = subprocess.run(["r3.sbrt.convert", "-p", "sbrt=utf8_model"],
                                 capture_output=True, timeout=60).stdout
        self.assertIn(REPAIRED, listing)
        self.assertNotIn(b"\xff", listing)


if __name__ == "__main__":
    test()
