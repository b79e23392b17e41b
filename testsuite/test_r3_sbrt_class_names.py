"""
MODULE:    testsuite/test_r3_sbrt_class_names.py (r3.sbrt addon)
PURPOSE:   Classes named as geologists name them (issue 51, item 3): by
           TNO's code or a short name from the survey preset (classes=g,
           classes=gravel, classes=zf, hide=BX), a label with commas as it
           is or without its commas, on a GeoTOP file as TNO ships it too;
           an unknown name lists the accepted names sorted by id
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import error_of

HERE = os.path.dirname(os.path.abspath(__file__))
GEOTOP_LIKE = os.path.join(HERE, "..", "benchmarks", "geotop_like")
LOAM = "clayey sand, sandy clay, loam (kleiig zand, zandige klei en leem)"
TIMEOUT = 120


def volume_rows(*words):
    """r3.sbrt.volume format=csv: {classes: (labels, volume, cells)}."""
    out = subprocess.run(["r3.sbrt.volume", "format=csv"] + list(words),
                         capture_output=True, text=True, check=True,
                         timeout=TIMEOUT).stdout
    import csv
    rows = list(csv.DictReader(out.splitlines()))
    return {r["classes"]: (r["labels"], float(r["volume"]), int(r["cells"])) for r in rows}


class TestClassNames(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.model_region()
        # lithoclasses met unsorted (from the bottom 6, 2, 8, 3, 5)
        cls.runModule("r3.mapcalc", overwrite=True, expression=(
            "cn_litho = if(depth() < 3, 6, if(depth() < 5, 2, if(depth() < 7, 8, "
            "if(depth() < 9, 3, 5))))"))
        # strat units: BX (3100) on top of NIHO (1090) on EC (2010)
        cls.runModule("r3.mapcalc", overwrite=True, expression=(
            "cn_strat = if(depth() < 4, 2010, if(depth() < 7, 1090, 3100))"))
        for name, preset in (("cn_litho", "geotop_lithoclass"), ("cn_strat", "geotop_strat")):
            subprocess.run(["r3.sbrt.convert", f"input={name}", f"output={name}",
                            "--overwrite", "--quiet"], check=True, timeout=TIMEOUT)
            subprocess.run(["r3.sbrt.support", f"sbrt={name}", f"preset={preset}",
                            "--quiet"], check=True, timeout=TIMEOUT)

    @classmethod
    def model_region(cls):
        cls.runModule("g.region", n=100, s=0, e=100, w=0, b=0, t=10, res=10,
                      res3=10, tbres=1)

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        cls.runModule("g.remove", flags="f", type="raster_3d", name="cn_litho,cn_strat")
        cls.runModule("g.remove", flags="f", type="raster", pattern="cn_*")

    def setUp(self):
        self.model_region()

    def test_classes_by_tno_code_and_short_name(self):
        by_id = volume_rows("input=cn_litho", "classes=8")
        self.assertEqual(list(by_id), ["8"])
        self.assertEqual(by_id["8"][0], "gravel (grind)")
        self.assertGreater(by_id["8"][1], 0)
        for name in ("gravel", "g", "G", "Gravel (Grind)"):
            self.assertEqual(volume_rows("input=cn_litho", f"classes={name}"), by_id, name)
        zf = volume_rows("input=cn_litho", "classes=zf")
        self.assertEqual(zf, volume_rows("input=cn_litho", "classes=5"))
        self.assertEqual(zf["5"][0], "fine sand (zand fijn)")
        self.assertEqual(list(volume_rows("input=cn_litho", "classes=zf,k,fine sand")),
                         ["2 5"])

    def test_surface_classes_by_code(self):
        for name, classes in (("cn_code", "zm,g"), ("cn_ids", "6,8")):
            subprocess.run(["r3.sbrt.surface", "input=cn_litho", f"classes={classes}",
                            f"thickness={name}", "--overwrite", "--quiet"], check=True,
                           timeout=TIMEOUT)
        self.assertRastersNoDifference("cn_code", "cn_ids", precision=0)
        self.assertRasterMinMax("cn_code", 4, 4)

    def test_hide_by_strat_code(self):
        self.assertModule("r3.sbrt.render", input="cn_strat", output="cn_bx", view="top",
                          material="cn_bx_m", hide="BX", backend="cpu", overwrite=True)
        self.assertModule("r3.sbrt.render", input="cn_strat", output="cn_all", view="top",
                          material="cn_all_m", backend="cpu", overwrite=True)
        self.assertRasterMinMax("cn_all_m", 3100, 3100)
        # BX hidden: the top view is the unit below it, NIHO
        self.assertRasterMinMax("cn_bx_m", 1090, 1090)
        self.assertModule("r3.sbrt.render", input="cn_strat", output="cn_bx2", view="top",
                          material="cn_bx2_m", hide="bx,NIHO", backend="cpu", overwrite=True)
        self.assertRasterMinMax("cn_bx2_m", 2010, 2010)

    def test_label_with_commas(self):
        kz = volume_rows("input=cn_litho", "classes=kz")
        self.assertEqual(kz["3"][0], LOAM)
        # as it is: GRASS parts it at the commas, the parts are joined again
        self.assertEqual(volume_rows("input=cn_litho", f"classes={LOAM}"), kz)
        self.assertEqual(list(volume_rows("input=cn_litho", f"classes=g,{LOAM},zf")),
                         ["3 5 8"])
        # or without its commas
        self.assertEqual(volume_rows("input=cn_litho", "classes=" + LOAM.replace(",", "")),
                         kz)
        # hide= and opacity= take it too
        self.assertModule("r3.sbrt.render", input="cn_litho", output="cn_l", view="top",
                          material="cn_l_m", hide=f"zf,{LOAM}", backend="cpu",
                          overwrite=True)
        self.assertRasterMinMax("cn_l_m", 8, 8)
        self.assertModule("r3.sbrt.render", input="cn_litho", output="cn_o", view="top",
                          opacity=f"{LOAM}:0.5,zf:0", backend="cpu", overwrite=True)

    def test_unknown_name_lists_the_names_sorted_by_id(self):
        listed = ("2 (clay (klei); also k, clay), 3 (" + LOAM + "; also kz, loam, clayey "
                  "sand, sandy clay), 5 (fine sand (zand fijn); also zf, fine sand), 6 "
                  "(medium sand (zand midden); also zm, medium sand), 8 (gravel (grind); "
                  "also g, gravel)")
        for module, option in (("r3.sbrt.volume", "classes"), ("r3.sbrt.surface", "classes"),
                               ("r3.sbrt.render", "hide")):
            extra = ["thickness=cn_x"] if module == "r3.sbrt.surface" else (
                ["output=cn_x", "view=top", "backend=cpu"] if module == "r3.sbrt.render"
                else [])
            rc, err = error_of(module, "input=cn_litho", f"{option}=g,granite", *extra)
            self.assertNotEqual(rc, 0, module)
            self.assertIn(f"{option}: no class of SBRT <cn_litho> is named 'granite' (an id, "
                          "code, short name or label", err)
            self.assertIn("without its commas", err)
            self.assertIn(listed, err)
        rc, err = error_of("r3.sbrt.render", "input=cn_strat", "output=cn_x", "view=top",
                           "backend=cpu", "hide=BXX")
        self.assertIn("1090 (NIHO Formatie van Nieuwkoop, Hollandveen Laagpakket; also NIHO), "
                      "2010 (EC Formatie van Echteld; also EC), 3100 (BX Formatie van Boxtel; "
                      "also BX)",
                      err)

    def test_relabelled_class_keeps_no_preset_names(self):
        rules = os.path.join(tempfile.mkdtemp(prefix="sbrt_cn_"), "labels.txt")
        with open(rules, "w") as f:
            f.write("8:my gravel\n")
        subprocess.run(["r3.sbrt.convert", "input=cn_litho", "output=cn_own", "--overwrite",
                        "--quiet"], check=True, timeout=TIMEOUT)
        try:
            subprocess.run(["r3.sbrt.support", "sbrt=cn_own", "preset=geotop_lithoclass",
                            "--quiet"], check=True, timeout=TIMEOUT)
            subprocess.run(["r3.sbrt.support", "sbrt=cn_own", f"labels={rules}", "--quiet"],
                           check=True, timeout=TIMEOUT)
            self.assertEqual(list(volume_rows("input=cn_own", "classes=my gravel,zf")),
                             ["5 8"])
            rc, err = error_of("r3.sbrt.volume", "input=cn_own", "classes=g")
            self.assertNotEqual(rc, 0)
            self.assertIn("8 (my gravel)", err)
        finally:
            gs.run_command("g.remove", flags="f", type="raster_3d", name="cn_own",
                           quiet=True)


class TestGeotopAsTnoShipsIt(TestCase):
    """The names work on an import of a GeoTOP file (netCDF as TNO delivers
    it: no labels; the preset applied on import)."""

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_cn_")
        subprocess.run(["make", "-s", "-C", GEOTOP_LIKE, "build/geotop_like"], check=True,
                       timeout=600)
        cls.geotop = os.path.join(cls.tmp, "geotop_like.nc")
        subprocess.run([os.path.join(GEOTOP_LIKE, "build", "geotop_like"), "write",
                        cls.geotop, "24", "18", "60"], check=True, timeout=TIMEOUT)
        # -o: the file is in EPSG:7415, the test location is XY
        subprocess.run(["r3.sbrt.convert", "-o", f"file={cls.geotop}", "variable=lithok",
                        "output=cn_gt", "--overwrite", "--quiet"], check=True,
                       timeout=TIMEOUT)
        # the file's extent (x 13650 + 100 i, y 306050 + 100 j, cell centres)
        cls.runModule("g.region", n=307800, s=306000, e=16000, w=13600, res=100)

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        cls.runModule("g.remove", flags="f", type="raster_3d", name="cn_gt")

    def test_codes_name_the_classes(self):
        every = volume_rows("input=cn_gt")
        for code, cid in (("g", "8"), ("gravel", "8"), ("zf", "5"), ("k", "2"),
                          ("kz", "3"), ("she", "9"), ("v", "1"), ("peat", "1")):
            if cid not in every:
                continue
            self.assertEqual(volume_rows("input=cn_gt", f"classes={code}"),
                             {cid: every[cid]}, code)
        self.assertIn("5", every)


if __name__ == "__main__":
    test()
