"""
MODULE:    testsuite/test_r3_sbrt_geotop_delivered.py (r3.sbrt addon)
PURPOSE:   GeoTOP as TNO ships it (issue 51, item 1): kans_* without units,
           Dutch long_names, epsg on x, y and z, no flag_meanings. Imported
           with nothing but the (automatic) GeoTOP preset, the expected
           thickness and volume of kans_5+kans_6+kans_7 equal a reference
           computed from the NetCDF cell by cell; imported with
           preset=none, r3.sbrt.support channel= unit= kind= makes them
           work; -g lists each channel's kind
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import json
import math
import os
import re
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from shell_output import shell_records

HERE = os.path.dirname(os.path.abspath(__file__))
GEOTOP_LIKE = os.path.join(HERE, "..", "benchmarks", "geotop_like")
NX, NY, NZ = 17, 16, 20  # chunks of 16 columns: no side below 16
DZ = 0.5
CELL_AREA = 100.0 * 100.0
SAND = "kans_5+kans_6+kans_7"
FILL = -127


def ncdump_values(path, names):
    """name -> flat list of a variable's values (None for the fill), x
    slowest, z fastest, as ncdump prints them."""
    run = subprocess.run(["ncdump", "-v", ",".join(names), path],
                         capture_output=True, text=True, timeout=60, check=True)
    data = run.stdout.split("data:", 1)[1]
    values = {}
    for name in names:
        body = re.search(r"\b%s =(.*?);" % re.escape(name), data, re.S).group(1)
        values[name] = [None if word.strip() in ("_", str(FILL)) else int(word)
                        for word in body.replace("\n", " ").split(",")]
    return values


def reference_thickness(path):
    """(i, j) -> the expected thickness of kans_5+6+7 in column (x i, y j):
    the sum of p / 100 * DZ over its voxels with a value; None where none."""
    names = SAND.split("+")
    values = ncdump_values(path, names)
    out = {}
    for i in range(NX):
        for j in range(NY):
            total, any_value = 0.0, False
            for k in range(NZ):
                at = (i * NY + j) * NZ + k
                ps = [values[n][at] for n in names]
                if None in ps:
                    continue
                any_value = True
                total += sum(ps) / 100.0 * DZ
            out[(i, j)] = total if any_value else None
    return out


def raster_cells(name):
    """(i, j) -> value of raster `name` (None for null): column i from the
    west, j from the south (the file's y ascends)."""
    text = gs.read_command("r.out.ascii", input=name, precision=9, null_value="*",
                           flags="h")
    rows = [line.split() for line in text.strip().splitlines()]
    assert len(rows) == NY and all(len(r) == NX for r in rows), (len(rows), rows[:1])
    return {(i, NY - 1 - r): None if word == "*" else float(word)
            for r, row in enumerate(rows) for i, word in enumerate(row)}


def channels_of(sbrt):
    output = gs.read_command("r3.sbrt.convert", flags="g", sbrt=sbrt)
    return {c["channel"]: c for c in shell_records(output, "channel")}


def expected_volume(sbrt):
    report = json.loads(gs.read_command("r3.sbrt.volume", input=sbrt,
                                        probability=SAND, format="json"))
    return report["expected"][0]


class TestGeotopAsDelivered(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_geotop_delivered_")
        subprocess.run(["make", "-s", "-C", GEOTOP_LIKE, "build/geotop_like"],
                       check=True, timeout=300)
        cls.file = os.path.join(cls.tmp, "geotop.nc")
        subprocess.run([os.path.join(GEOTOP_LIKE, "build", "geotop_like"), "write",
                        cls.file, str(NX), str(NY), str(NZ), "properties"],
                       check=True, timeout=60)
        properties = "kans_5,kans_6,kans_7,onz_lk,onz_ls"
        # -o: the file is in EPSG:7415, the test location is XY
        cls.import_log = gs.read_command(
            "r3.sbrt.convert", flags="o", file=cls.file, variable="lithok",
            properties=properties, output="gd", overwrite=True, stderr=subprocess.STDOUT)
        gs.run_command("r3.sbrt.convert", flags="o", file=cls.file, variable="lithok",
                      properties=properties, output="gd_none", preset="none",
                      overwrite=True, quiet=True)
        gs.run_command("r3.sbrt.convert", flags="s", sbrt="gd", quiet=True)
        cls.reference = reference_thickness(cls.file)

    def test_the_generator_writes_the_delivered_layout(self):
        header = subprocess.run(["ncdump", "-h", self.file], capture_output=True,
                                text=True, timeout=60, check=True).stdout
        self.assertIn('kans_5:long_name = "kans op lithoklasse 5"', header)
        self.assertNotIn("kans_5:units", header)
        self.assertNotIn("flag_meanings", header)
        for axis in "xyz":
            self.assertIn('%s:epsg = "7415"' % axis, header)

    def test_preset_says_what_the_channels_are(self):
        self.assertIn("preset geotop_lithoclass", " ".join(self.import_log.split()))
        self.assertIn("kans_5 probability in %", " ".join(self.import_log.split()))
        channels = channels_of("gd")
        for name in ("kans_5", "kans_6", "kans_7"):
            self.assertEqual((channels[name]["kind"], channels[name]["unit"]),
                             ("probability", "%"), name)
        self.assertEqual(channels["kans_5"]["long_name"], "kans op lithoklasse 5")
        self.assertEqual((channels["onz_lk"]["kind"], channels["onz_lk"]["unit"]),
                         ("uncertainty", ""))
        # without the preset: the file's (no) units, kind other
        self.assertEqual((channels_of("gd_none")["kans_5"]["kind"],
                          channels_of("gd_none")["kans_5"]["unit"]), ("other", ""))

    def assert_thickness_is_the_reference(self, sbrt, output):
        self.assertModule("r3.sbrt.surface", input=sbrt, probability=SAND,
                          expected_thickness=output, overwrite=True)
        cells = raster_cells(output)
        compared = 0
        for key, want in self.reference.items():
            got = cells[key]
            if want is None:
                self.assertIsNone(got, key)
                continue
            self.assertIsNotNone(got, key)
            self.assertAlmostEqual(got, want, delta=1e-6, msg=key)
            compared += 1
        self.assertGreater(compared, NX * NY // 3)
        volume = expected_volume(sbrt)
        want = sum(t for t in self.reference.values() if t) * CELL_AREA
        self.assertAlmostEqual(volume["volume"], want, delta=1e-6 * want)
        self.assertEqual(volume["cells"],
                         sum(1 for t in self.reference.values() if t and t > 0))

    def test_expected_thickness_and_volume_with_the_preset_alone(self):
        self.assert_thickness_is_the_reference("gd", "gd_sand")

    def test_support_makes_an_import_without_the_preset_work(self):
        gs.run_command("r3.sbrt.convert", flags="o", file=self.file, variable="lithok",
                       properties="kans_5,kans_6,kans_7,onz_lk", output="gd_set",
                       preset="none", overwrite=True, quiet=True)
        module = self.assertModuleFail_stderr(
            "r3.sbrt.surface", input="gd_set", probability=SAND,
            expected_thickness="gd_set_sand", overwrite=True)
        self.assertIn("'kans_5' is in ''", module)
        self.assertIn("kind=probability", module)
        self.assertModuleFail("r3.sbrt.volume", input="gd_set", probability=SAND)
        self.assertModule("r3.sbrt.support", sbrt="gd_set",
                          channel="kans_5,kans_6,kans_7", unit="%", kind="probability")
        channels = channels_of("gd_set")
        self.assertEqual((channels["kans_6"]["kind"], channels["kans_6"]["unit"]),
                         ("probability", "%"))
        self.assertEqual(channels["onz_lk"]["kind"], "other")  # not named: as it was
        self.assertEqual(channels["kans_6"]["valid"], channels_of("gd")["kans_6"]["valid"])
        self.assert_thickness_is_the_reference("gd_set", "gd_set_sand")
        # the kind decides, not the unit: in % but no probability, refused
        self.assertModule("r3.sbrt.support", sbrt="gd_set", channel="kans_7",
                          kind="uncertainty")
        kans_7 = channels_of("gd_set")["kans_7"]
        self.assertEqual((kans_7["kind"], kans_7["unit"]), ("uncertainty", "%"))
        module = self.assertModuleFail_stderr(
            "r3.sbrt.surface", input="gd_set", probability=SAND,
            expected_thickness="gd_set_sand", overwrite=True)
        self.assertIn("'kans_7'", module)

    def test_support_history_line(self):
        gs.run_command("r3.sbrt.convert", flags="o", file=self.file, variable="lithok",
                       properties="kans_5", output="gd_hist", preset="none",
                       overwrite=True, quiet=True)
        self.assertModule("r3.sbrt.support", sbrt="gd_hist", channel="kans_5",
                          kind="probability")
        self.assertEqual(channels_of("gd_hist")["kans_5"]["unit"], "%")  # a probability
        env = gs.gisenv()
        hist = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"],
                            "sbrt", "gd_hist", "hist")
        with open(hist, encoding="utf-8") as f:
            self.assertIn("channels changed: ", f.read())

    def test_bad_channel_changes_are_refused_by_name(self):
        gs.run_command("r3.sbrt.convert", flags="o", file=self.file, variable="lithok",
                       properties="kans_5", output="gd_bad", preset="none",
                       overwrite=True, quiet=True)
        before = channels_of("gd_bad")
        cases = (
            (dict(channel="kans_9", kind="probability"), "no channel 'kans_9'"),
            (dict(channel="kans_5", kind="probability", unit="m"), "a probability is in %"),
            (dict(channel="kans_5", kind="likely"), "likely"),
            (dict(channel="kans_5"), "unit"),
            (dict(unit="%"), "channel"),
            (dict(channel="kans_5,kans_5", kind="other"), "twice"),
            (dict(channel="kans_5", unit="a\tb"), "printable"),
        )
        for options, message in cases:
            module = self.assertModuleFail_stderr("r3.sbrt.support", sbrt="gd_bad",
                                                  **options)
            self.assertIn(message, module, options)
        self.assertEqual(channels_of("gd_bad"), before)
        gs.run_command("r3.sbrt.convert", flags="o", file=self.file, variable="lithok",
                       output="gd_plain", overwrite=True, quiet=True)
        module = self.assertModuleFail_stderr("r3.sbrt.support", sbrt="gd_plain",
                                              channel="kans_5", kind="probability")
        self.assertIn("no property channels", module)

    def assertModuleFail_stderr(self, module, **options):
        """Runs `module` (a failure expected): its stderr, spaces joined."""
        overwrite = ["--overwrite"] if options.pop("overwrite", False) else []
        run = subprocess.run([module] + ["%s=%s" % kv for kv in options.items()]
                             + overwrite, capture_output=True, text=True, timeout=120)
        self.assertNotEqual(run.returncode, 0, (module, options))
        self.assertNotIn("Traceback", run.stderr)
        return " ".join(run.stderr.split())


if __name__ == "__main__":
    test()
