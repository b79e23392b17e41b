"""
MODULE:    testsuite/test_r3_sbrt_level_of_detail.py (r3.sbrt addon)
PURPOSE:   The coarse level of detail (issue 49, item 4): r3.sbrt.convert
           stores stacks_lod beside the stacks of a model of 512 x 512
           cells or more; r3.sbrt.render detail=coarse draws it (a frame
           that differs from the exact one in a bounded share of pixels,
           said so in a message and in the maps' history); detail=exact
           (the default) draws what it drew before, byte for byte; a small
           model has no coarse level; a damaged one is a clear error for
           detail=coarse only; r3.sbrt.manage copy carries it
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

LIMIT = 60  # seconds for any one process (a loaded CI machine)
# a moving frame of the viewer's size; the camera as the viewer sends it
VIEW = ["size=200,150", "azimuth=225", "elevation=35", "zexag=100", "-n"]


def sbrt_dir(name):
    env = gs.gisenv()
    return os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], "sbrt", name)


def run(*args):
    return subprocess.run(list(args), capture_output=True, text=True, timeout=LIMIT)


class TestLevelOfDetail(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.work = tempfile.mkdtemp(prefix="lod_")
        # 512 x 512 cells, 4 depths: the smallest model with a coarse level
        # (factor 2); classes in patches of tens of cells, a ground level
        # in steps, so that the coarse frame differs at the patches' edges
        for name, res in (("lod_big", 10), ("lod_small", 20)):
            cls.runModule("g.region", n=5120, s=0, e=5120, w=0, t=8, b=0, res=res,
                          res3=res, tbres=2)
            cls.runModule("r3.mapcalc", overwrite=True, expression=(
                f"{name} = if(depth() > 1 + (row() * {res} / 400 + col() * {res} / 700) % 4, "
                f"null(), 1 + (row() * {res} / 230 + col() * {res} / 310 + depth()) % 5)"))
            subprocess.run(["r3.sbrt.convert", f"input={name}", f"output={name}",
                            "--overwrite", "--quiet"], check=True, timeout=LIMIT)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)
        for name in ("lod_big", "lod_small", "lod_copy", "lod_old"):
            if os.path.isdir(sbrt_dir(name)):
                cls.runModule("r3.sbrt.manage", flags="f", remove=name)
        cls.runModule("g.remove", flags="f", type="raster_3d", name="lod_big,lod_small")
        cls.runModule("g.remove", flags="f", type="raster", pattern="lod_img*")
        cls.del_temp_region()

    def render(self, name, png, *words):
        """r3.sbrt.render of SBRT `name` into `png` (in the work folder):
        (its bytes, its standard error)."""
        path = os.path.join(self.work, png)
        result = run("r3.sbrt.render", f"input={name}", f"png={path}", *VIEW, *words,
                     "--overwrite")
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(path, "rb") as f:
            return f.read(), result.stderr

    def pixels(self, png):
        """(width, height, RGB bytes) of a PNG of the work folder."""
        from test_r3_sbrt_render_server_options import read_png
        return read_png(os.path.join(self.work, png))

    def differing_share(self, a, b):
        wa, ha, pa = self.pixels(a)
        wb, hb, pb = self.pixels(b)
        self.assertEqual((wa, ha), (wb, hb))
        differ = sum(1 for i in range(0, len(pa), 3) if pa[i:i + 3] != pb[i:i + 3])
        return differ / (wa * ha)

    def test_convert_stores_a_coarse_level_of_large_models_only(self):
        self.assertTrue(os.path.isfile(os.path.join(sbrt_dir("lod_big"), "stacks_lod")))
        self.assertFalse(os.path.exists(os.path.join(sbrt_dir("lod_small"), "stacks_lod")))

    def test_coarse_frame_differs_boundedly_and_says_so(self):
        exact, _ = self.render("lod_big", "exact.png")
        coarse, message = self.render("lod_big", "coarse.png", "detail=coarse")
        self.assertIn("1 cell in 2", message)
        self.assertIn("not exact", message)
        share = self.differing_share("exact.png", "coarse.png")
        self.assertGreater(share, 0.0, "the coarse frame is the exact one")
        self.assertLess(share, 0.25, "the coarse frame differs in %.1f %% of pixels"
                        % (100 * share))
        self.assertNotEqual(exact, coarse)

    def test_the_png_of_a_coarse_frame_says_so(self):
        # with the legend panel (right of the 200-pixel view): the coarse
        # frame's has a caption line more, in dark text
        words = [w for w in VIEW if w != "-n"]

        def dark_in_panel(png, *more):
            path = os.path.join(self.work, png)
            result = run("r3.sbrt.render", "input=lod_big", f"png={path}", *words, *more,
                         "--overwrite")
            self.assertEqual(result.returncode, 0, result.stderr)
            width, height, rgb = self.pixels(png)
            self.assertGreater(width, 200)
            return sum(1 for y in range(height) for x in range(200, width)
                       if sum(rgb[3 * (y * width + x):3 * (y * width + x) + 3]) < 200)

        self.assertGreater(dark_in_panel("caption_coarse.png", "detail=coarse"),
                           dark_in_panel("caption_exact.png") + 100)

    def test_exact_output_is_what_it_was(self):
        """detail=exact is the default, and the member changes nothing of
        it: an SBRT without stacks_lod (as before) draws the same bytes."""
        default, _ = self.render("lod_big", "default.png")
        exact, message = self.render("lod_big", "exact2.png", "detail=exact")
        self.assertEqual(default, exact)
        self.assertNotIn("coarse", message)
        old = sbrt_dir("lod_old")
        shutil.rmtree(old, ignore_errors=True)
        shutil.copytree(sbrt_dir("lod_big"), old)
        os.remove(os.path.join(old, "stacks_lod"))
        before, _ = self.render("lod_old", "before.png")
        self.assertEqual(before, exact)
        # an SBRT of before: detail=coarse draws it exactly, with a message
        coarse, message = self.render("lod_old", "old_coarse.png", "detail=coarse")
        self.assertEqual(coarse, exact)
        self.assertIn("no coarse level", message)

    def test_small_model_renders_exactly_with_a_message(self):
        exact, _ = self.render("lod_small", "small_exact.png")
        coarse, message = self.render("lod_small", "small_coarse.png", "detail=coarse")
        self.assertEqual(coarse, exact)
        self.assertIn("no coarse level", message)

    def test_map_history_names_a_coarse_frame(self):
        for detail in ("exact", "coarse"):
            result = run("r3.sbrt.render", "input=lod_big", f"output=lod_img_{detail}",
                         *VIEW, f"detail={detail}", "--overwrite", "--quiet")
            self.assertEqual(result.returncode, 0, result.stderr)
        history = gs.read_command("r.info", flags="h", map="lod_img_coarse.red")
        self.assertIn("coarse level of detail", history)
        history = gs.read_command("r.info", flags="h", map="lod_img_exact.red")
        self.assertNotIn("coarse", history)

    def test_a_damaged_coarse_level_is_an_error_for_coarse_frames_only(self):
        # r3.sbrt.manage copy carries the member
        shutil.rmtree(sbrt_dir("lod_copy"), ignore_errors=True)
        self.runModule("r3.sbrt.manage", copy=("lod_big", "lod_copy"), overwrite=True)
        member = os.path.join(sbrt_dir("lod_copy"), "stacks_lod")
        self.assertTrue(os.path.isfile(member))
        with open(member, "r+b") as f:
            f.seek(os.path.getsize(member) // 2)
            byte = f.read(1)
            f.seek(-1, os.SEEK_CUR)
            f.write(bytes([byte[0] ^ 0x5A]))
        png = os.path.join(self.work, "damaged.png")
        result = run("r3.sbrt.render", "input=lod_copy", f"png={png}", *VIEW,
                     "detail=coarse", "--overwrite")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("stacks_lod", result.stderr)
        self.assertIn("detail=exact", result.stderr)  # what to do
        exact, _ = self.render("lod_big", "exact3.png")
        copy, _ = self.render("lod_copy", "copy_exact.png")
        self.assertEqual(copy, exact)


if __name__ == "__main__":
    test()
