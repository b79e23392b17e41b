"""
MODULE:    testsuite/test_r3_sbrt_memory.py (r3.sbrt addon)
PURPOSE:   memory= of r3.sbrt.surface and r3.sbrt.volume: the model read
           band by band (rows of blocks, sized by the 2.1 block summaries;
           a row of blocks a band for 2.0 stacks) gives the maps and the
           volumes of a single band, cell for cell and digit for digit; a
           budget below one row of blocks is a clear error that leaves no
           output behind
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

from stacks_fixture import as_format_20, copy_sbrt, sbrt_dir

MAPS = ("top", "base", "thickness", "layers")


def surface(sbrt, suffix, memory):
    """r3.sbrt.surface of classes 1 and 2 of `sbrt` into maps named
    <map>_<suffix>, with memory=; the finished process."""
    outputs = {m: "%s_%s" % (m, suffix) for m in MAPS}
    return subprocess.run(
        ["r3.sbrt.surface", "--o", "--v", "input=" + sbrt, "classes=1,2",
         "memory=%d" % memory] + ["%s=%s" % kv for kv in outputs.items()],
        capture_output=True, text=True, timeout=120)


def volume(sbrt, memory, output):
    """r3.sbrt.volume of every class of `sbrt` as csv into `output`."""
    return subprocess.run(
        ["r3.sbrt.volume", "--v", "input=" + sbrt, "format=csv", "memory=%d" % memory,
         "output=" + output], capture_output=True, text=True, timeout=120)


class TestInBands(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        # 200 x 1500 cells, 6 levels: a row of 64-cell blocks holds 96,000
        # cells and about 192,000 intervals, 1.3 MB decoded: more than
        # memory=1, and two rows of blocks more than memory=2
        cls.runModule("g.region", n=200, s=0, e=1500, w=0, b=0, t=6, res=1, res3=1, tbres=1)
        cls.runModule(
            "r3.mapcalc",
            expression="two = if(depth() > 3 + (row() + col() / 7) % 3, null(), "
            "if(depth() <= 1 + (col() / 11 + row() / 13) % 3, 1, 2))")
        cls.runModule("r3.sbrt.convert", input="two", output="bands21")
        copy_sbrt("bands21", "bands20")
        as_format_20("bands20")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        for name in ("bands21", "bands20"):
            shutil.rmtree(sbrt_dir(name), ignore_errors=True)
        cls.runModule("g.remove", flags="f", type="raster", pattern="*_m*")
        cls.runModule("g.remove", flags="f", type="raster_3d", name="two")

    def assert_same_maps(self, a, b):
        for m in MAPS:
            self.assertRastersNoDifference("%s_%s" % (m, a), "%s_%s" % (m, b), precision=0)

    def bands_read(self, run):
        self.assertEqual(run.returncode, 0, run.stderr)
        found = re.search(r"Read in (\d+) band\(s\)", run.stderr)
        self.assertIsNotNone(found, run.stderr)
        return int(found.group(1))

    def test_bands_give_the_maps_of_one_band(self):
        # 2.1: as many rows of blocks a band as memory= holds (one at 2 MB,
        # all at 1000); 2.0: a row of blocks a band, 200 rows in 4
        self.assertGreater(self.bands_read(surface("bands21", "bands21_m2", 2)), 1)
        self.assertEqual(self.bands_read(surface("bands21", "bands21_m1000", 1000)), 1)
        self.assertEqual(self.bands_read(surface("bands20", "bands20_m2", 2)), 4)
        self.assertEqual(self.bands_read(surface("bands20", "bands20_m1000", 1000)), 4)
        for sbrt in ("bands21", "bands20"):
            self.assert_same_maps(sbrt + "_m2", sbrt + "_m1000")
        self.assert_same_maps("bands21_m2", "bands20_m2")
        # the maps hold the classes: a column is 3 to 5 levels of 1 and 2
        self.assertRasterMinMax("thickness_bands21_m2", refmin=3, refmax=5)

    def test_volumes_of_bands_are_those_of_one_band(self):
        with tempfile.TemporaryDirectory() as tmp:
            tables = {}
            for sbrt, memory in (("bands21", 2), ("bands21", 1000), ("bands20", 2)):
                path = os.path.join(tmp, "%s_%d.csv" % (sbrt, memory))
                self.bands_read(volume(sbrt, memory, path))
                with open(path) as f:
                    tables[sbrt, memory] = f.read()
            self.assertEqual(tables["bands21", 2], tables["bands21", 1000])
            self.assertEqual(tables["bands21", 2], tables["bands20", 2])
            # both classes, over the whole grid: cells of class 1 and 2
            lines = tables["bands21", 2].splitlines()
            self.assertEqual(lines[0], "classes,labels,volume,cells")
            self.assertEqual([line.split(",")[0] for line in lines[1:]], ["1", "2"])
            self.assertEqual(sum(int(line.split(",")[2]) for line in lines[1:]),
                             int(gs.read_command("r3.univar", flags="g", map="two")
                                 .split("n=")[1].split()[0]))

    def test_budget_below_a_row_of_blocks_is_a_clear_error(self):
        run = surface("bands21", "m1", 1)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("more than memory=1: give memory= at least that",
                      " ".join(run.stderr.split()))
        self.assertNotIn("Traceback", run.stderr)
        for m in MAPS:
            self.assertFalse(subprocess.run(
                ["g.findfile", "element=cell", "file=%s_m1" % m], capture_output=True,
                timeout=30).returncode == 0, m + " left behind")
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "volumes.csv")
            run = volume("bands21", 1, path)
            self.assertNotEqual(run.returncode, 0)
            self.assertIn("more than memory=1", " ".join(run.stderr.split()))
            self.assertFalse(os.path.exists(path), "volumes.csv left behind")


if __name__ == "__main__":
    test()
