"""
MODULE:    testsuite/test_r3_sbrt_convert.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.convert against GRASS's own tools: voxel round trips,
           Table 1 figures, horizons, rules, legends and bad input
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import Raster3dCompare

HERE = os.path.dirname(os.path.abspath(__file__))
MAKE_GEOMODEL = os.path.join(HERE, "..", "tools", "make_geomodel.sh")


def sbrt_dir(name):
    env = gs.gisenv()
    return os.path.join(
        env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], "sbrt", name
    )


class TestConvertSyntheticModel(TestCase, Raster3dCompare):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        subprocess.run([MAKE_GEOMODEL, "T", "geo"], check=True)

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def test_round_trip_is_identical(self):
        self.assertModule("r3.sbrt.convert", input="geo", output="geo_sbrt")
        self.assertModule(
            "r3.sbrt.convert", flags="r", input="geo_sbrt", output="geo_back"
        )
        n, differing = self.count_differences("geo", "geo_back")
        self.assertEqual(n, 40 * 50 * 64)
        self.assertEqual(differing, 0)

    def test_labels_and_colours_are_kept(self):
        self.assertModule("r3.sbrt.convert", input="geo", output="geo_l")
        self.assertModule("r3.sbrt.convert", flags="r", input="geo_l", output="geo_lb")
        with open(os.path.join(sbrt_dir("geo_l"), "cats")) as f:
            self.assertIn("14:Gravel aquifer", f.read())
        colors = gs.read_command("r3.colors.out", map="geo_lb")
        self.assertIn("14 30:110:230", colors)
        info = gs.read_command("r3.info", map="geo_lb")
        self.assertIn("Number of Categories: 16", info)

    def test_shell_figures_match_the_grid(self):
        self.assertModule("r3.sbrt.convert", input="geo", output="geo_g")
        figures = gs.parse_command("r3.sbrt.convert", input="geo_g", flags="g")
        self.assertEqual(int(figures["voxels"]), 40 * 50 * 64)
        self.assertEqual(int(figures["voxel_bytes"]), 4 * 40 * 50 * 64)
        self.assertEqual(int(figures["materials"]), 16)
        self.assertGreater(float(figures["compression"]), 50)
        self.assertLessEqual(int(figures["max_stack"]), 64)

    def test_list_names_the_sbrt_with_mapset(self):
        self.assertModule("r3.sbrt.convert", input="geo", output="geo_list")
        listing = gs.read_command("r3.sbrt.convert", flags="l").split()
        self.assertIn("geo_list@" + gs.gisenv()["MAPSET"], listing)

    def test_existing_output_needs_overwrite(self):
        self.assertModule("r3.sbrt.convert", input="geo", output="geo_o")
        self.assertModuleFail("r3.sbrt.convert", input="geo", output="geo_o")
        gs.run_command("r3.sbrt.convert", input="geo", output="geo_o", overwrite=True)


class TestConvertExactFigures(TestCase, Raster3dCompare):
    """A model whose stacks are known: single-voxel layers and a cave."""

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=20, s=0, e=10, w=0, b=0, t=6, res=1, res3=1, tbres=1)
        # bottom up: 1 1 cave 7 2 2; the top voxel is air where col() > 5
        cls.runModule(
            "r3.mapcalc",
            expression="known = if(depth() <= 2, 1, if(depth() == 3, null(), "
            "if(depth() == 4, 7, if(depth() == 6 && col() > 5, null(), 2))))",
        )

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def test_intervals_and_stacks(self):
        self.assertModule("r3.sbrt.convert", input="known", output="known_s")
        f = gs.parse_command("r3.sbrt.convert", input="known_s", flags="g")
        self.assertEqual(int(f["intervals"]), 200 * 4)
        self.assertEqual(int(f["solid_intervals"]), 200 * 3)
        self.assertEqual(int(f["max_stack"]), 4)
        self.assertAlmostEqual(float(f["mean_stack"]), 4.0)
        # in memory: 4-byte intervals (voxel tops), a count byte per cell
        # and 8 bytes per group of 16 cells (13 groups), 8 per material
        self.assertEqual(int(f["sbrt_bytes"]), 208 + 13 * 8 + 800 * 4 + 4 * 8)
        self.assertEqual(float(f["memory_bytes_per_interval"]), 4.0)
        self.assertAlmostEqual(float(f["memory_index_bytes_per_cell"]), 312 / 200)
        # on disk: format 2, the stacks file's own size, far below memory
        stacks = os.path.join(sbrt_dir("known_s"), "stacks")
        self.assertEqual(f["format"], "2.1")
        self.assertEqual(int(f["file_bytes"]), os.path.getsize(stacks))
        self.assertLess(int(f["file_bytes"]), int(f["sbrt_bytes"]) / 4)
        self.assertAlmostEqual(
            float(f["file_bytes_per_interval"]), os.path.getsize(stacks) / 800, places=3
        )

    def test_round_trip_with_cave(self):
        self.assertModule("r3.sbrt.convert", input="known", output="known_r")
        self.assertModule("r3.sbrt.convert", flags="r", input="known_r", output="known_b")
        self.assertEqual(self.count_differences("known", "known_b"), (1200, 0))


class TestConvertHorizons(TestCase, Raster3dCompare):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=10, s=0, e=20, w=0, b=0, t=100, res=1, res3=1, tbres=1)
        cls.runModule("r.mapcalc", expression="h1 = 90")
        cls.runModule("r.mapcalc", expression="h2 = 55.5 + col()")
        cls.runModule("r.mapcalc", expression="h3 = if(row() == 3, null(), 70)")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def test_crossing_and_absent_units_match_independent_voxels(self):
        self.assertModule(
            "r3.sbrt.convert",
            horizons="h1,h2,h3",
            materials=[1, 2, 3],
            bottom=5,
            output="hz",
        )
        self.assertModule("r3.sbrt.convert", flags="r", input="hz", output="hz_vox")
        # independent: unit tops clipped from the top down, voxel centres z()
        self.runModule(
            "r3.mapcalc",
            expression="hz_ref = eval(e2 = min(55.5 + col(), 90), "
            "e3 = if(row() == 3, null(), min(70, e2)), "
            "if(z() < 5 || z() > 90, null(), "
            "if(if(isnull(e3), 0, z() < e3), 3, if(z() < e2, 2, 1))))",
        )
        self.assertEqual(self.count_differences("hz_ref", "hz_vox"), (20000, 0))

    def test_horizons_need_one_material_each(self):
        self.assertModuleFail(
            "r3.sbrt.convert", horizons="h1,h2", materials=[1], output="hz_bad"
        )


class TestConvertRulesAndErrors(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=5, s=0, e=5, w=0, b=0, t=4, res=1, res3=1, tbres=1)
        cls.runModule("r3.mapcalc", expression="frac = depth() * 0.5")
        cls.runModule("r3.mapcalc", expression="allnull = null()")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def test_non_integer_values_need_rules(self):
        result = gs.Popen(
            ["r3.sbrt.convert", "input=frac", "output=frac_s"],
            stderr=subprocess.PIPE,
        ).communicate()[1].decode()
        self.assertIn("0.5", result)
        self.assertIn("rules=", result)
        self.assertModuleFail("r3.sbrt.convert", input="frac", output="frac_s")

    def test_rules_classify_ranges(self):
        rules = "0:1.2:1:shallow\n1.2:*:2:deep\n"
        self.assertModule(
            "r3.sbrt.convert", input="frac", output="frac_r", rules="-", stdin_=rules
        )
        f = gs.parse_command("r3.sbrt.convert", input="frac_r", flags="g")
        self.assertEqual(int(f["intervals"]), 25 * 2)
        with open(os.path.join(sbrt_dir("frac_r"), "cats")) as cats:
            self.assertIn("2:deep", cats.read())

    def test_missing_and_all_null_maps_fail(self):
        self.assertModuleFail("r3.sbrt.convert", input="nosuchmap", output="x")
        self.assertModuleFail("r3.sbrt.convert", input="allnull", output="x")
        self.assertModuleFail("r3.sbrt.convert", flags="r", input="nosuch", output="x")

    def test_infinite_values_and_too_many_classes_fail(self):
        self.runModule("r3.mapcalc", expression="infs = if(depth() == 2, exp(1000.0), 1.0)",
                       overwrite=True)
        run = subprocess.run(["r3.sbrt.convert", "input=infs", "output=infs"],
                             capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("inf", run.stderr)
        self.assertFalse(os.path.exists(sbrt_dir("infs")))
        # 70,000 distinct values: more classes than an SBRT holds
        self.runModule("g.region", n=100, s=0, e=70, w=0, b=0, t=10, res=1, res3=1, tbres=1)
        self.runModule("r3.mapcalc", overwrite=True,
                       expression="many = row() * 1000 + col() * 10 + depth()")
        run = subprocess.run(["r3.sbrt.convert", "input=many", "output=many"],
                             capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("65535", run.stderr)
        self.assertIn("rules=", run.stderr)
        self.assertFalse(os.path.exists(sbrt_dir("many")))
        self.runModule("g.region", n=5, s=0, e=5, w=0, b=0, t=4, res=1, res3=1, tbres=1)

    def test_corrupt_sbrt_fails_clearly(self):
        self.runModule("r3.mapcalc", expression="ones = 1", overwrite=True)
        self.assertModule("r3.sbrt.convert", input="ones", output="broken")
        stacks = os.path.join(sbrt_dir("broken"), "stacks")
        with open(stacks, "r+b") as f:
            f.seek(200)
            byte = f.read(1)
            f.seek(200)
            f.write(bytes([byte[0] ^ 0x10]))
        proc = gs.Popen(
            ["r3.sbrt.convert", "input=broken", "-p"], stderr=subprocess.PIPE
        )
        message = proc.communicate()[1].decode()
        self.assertNotEqual(proc.returncode, 0)
        self.assertIn("damaged", message)


def run_convert(*args, timeout=60):
    """rc and stderr (one line) of r3.sbrt.convert; past `timeout` seconds
    the test fails (a hang)."""
    run = subprocess.run(["r3.sbrt.convert", *args], capture_output=True,
                         text=True, timeout=timeout)
    return run.returncode, " ".join(run.stderr.split())


class TestRegionOfAnSbrt(TestCase, Raster3dCompare):
    """Issue 28, item 8: the manual's g.region recipe left the 3D rows and
    columns at 1 and -r then silently wrote a 1 x 1 x depths map."""

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=30, s=10, e=25, w=5, b=-4, t=8, res=2,
                      res3=2, tbres=0.5)
        cls.runModule("r3.mapcalc",
                      expression="strata = if(depth() < row() + 3, 1, "
                      "if(depth() < 18, 2, null()))")
        cls.runModule("r3.sbrt.convert", input="strata", output="strata_s")
        # a region of another grid, as the manual's old recipe left it
        cls.runModule("g.region", n=1, s=0, e=1, w=0, b=0, t=1, res=1, res3=1,
                      tbres=1)

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def setUp(self):
        self.runModule("g.region", n=1, s=0, e=1, w=0, b=0, t=1, res=1, res3=1,
                       tbres=1)

    def test_s_sets_the_2d_and_3d_region_in_one_step(self):
        self.assertModule("r3.sbrt.convert", flags="s", sbrt="strata_s")
        frame = gs.parse_command("r3.sbrt.convert", flags="g", sbrt="strata_s")
        region = gs.region(region3d=True)
        for key in ("north", "south", "east", "west", "top", "bottom"):
            self.assertAlmostEqual(region[key[0]], float(frame[key]), places=9)
        self.assertEqual((region["rows"], region["cols"]), (10, 10))
        self.assertEqual((region["rows3"], region["cols3"], region["depths"]), (10, 10, 24))
        self.assertAlmostEqual(region["nsres3"], 2)
        self.assertAlmostEqual(region["tbres"], 0.5)
        # -r in it: the map as it was, voxel for voxel
        self.assertModule("r3.sbrt.convert", flags="r", sbrt="strata_s",
                          output="strata_back")
        self.assertEqual(self.count_differences("strata", "strata_back"), (2400, 0))

    def test_r_with_s_expands_in_the_sbrts_grid(self):
        self.assertModule("r3.sbrt.convert", flags="rs", sbrt="strata_s",
                          output="strata_rs")
        info = gs.parse_command("r3.info", flags="g", map="strata_rs")
        self.assertEqual((int(info["rows"]), int(info["cols"]), int(info["depths"])),
                         (10, 10, 24))

    def test_r_in_another_grid_warns_with_the_way_to_set_it(self):
        code, message = run_convert("-r", "sbrt=strata_s", "output=strata_other",
                                    "--overwrite")
        self.assertEqual(code, 0, message)
        self.assertIn("is not the grid of SBRT <strata_s> (10 x 10 x 24", message)
        self.assertIn("(1 rows x 1 columns x 1 depths", message)
        self.assertIn("r3.sbrt.convert -s sbrt=strata_s", message)
        # in the SBRT's own grid: no warning
        self.runModule("r3.sbrt.convert", flags="s", sbrt="strata_s")
        code, message = run_convert("-r", "sbrt=strata_s", "output=strata_same",
                                    "--overwrite")
        self.assertEqual(code, 0, message)
        self.assertNotIn("WARNING", message)

    def test_s_without_an_sbrt_is_refused(self):
        self.assertModuleFail("r3.sbrt.convert", flags="s")


class TestOutputNames(TestCase):
    """Issue 28, item 9: a 300-character output name failed after the work
    with "AtomicDirectory: ... File name too long"."""

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=5, s=0, e=5, w=0, b=0, t=4, res=1, res3=1, tbres=1)
        cls.runModule("r3.mapcalc", expression="little = 1")
        cls.runModule("r3.sbrt.convert", input="little", output="little_s")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def test_long_sbrt_name_is_refused_before_the_work(self):
        code, message = run_convert("input=little", "output=" + "s" * 300)
        self.assertNotEqual(code, 0)
        self.assertIn("The SBRT name in output= has 300 characters; at most 239 are "
                      "allowed", message)
        self.assertNotIn("AtomicDirectory", message)
        self.assertModule("r3.sbrt.convert", input="little", output="s" * 239)

    def test_long_3d_raster_name_is_refused(self):
        code, message = run_convert("-r", "sbrt=little_s", "output=" + "r" * 300)
        self.assertNotEqual(code, 0)
        self.assertIn("The 3D raster map name in output= has 300 characters; at most "
                      "255", message)

if __name__ == "__main__":
    test()
