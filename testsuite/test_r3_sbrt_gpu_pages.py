"""
MODULE:    testsuite/test_r3_sbrt_gpu_pages.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.render on the GPU (EGL; llvmpipe here) of a model read
           block by block: its blocks brought up to the GPU as the rays
           reach them, within gpu_memory=. The maps equal those of the model
           uploaded whole (layout=textures) cell for cell and the PNGs byte
           for byte; an atlas of a few blocks still gives the CPU's maps;
           gpu_memory= out of range is a clear error; a pyramid over half of
           gpu_memory pages the columns, or where the model holds no tops
           is a clear error
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import re
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import image_region
from stacks_fixture import sbrt_dir

VIEW = dict(azimuth=150, elevation=35)


class TestGpuPages(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        # 384 x 448 cells of 8 levels in blocks of 64: 42 blocks, 2.5 MB of
        # intervals decoded; gpu_memory=4 holds the pyramid (1.8 MB), the
        # columns' tops (0.7 MB) and a few blocks
        cls.runModule("g.region", n=384, s=0, e=448, w=0, b=0, t=8, res=1, res3=1, tbres=1)
        cls.runModule(
            "r3.mapcalc",
            expression="paged3d = if(depth() > 5 + (row() / 9 + col() / 13) % 4, null(), "
            "1 + (depth() + row() / 17 + col() / 23) % 4)")
        cls.runModule("r3.sbrt.convert", input="paged3d", output="paged")
        cls.tmp = tempfile.mkdtemp(prefix="gpu_pages")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        shutil.rmtree(sbrt_dir("paged"), ignore_errors=True)
        shutil.rmtree(cls.tmp, ignore_errors=True)
        cls.runModule("g.remove", flags="f", type="raster_3d", name="paged3d")
        cls.runModule("g.remove", flags="f", type="raster", pattern="gp_*")

    def render(self, name, *words):
        """r3.sbrt.render of the model into maps gp_<name>* and a PNG; the
        finished process (verbose)."""
        run = subprocess.run(
            ["r3.sbrt.render", "--o", "--v", "input=paged", "size=120,90",
             "output=gp_" + name, "material=gp_%s_m" % name, "depth=gp_%s_d" % name,
             "png=" + os.path.join(self.tmp, name + ".png"),
             "azimuth=%d" % VIEW["azimuth"], "elevation=%d" % VIEW["elevation"]] + list(words),
            capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stderr)
        return run

    def differing_cells(self, a, b):
        self.runModule(
            "r.mapcalc", overwrite=True,
            expression=f"gp_diff = if(isnull({a}) != isnull({b}) || "
            f"(!isnull({a}) && {a} != {b}), 1, 0)")
        return int(float(gs.parse_command("r.univar", map="gp_diff", flags="g")["sum"]))

    def png(self, name):
        with open(os.path.join(self.tmp, name + ".png"), "rb") as f:
            return f.read()

    def test_blocks_brought_up_give_the_whole_models_maps(self):
        image_region(self, 120, 90)
        paged = self.render("paged", "backend=egl")
        self.assertIn("GPU blocks (gpu_memory=)", paged.stderr)
        self.assertRegex(paged.stderr, r"SBRT <paged> paged: its 42 blocks")
        self.render("whole", "backend=egl", "layout=textures")
        self.assertEqual(self.differing_cells("gp_paged_m", "gp_whole_m"), 0)
        self.assertRastersNoDifference("gp_paged_d", "gp_whole_d", precision=0)
        self.assertRastersNoDifference("gp_paged", "gp_whole", precision=0)
        self.assertEqual(self.png("paged"), self.png("whole"))

    def test_an_atlas_of_a_few_blocks_gives_the_cpus_maps(self):
        image_region(self, 120, 90)
        small = self.render("small", "backend=egl", "gpu_memory=4")
        found = re.search(r"GPU blocks \(gpu_memory=\): (\d+) up, ([\d.]+) of ([\d.]+) MB",
                          small.stderr)
        self.assertIsNotNone(found, small.stderr)
        self.assertLess(int(found.group(1)), 42)
        self.assertLessEqual(float(found.group(3)), 2.0)  # 4 MB less pyramid and tops
        # the rays that met a block with no room on the GPU: on the CPU
        self.assertIn("or met a block not on the GPU", small.stderr)
        self.render("cpu", "backend=cpu")
        self.assertLessEqual(self.differing_cells("gp_small_m", "gp_cpu_m"), 120 * 90 // 1000)
        self.assertRastersNoDifference("gp_small_d", "gp_cpu_d", precision=0.01)

    def test_a_damaged_block_met_on_the_gpu_is_a_clear_error(self):
        """A block decoded as the GPU's rays want it (on the module's
        threads) and found damaged: an error naming it, no map."""
        shutil.copytree(sbrt_dir("paged"), sbrt_dir("damaged"))
        self.addCleanup(shutil.rmtree, sbrt_dir("damaged"), True)
        stacks = os.path.join(sbrt_dir("damaged"), "stacks")
        with open(stacks, "r+b") as f:
            data = bytearray(f.read())
            for k in range(2000, 2400):  # in the first blocks' bytes
                data[k] ^= 0x5A
            f.seek(0)
            f.write(data)
        # the whole image: its rays reach the damaged block
        self.assertRegex(self.refused("damaged", "gp_damaged", size="120,90"),
                         r"stacks block \d+: checksum mismatch")

    def refused(self, sbrt, output, *words, size="40,30"):
        """r3.sbrt.render of `sbrt` into `output` on EGL, which must fail
        leaving no map; its error output on one line."""
        run = subprocess.run(
            ["r3.sbrt.render", "input=" + sbrt, "output=" + output, "size=" + size,
             "backend=egl"] + list(words), capture_output=True, text=True, timeout=120)
        self.assertNotEqual(run.returncode, 0)
        self.assertRasterDoesNotExist(output + ".red")
        self.assertRasterDoesNotExist(output)
        return " ".join(run.stderr.split())

    def test_gpu_memory_out_of_range_is_a_clear_error(self):
        self.assertIn("gpu_memory", self.refused("paged", "gp_bad", "gpu_memory=0"))

    def test_a_pyramid_over_half_of_gpu_memory_pages_the_columns(self):
        """gpu_memory=3: the pyramid (1.8 MB) takes more than half; the
        columns' tops and ranges go up in pages, the pyramid from level 1
        on, and the maps are the CPU's."""
        image_region(self, 120, 90)
        tight = self.render("tight", "backend=egl", "gpu_memory=3")
        self.assertIn("the columns' top intervals and ranges in pages beside the blocks', "
                      "the empty-space pyramid from level 1 on", " ".join(tight.stderr.split()))
        self.render("tight_cpu", "backend=cpu")
        self.assertLessEqual(self.differing_cells("gp_tight_m", "gp_tight_cpu_m"),
                             120 * 90 // 1000)
        self.assertRastersNoDifference("gp_tight_d", "gp_tight_cpu_d", precision=0.01)

    def test_a_pyramid_over_half_without_column_tops_is_a_clear_error(self):
        """A model stored without its tops member (as older files are):
        its columns cannot be paged, so a pyramid over half of gpu_memory
        is an error that says so."""
        shutil.copytree(sbrt_dir("paged"), sbrt_dir("untopped"))
        self.addCleanup(shutil.rmtree, sbrt_dir("untopped"), True)
        os.remove(os.path.join(sbrt_dir("untopped"), "tops"))
        self.assertIn("empty-space pyramid takes 2 MB on the GPU, more than half of "
                      "gpu_memory (3 MB), and the model holds no column tops",
                      self.refused("untopped", "gp_untopped", "gpu_memory=3"))

if __name__ == "__main__":
    test()
