"""
MODULE:    testsuite/test_r3_sbrt_raster_channels.py (r3.sbrt addon)
PURPOSE:   Property channels from 3D raster maps (issue 29, item 2):
           r3.sbrt.convert input= properties= keeps per-voxel maps beside
           the classes; -r property= expands each back equal voxel for
           voxel to the map inside the columns' solid spans (nulls kept,
           caves too); -g lists type, unit and title; a value float32 would
           round, a missing map, a map named twice and the class map itself
           are refused by name
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import Raster3dCompare, error_of
from shell_output import shell_records

# r3.mapcalc's row(), col() and depth() count from 1, depth 1 at the bottom
GROUND = "(5 + (row() * 3 + col() * 2) % 7)"
CAVE = "(depth() == 4 && (row() + col()) % 3 == 0)"


class TestRasterChannels(TestCase, Raster3dCompare):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=9, s=0, e=11, w=0, t=12, b=0, res=1, res3=1,
                      tbres=1)
        expressions = {
            # classes up to a ground level, a cave inside some columns
            "lith": f"if(depth() > {GROUND} || {CAVE}, null(), "
                    "1 + (depth() / 4 + col() / 3) % 4)",
            # an integer percentage with nulls, set in caves and above ground
            "prob": "float(if((row() + col() + depth()) % 11 == 0, null(), "
                    "(row() * 13 + col() * 7 + depth() * 3) % 101))",
            # floats with fractions, negative ones too
            "poro": "float(((row() * 31 + col() * 17 + depth() * 5) % 97) / 8.0 - 3.0)",
            # doubles that float32 rounds
            "fine": "0.1 * depth()",
        }
        for name, expression in expressions.items():
            cls.runModule("r3.mapcalc", expression=f"{name} = {expression}",
                          overwrite=True)
        cls.runModule("r3.support", map="prob", unit="%", title="P(sand)")
        cls.runModule("r3.sbrt.convert", input="lith", properties="prob,poro",
                      output="lith_channels")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def expanded_equals(self, channel):
        """-r property= gives the map inside the spans, null above them."""
        self.runModule("r3.mapcalc", overwrite=True,
                       expression=f"expected_{channel} = if(depth() <= {GROUND}, "
                                  f"{channel}, null())")
        self.assertModule("r3.sbrt.convert", flags="r", sbrt="lith_channels",
                          property=channel, output="back_" + channel)
        n, differing = self.count_differences("expected_" + channel, "back_" + channel)
        self.assertEqual(n, 9 * 11 * 12)
        self.assertEqual(differing, 0, channel)
        self.assertEqual(gs.raster3d_info("back_" + channel)["datatype"], '"FCELL"')

    def test_each_map_expands_back_to_its_values(self):
        self.expanded_equals("prob")
        self.expanded_equals("poro")
        # the nulls inside the spans stay null (not a fill value)
        stats = gs.parse_command("r3.univar", map="back_prob", flags="g")
        self.assertLessEqual(float(stats["max"]), 100)
        self.assertGreaterEqual(float(stats["min"]), 0)

    def test_g_lists_the_channels_with_type_unit_and_title(self):
        channels = {c["channel"]: c for c in shell_records(
            gs.read_command("r3.sbrt.convert", flags="g", sbrt="lith_channels"), "channel")}
        self.assertEqual(sorted(channels), ["poro", "prob"])
        # 0..100 and a fill of 101 for the nulls: one byte a voxel
        self.assertEqual(channels["prob"]["type"], "u8")
        self.assertEqual(channels["prob"]["unit"], "%")
        self.assertEqual(channels["prob"]["long_name"], "P(sand)")
        self.assertEqual(float(channels["prob"]["max"]), 100)
        self.assertEqual(channels["poro"]["type"], "f32")
        spans = 0
        for row in range(1, 10):
            for col in range(1, 12):
                spans += 5 + (row * 3 + col * 2) % 7
        self.assertEqual(int(channels["poro"]["voxels"]), spans)

    def test_property_view_of_a_raster_channel(self):
        """A top view's value= is prob at each column's topmost voxel."""
        self.assertModule("r3.sbrt.render", input="lith_channels", view="top",
                          output="top_prob", property="prob", value="top_prob_value",
                          flags="n")
        self.runModule("r3.to.rast", input="prob", output="prob_slice")
        # the topmost solid voxel of a column is at depth GROUND (1-based)
        stats = []
        for row in range(1, 10):
            for col in range(1, 12):
                stats.append((row, col, 5 + (row * 3 + col * 2) % 7))
        region = gs.region()
        for row, col, ground in stats[::7]:
            x = region["w"] + col - 0.5
            y = region["n"] - row + 0.5
            got = gs.read_command("r.what", map="top_prob_value",
                                  coordinates=f"{x},{y}").strip().split("|")[-1]
            want = gs.read_command("r.what", map=f"prob_slice_{ground:05d}",
                                   coordinates=f"{x},{y}").strip().split("|")[-1]
            self.assertEqual(got == "*", want == "*", (row, col))
            if want != "*":
                self.assertEqual(float(got), float(want), (row, col))

    def test_bad_properties_are_refused_by_name(self):
        code, err = error_of("r3.sbrt.convert", "input=lith", "properties=fine",
                             "output=bad")
        self.assertNotEqual(code, 0)
        self.assertIn("<fine>", err)
        self.assertIn("not exact", err)
        code, err = error_of("r3.sbrt.convert", "input=lith", "properties=nothing",
                             "output=bad")
        self.assertNotEqual(code, 0)
        self.assertIn("<nothing> not found", err)
        code, err = error_of("r3.sbrt.convert", "input=lith", "properties=prob,prob",
                             "output=bad")
        self.assertIn("'prob' twice", err)
        code, err = error_of("r3.sbrt.convert", "input=lith", "properties=lith",
                             "output=bad")
        self.assertIn("class map itself", err)
        self.assertNotIn("bad", gs.read_command("r3.sbrt.convert", flags="l"))


if __name__ == "__main__":
    test()
