"""
MODULE:    testsuite/test_r3_sbrt_surface.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.surface and r3.sbrt.volume against GRASS's own route:
           the set as 0/1 voxels (r3.mapcalc), one 2D map per level
           (r3.to.rast), r.series across them; volumes against r3.univar
           counts times the voxel volume and v.to.rast zones; bad input
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import json
import os

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

# UTM-size coordinates; 30 x 20 cells of 10 m, 40 levels of 2 m
REGION = dict(n=5800200, s=5800000, w=450000, e=450300, b=-40, t=40, res=10, res3=10, tbres=2)
TBRES = 2.0
VOXEL = 10.0 * 10.0 * 2.0

# classes 1..4 in sloping bands (several layers of a class in a column),
# air above a sloping surface (overhang-free but uneven), caves (null
# voxels inside), a hole of empty columns in the north-west corner, and
# class 4 filling some columns to the frame's top
MODEL = (
    "geo = if(row() <= 3 && col() <= 3, null(),"
    " if(col() >= 27 && row() >= 17, 4,"
    " if(z() > 10 + col() * 0.8 - row() * 0.5, null(),"
    " if((row() + col() + depth()) % 11 == 0 && depth() > 5, null(),"
    " int((z() + 40 + row() + col() * 2) / 6) % 4 + 1))))"
)

CATS = """# 4 categories
Test geology

0.00 0.00 0.00 0.00
1:Sand
2:Clay
3:Peat
4:Gravel
"""


# two areas (cat 1: a rectangle with an isle, cat 2: a triangle), edges
# off the cell centres (450005 + 10 k, 5800005 + 10 k), so that every
# centre is plainly inside or outside; v.in.ascii's standard format
AREAS = """B 5
 450012.3 5800013.7
 450151.1 5800013.7
 450151.1 5800121.9
 450012.3 5800121.9
 450012.3 5800013.7
B 5
 450051.2 5800051.2
 450089.1 5800051.2
 450089.1 5800089.1
 450051.2 5800089.1
 450051.2 5800051.2
C 1 1
 450030.1 5800030.1
 1 1
B 4
 450160.7 5800010.3
 450291.9 5800060.1
 450190.2 5800190.6
 450160.7 5800010.3
C 1 1
 450200.1 5800070.1
 1 2
"""


def grid3_dir(name):
    env = gs.gisenv()
    return os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], "grid3", name)


class TestSurfaceAgainstGrassRoute(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        # a rerun in the same mapset (run directly, not by gunittest.main)
        os.environ["GRASS_OVERWRITE"] = "1"
        gs.run_command("g.region", flags="3", **REGION)
        gs.mapcalc3d(MODEL)
        with open(os.path.join(grid3_dir("geo"), "cats"), "w") as f:
            f.write(CATS)
        gs.run_command("r3.sbrt.convert", input="geo", output="geo_sbrt", quiet=True)
        # the GRASS route, for the set {1 (Sand), 3 (Peat)}
        gs.mapcalc3d("inset = if(isnull(geo), 0, if(geo == 1 || geo == 3, 1, 0))")
        gs.mapcalc3d("solid = if(isnull(geo), 0, 1)")
        gs.mapcalc3d("start = if(inset == 1 && (depth() == 1 ||| inset[0,0,-1] == 0), 1, 0)")
        gs.mapcalc3d("ztop = if(inset == 1, z() + %g, null())" % (TBRES / 2))
        gs.mapcalc3d("zbase = if(inset == 1, z() - %g, null())" % (TBRES / 2))
        gs.mapcalc3d("zsolid = if(solid == 1, z() + %g, null())" % (TBRES / 2))
        for name in ("inset", "start", "ztop", "zbase", "zsolid"):
            gs.run_command("r3.to.rast", input=name, output="sl_" + name, quiet=True)
        cls.series("inset", "sum", "count")
        cls.series("start", "sum", "starts")
        cls.series("ztop", "maximum", "ref_top")
        cls.series("zbase", "minimum", "ref_base")
        cls.series("zsolid", "maximum", "surface")
        gs.mapcalc("ref_thickness = if(count > 0, count * %g, null())" % TBRES)
        gs.mapcalc("ref_layers = if(count > 0, starts, null())")
        gs.mapcalc("ref_depth = if(count > 0, surface - ref_top, null())")
        # probabilities in % (p1, p2) beside the classes, null in the air
        # and in some voxels inside the columns; a channel in another unit
        air = ("(!(col() >= 27 && row() >= 17) && "
               "z() > 10 + col() * 0.8 - row() * 0.5)")
        gs.mapcalc3d(f"p1 = float(if({air} || (row() * col() + depth()) % 13 == 0, null(), "
                     "(row() * 7 + col() * 3 + depth()) % 41))")
        gs.mapcalc3d(f"p2 = float(if({air}, null(), (row() + col() * 5 + depth() * 2) % 37))")
        gs.mapcalc3d("tmp = float(depth())")
        for name in ("p1", "p2"):
            gs.run_command("r3.support", map=name, unit="%")
        gs.run_command("r3.sbrt.convert", input="geo", properties="p1,p2,tmp",
                       output="geo_prob", quiet=True)

    @classmethod
    def series(cls, name, method, output):
        maps = gs.list_strings("raster", pattern="sl_%s_*" % name)
        gs.run_command("r.series", input=maps, method=method, output=output, quiet=True)

    @classmethod
    def tearDownClass(cls):
        os.environ.pop("GRASS_OVERWRITE", None)
        cls.del_temp_region()

    def test_every_map_equals_the_grass_route(self):
        self.assertModule(
            "r3.sbrt.surface", input="geo_sbrt", classes="Sand,3", top="s_top",
            base="s_base", thickness="s_thick", layers="s_layers", depth="s_depth",
        )
        self.assertRastersNoDifference("s_thick", "ref_thickness", precision=0)
        self.assertRastersNoDifference("s_top", "ref_top", precision=0)
        self.assertRastersNoDifference("s_base", "ref_base", precision=0)
        self.assertRastersNoDifference("s_layers", "ref_layers", precision=0)
        self.assertRastersNoDifference("s_depth", "ref_depth", precision=0)
        # the set is absent in places (nulls there) and layered elsewhere
        stats = gs.parse_command("r.univar", map="s_layers", flags="g")
        self.assertGreater(int(stats["null_cells"]), 9)
        self.assertGreaterEqual(int(stats["max"]), 2)

    def test_expected_thickness_equals_the_grass_route(self):
        """probability= expected_thickness=: the sum over each column's
        voxels of (p1 + p2) / 100 times the voxel height, voxels with a
        null in either adding nothing, caves counted, air not; as r3.mapcalc,
        r3.to.rast and r.series sum compute it voxel by voxel; null in the
        empty columns."""
        gs.mapcalc3d("pe = if(isnull(p1) || isnull(p2), 0, (p1 + p2) / 100.0 * %g)" % TBRES)
        gs.run_command("r3.to.rast", input="pe", output="sl_pe", quiet=True)
        # the span ends at the column's highest solid top (surface): a cave
        # right below the air is no part of it
        levels = sorted(gs.list_strings("raster", pattern="sl_pe_*"))
        terms = " + ".join("if(%g < surface, %s, 0)" % (REGION["b"] + (k + 0.5) * TBRES,
                                                         name.split("@")[0])
                           for k, name in enumerate(levels))
        gs.mapcalc("ref_expected = if(isnull(surface), null(), %s)" % terms)
        self.assertModule("r3.sbrt.surface", input="geo_prob", probability="p1 + p2",
                          expected_thickness="e_thick")
        self.assertRastersNoDifference("e_thick", "ref_expected", precision=1e-9)
        stats = gs.parse_command("r.univar", map="e_thick", flags="g")
        self.assertEqual(int(stats["null_cells"]), 9)  # the hole
        self.assertGreater(float(stats["min"]), 0)
        info = gs.parse_command("r.info", map="e_thick", flags="g")
        self.assertIn("probability p1 + p2", gs.read_command("r.info", map="e_thick"))
        self.assertEqual(info["datatype"], "DCELL")
        # with classes= the other maps come in the same run
        self.assertModule("r3.sbrt.surface", input="geo_prob", classes="Sand,3",
                          thickness="e_set", probability="p1", expected_thickness="e_p1")
        self.assertRastersNoDifference("e_set", "ref_thickness", precision=0)
        # refused by name: another unit, an unknown channel, a model
        # without channels, expected_thickness= without probability=, and
        # thickness= without classes=
        for options, message in (
                (dict(input="geo_prob", probability="p1+tmp"), "'tmp' is in"),
                (dict(input="geo_prob", probability="p9"), "no channel 'p9'; the SBRT has: p1, p2, tmp"),
                (dict(input="geo_sbrt", probability="p1"), "has no property channels"),
                (dict(input="geo_prob", probability="p1+p1"), "named twice")):
            run = gs.Popen(["r3.sbrt.surface", "expected_thickness=bad"] +
                           ["%s=%s" % kv for kv in options.items()],
                           stderr=gs.PIPE, text=True)
            err = " ".join(run.communicate()[1].split())
            self.assertNotEqual(run.returncode, 0)
            self.assertIn(message, err)
        self.assertModuleFail("r3.sbrt.surface", input="geo_prob", expected_thickness="bad")
        self.assertModuleFail("r3.sbrt.surface", input="geo_prob", thickness="bad")

    def test_expected_volume_is_the_expected_thickness_times_the_area(self):
        """probability= in r3.sbrt.volume: per zone, the sum of the expected
        thickness map (r3.sbrt.surface, itself against the GRASS route)
        times the cell area, and the cells where it is above 0; beside the
        set's own volume, in json, csv and plain."""
        self.assertModule("r3.sbrt.surface", input="geo_prob", probability="p1+p2",
                          expected_thickness="v_thick")
        stats = gs.parse_command("r.univar", map="v_thick", flags="g")
        gs.mapcalc("v_positive = if(v_thick > 0, 1, null())")
        positive = int(gs.parse_command("r.univar", map="v_positive", flags="g")["n"])
        report = json.loads(gs.read_command("r3.sbrt.volume", input="geo_prob",
                                            classes="Sand,3", probability="p1+p2",
                                            format="json"))
        self.assertEqual(report["probability"], "p1+p2")
        self.assertEqual(len(report["expected"]), 1)
        self.assertAlmostEqual(report["expected"][0]["volume"],
                               float(stats["sum"]) * 100.0, delta=1e-6)
        self.assertEqual(report["expected"][0]["cells"], positive)
        self.assertEqual(len(report["volumes"]), 1)  # the set's own row stays
        rows = gs.read_command("r3.sbrt.volume", input="geo_prob", classes="Sand,3",
                               probability="p1+p2", format="csv").splitlines()
        self.assertEqual(rows[0], "classes,labels,volume,cells,probability")
        self.assertTrue(rows[2].startswith(",,"), rows)
        self.assertTrue(rows[2].endswith(",p1+p2"), rows)
        self.assertAlmostEqual(float(rows[2].split(",")[2]), float(stats["sum"]) * 100.0,
                               delta=1e-6)
        plain = gs.read_command("r3.sbrt.volume", input="geo_prob", probability="p1+p2")
        self.assertIn("expected: p1+p2", plain)
        self.assertModuleFail("r3.sbrt.volume", input="geo_sbrt", probability="p1")
        self.assertModuleFail("r3.sbrt.volume", input="geo_prob", probability="tmp")

    def test_metadata_history_and_types(self):
        self.assertModule("r3.sbrt.surface", input="geo_sbrt", classes="sand,peat",
                          thickness="m_thick", layers="m_layers")
        info = gs.parse_command("r.info", map="m_thick", flags="g")
        self.assertEqual(info["datatype"], "DCELL")
        self.assertEqual(gs.parse_command("r.info", map="m_layers", flags="g")["datatype"],
                         "CELL")
        history = gs.read_command("r.info", map="m_thick", flags="h")
        self.assertIn("r3.sbrt.surface", history)
        self.assertIn("geo_sbrt", history)
        title = gs.parse_command("r.info", map="m_thick", flags="e")["title"]
        self.assertIn("1 (Sand), 3 (Peat)", title)
        # thickness colours start at 0
        rules = gs.read_command("r.colors.out", map="m_thick")
        self.assertTrue(rules.splitlines()[0].startswith("0 "), rules)

    def test_finer_region_samples_cell_centres(self):
        self.assertModule("r3.sbrt.surface", input="geo_sbrt", classes="1,3",
                          thickness="f_thick_model")
        # the class's temporary region, finer and shifted so that no centre
        # lies on a model cell's edge (where GRASS's resampling rounds), then
        # as it was
        gs.run_command("g.region", n=5800214, s=5799998, w=449998, e=450304, res=6)
        try:
            self.assertModule("r3.sbrt.surface", input="geo_sbrt", classes="1,3",
                              thickness="f_thick")
            # nearest neighbour at the centres is what r.resample does
            gs.run_command("r.resample", input="ref_thickness", output="f_ref")
            self.assertRastersNoDifference("f_thick", "f_ref", precision=0)
        finally:
            gs.run_command("g.region", flags="3", **REGION)

    def test_unknown_class_or_label_is_named(self):
        self.assertModuleFail("r3.sbrt.surface", input="geo_sbrt", classes="1,Basalt",
                              thickness="bad1")
        run = gs.start_command("r3.sbrt.surface", input="geo_sbrt", classes="7",
                               thickness="bad2", stderr=gs.PIPE)
        _, err = run.communicate()
        err = " ".join(gs.decode(err).split())  # GRASS wraps messages at 80 columns
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("'7'", err)
        self.assertIn("1 (Sand), 2 (Clay), 3 (Peat), 4 (Gravel)", err)
        self.assertFalse(gs.find_file("bad2", element="cell")["name"])

    def volumes(self, **options):
        text = gs.read_command("r3.sbrt.volume", input="geo_sbrt", format="json", **options)
        return json.loads(text)["volumes"]

    def test_volume_of_every_class_equals_the_voxel_count(self):
        rows = self.volumes()
        self.assertEqual([r["classes"] for r in rows], [[1], [2], [3], [4]])
        self.assertEqual(rows[0]["labels"], ["Sand"])
        for row in rows:
            k = row["classes"][0]
            gs.mapcalc3d("one = if(geo == %d, 1, null())" % k)
            voxels = int(gs.parse_command("r3.univar", map="one", flags="g")["n"])
            self.assertEqual(row["volume"], voxels * VOXEL, row)
        # a set: its cells are those where the GRASS route has a thickness
        (row,) = self.volumes(classes="1,peat")
        cells = int(gs.parse_command("r.univar", map="ref_thickness", flags="g")["n"])
        self.assertEqual(row["cells"], cells)
        voxels = int(gs.parse_command("r3.univar", map="inset", flags="g")["sum"])
        self.assertEqual(row["volume"], voxels * VOXEL)

    def test_volume_per_area_equals_rasterised_zones(self):
        gs.write_command("v.in.ascii", input="-", output="areas", format="standard",
                         flags="n", stdin=AREAS, quiet=True)
        gs.run_command("v.to.rast", input="areas", output="zones", use="cat", quiet=True)
        table = gs.read_command("r.univar", map="ref_thickness", zones="zones",
                                flags="t", separator="comma")
        lines = table.strip().splitlines()
        header = lines[0].split(",")
        reference = {}
        for line in lines[1:]:
            fields = dict(zip(header, line.split(",")))
            reference[int(fields["zone"])] = (
                float(fields["sum"]) * 100.0,
                int(fields["non_null_cells"]),
            )
        rows = self.volumes(classes="1,3", areas="areas")
        self.assertEqual([r["area"] for r in rows], [1, 2])
        self.assertEqual(len(reference), 2)
        for row in rows:
            volume, cells = reference[row["area"]]
            self.assertEqual(row["cells"], cells, row)
            self.assertAlmostEqual(row["volume"], volume, places=6, msg=row)
        # the same as CSV in a file
        out = os.path.join(gs.tempdir(), "volumes.csv")
        self.assertModule("r3.sbrt.volume", input="geo_sbrt", classes="1,3", areas="areas",
                          format="csv", output=out)
        with open(out) as f:
            csv_lines = f.read().splitlines()
        self.assertEqual(csv_lines[0], "area,classes,labels,volume,cells")
        self.assertTrue(csv_lines[1].startswith("1,1 3,Sand;Peat,"), csv_lines)

    def test_volume_bad_input(self):
        gs.write_command("v.in.ascii", input="-", output="points_only", separator="comma",
                         stdin="450015,5800015\n450025,5800025\n", quiet=True)
        run = gs.start_command("r3.sbrt.volume", input="geo_sbrt", areas="points_only",
                               stderr=gs.PIPE, stdout=gs.PIPE)
        _, err = run.communicate()
        self.assertNotEqual(run.returncode, 0)
        # GRASS wraps messages at 80 columns, where depends on the mapset's name
        self.assertIn("has no areas", " ".join(gs.decode(err).split()))
        # as pygrass calls it (layer=1 given), where the label is what is wrong
        run = gs.start_command("r3.sbrt.volume", input="geo_sbrt", classes="Basalt",
                               layer="1", stderr=gs.PIPE, stdout=gs.PIPE)
        _, err = run.communicate()
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("'Basalt'", " ".join(gs.decode(err).split()))
        self.assertModuleFail("r3.sbrt.volume", input="geo_sbrt", areas="no_such_map")

    def test_an_output_is_required(self):
        self.assertModuleFail("r3.sbrt.surface", input="geo_sbrt", classes="1")


if __name__ == "__main__":
    test()
