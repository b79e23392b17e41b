"""
MODULE:    testsuite/test_r3_sbrt_labels.py (r3.sbrt addon)
PURPOSE:   Labels and colours that travel with the model (issue 31, item 1):
           r3.sbrt.support (rules, colour tables, another map, presets),
           -p sorted with real colours, a GeoTOP-like file named and
           coloured on import, material= maps with labels and colours,
           bad input
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import error_of, run_in_new_location

HERE = os.path.dirname(os.path.abspath(__file__))
GEOTOP_LIKE = os.path.join(HERE, "..", "benchmarks", "geotop_like")


def parse_p(name):
    """As classes(), tolerant of the padded r:g:b columns."""
    out = gs.read_command("r3.sbrt.convert", flags="p", sbrt=name)
    rows, order, inside = {}, [], False
    for line in out.splitlines():
        if line.startswith("Materials:"):
            inside = True
            continue
        if inside and not line.startswith("  "):
            break
        if inside:
            head, _, rest = line.strip().partition("  ")
            rest = rest.strip()
            rgb_text = rest[:11]
            label = rest[11:].strip()
            rgb = tuple(int(c) for c in rgb_text.split(":"))
            rows[int(head)] = (rgb, label)
            order.append(int(head))
    return rows, order


class TestSbrtLabels(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.lab_region()
        # 1000 at the bottom: met first, so -p must sort
        cls.runModule("r3.mapcalc", expression="lab_v = if(depth() < 4, 1000, "
                      "if(depth() < 7, 3, 5))", overwrite=True)
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_labels_")
        subprocess.run(["make", "-s", "-C", GEOTOP_LIKE, "build/geotop_like"],
                       check=True)
        cls.geotop = os.path.join(cls.tmp, "geotop_like.nc")
        subprocess.run([os.path.join(GEOTOP_LIKE, "build", "geotop_like"), "write",
                        cls.geotop, "24", "18", "60"], check=True)

    @classmethod
    def lab_region(cls):
        cls.runModule("g.region", n=100, s=0, e=100, w=0, b=0, t=10, res=10,
                      res3=10, tbres=1)

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        cls.runModule("g.remove", flags="f", type="raster_3d", name="lab_v")
        cls.runModule("g.remove", flags="f", type="raster", name="lab_2d")
        cls.runModule("g.remove", flags="f", type="raster", pattern="gt_*")

    def fresh(self, name="lab"):
        self.lab_region()
        # output= has no gisprompt "new": --overwrite only through g.parser
        gs.run_command("r3.sbrt.convert", input="lab_v", output=name,
                       overwrite=True, quiet=True)
        return name

    def write(self, name, text):
        path = os.path.join(self.tmp, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_p_sorted_by_id_with_real_colours(self):
        name = self.fresh()
        rows, order = parse_p(name)
        self.assertEqual(order, [3, 5, 1000])
        colours = [rows[i][0] for i in order]
        self.assertNotIn((128, 128, 128), colours)
        self.assertEqual(len(set(colours)), 3)

    def test_colour_rules_and_labels(self):
        name = self.fresh()
        rules = self.write("rules.txt", "3 red\n5 0:0:255\n1000 green\n")
        labels = self.write("labels.txt", "# lithology\n3:clay\n5:sand\n")
        self.assertModule("r3.sbrt.support", sbrt=name, rules=rules, labels=labels)
        rows, _ = parse_p(name)
        self.assertEqual(rows[3], ((255, 0, 0), "clay"))
        self.assertEqual(rows[5], ((0, 0, 255), "sand"))
        self.assertEqual(rows[1000][0], (0, 255, 0))
        # -r: back to the palette, labels kept
        self.assertModule("r3.sbrt.support", sbrt=name, flags="r")
        rows, _ = parse_p(name)
        self.assertNotEqual(rows[3][0], (255, 0, 0))
        self.assertEqual(rows[3][1], "clay")

    def test_colour_table(self):
        name = self.fresh()
        self.assertModule("r3.sbrt.support", sbrt=name, color="grey")
        rows, _ = parse_p(name)
        # grey over the class range 3..1000: black at 3, white at 1000
        self.assertEqual(rows[3][0], (0, 0, 0))
        self.assertEqual(rows[1000][0], (255, 255, 255))

    def test_another_maps_table(self):
        name = self.fresh()
        self.runModule("r.mapcalc", expression="lab_2d = row()", overwrite=True)
        self.runModule("r.colors", map="lab_2d",
                       rules=self.write("c2d.txt", "3 10:20:30\n5 40:50:60\n1000 70:80:90\n"))
        self.runModule("r.category", map="lab_2d", separator=":",
                       rules=self.write("l2d.txt", "3:peat\n5:gravel\n"))
        self.assertModule("r3.sbrt.support", sbrt=name, raster="lab_2d")
        rows, _ = parse_p(name)
        self.assertEqual(rows[3], ((10, 20, 30), "peat"))
        self.assertEqual(rows[5], ((40, 50, 60), "gravel"))
        self.assertEqual(rows[1000][0], (70, 80, 90))

    def test_preset(self):
        name = self.fresh()
        self.assertModule("r3.sbrt.support", sbrt=name, preset="geotop_lithoclass")
        rows, _ = parse_p(name)
        self.assertEqual(rows[3][0], (194, 207, 92))
        self.assertTrue(rows[5][1].startswith("fine sand"))
        self.assertEqual(rows[1000][1], "")  # not a lithoclass

    def test_geotop_like_file_imports_with_names_and_colours(self):
        # -o: the file is in EPSG:7415, the test location is XY
        err = gs.read_command("r3.sbrt.convert", flags="o", file=self.geotop,
                              variable="lithok", output="gt", overwrite=True,
                              stderr=subprocess.STDOUT)
        self.assertIn("preset geotop_lithoclass", " ".join(err.split()))
        rows, order = parse_p("gt")
        self.assertEqual(order, [0, 1, 2, 3, 5, 6, 7, 8, 9])
        self.assertEqual(rows[2], ((0, 146, 0), "clay (klei)"))
        self.assertTrue(rows[1][1].startswith("organic, peat"))
        gs.run_command("r3.sbrt.convert", flags="o", file=self.geotop,
                       variable="lithok", output="gt_none", preset="none",
                       overwrite=True, quiet=True)
        rows, _ = parse_p("gt_none")
        self.assertEqual(rows[2][1], "")

    def test_geotop_crs_is_read_from_its_coordinates(self):
        """GeoTOP names its CRS only by epsg = "7415" (RD New + NAP height)
        on x, y and z: compared by its horizontal part, EPSG:28992."""
        convert = ["r3.sbrt.convert", f"file={self.geotop}", "variable=lithok",
                   "output=gt_crs", "--overwrite"]
        code, message = error_of(*convert)
        self.assertNotEqual(code, 0)
        self.assertIn("EPSG:7415", message)
        self.assertIn("horizontally Amersfoort / RD New (EPSG:28992)", message)
        self.assertIn("-o", message)
        code, message = run_in_new_location("EPSG:28992", convert)
        self.assertEqual(code, 0, message)
        code, message = run_in_new_location("EPSG:32631", convert)
        self.assertNotEqual(code, 0)
        self.assertIn("WGS 84 / UTM zone 31N", message)

    def test_material_map_carries_labels_and_colours(self):
        gs.run_command("r3.sbrt.convert", flags="o", file=self.geotop,
                       variable="lithok", output="gt", overwrite=True, quiet=True)
        gs.run_command("r3.sbrt.convert", flags="s", sbrt="gt", quiet=True)
        self.assertModule("r3.sbrt.render", input="gt", output="gt_rgb",
                          material="gt_mat", view="top", backend="cpu",
                          overwrite=True)
        # every class, not only those the top view shows
        cats = gs.read_command("r.category", map="gt_mat", separator=":", cats="0-9")
        self.assertIn("2:clay (klei)", cats)
        colours = gs.read_command("r.colors.out", map="gt_mat")
        self.assertIn("2 0:146:0", colours)
        # frames: each frame's class map the same
        self.assertModule("r3.sbrt.render", input="gt", output="gt_fr",
                          material="gt_fm", frames=2, size=[40, 30],
                          backend="cpu", overwrite=True)
        for frame in ("gt_fm_0001", "gt_fm_0002"):
            cats = gs.read_command("r.category", map=frame, separator=":", cats="0-9")
            self.assertIn("9:shells (schelpen)", cats)
            self.assertIn("9 95:95:255", gs.read_command("r.colors.out", map=frame))

    def test_bad_input_is_refused_clearly(self):
        name = self.fresh()
        module = self.assertModuleFail_stderr(name, preset="geotop_nope")
        self.assertIn("geotop_lithoclass,geotop_strat", module)
        bad = self.write("bad.txt", "3 red\n5 blu\n")
        module = self.assertModuleFail_stderr(name, rules=bad)
        self.assertIn("line 2", module)
        bad_labels = self.write("bad_labels.txt", "3:clay\nsand\n")
        module = self.assertModuleFail_stderr(name, labels=bad_labels)
        self.assertIn("line 2", module)
        module = self.assertModuleFail_stderr(name, raster_3d="no_such_map")
        self.assertIn("not found", module)

    def assertModuleFail_stderr(self, name, **options):
        """Runs r3.sbrt.support past pygrass's own checks of the options
        (an unknown preset must be refused by the module itself)."""
        args = ["r3.sbrt.support", f"sbrt={name}"]
        args += [f"{key}={value}" for key, value in options.items()]
        run = subprocess.run(args, capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0, run.stderr)
        return " ".join(run.stderr.split())


if __name__ == "__main__":
    test()
