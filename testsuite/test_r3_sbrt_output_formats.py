"""
MODULE:    testsuite/test_r3_sbrt_output_formats.py (r3.sbrt addon)
PURPOSE:   Issue 52, item 3: every module that prints offers format= (plain,
           json, csv, shell where it has -g) from one definition; json
           parses with json.loads and csv with csv.reader for every
           separator= name, shell as a shell reads it, for a model whose
           labels, units and datum hold quotes, commas, the separators, a
           newline, a tab, `$(touch x)`, bytes that are no UTF-8 and Dutch
           names; the values come back as they were set (in csv, which is
           printed to terminals, control characters are U+FFFD)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import csv
import io
import json
import os
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from shell_output import shell_records, shell_values
from test_r3_sbrt_shell_output import (DATUM, LONG_NAME, NX, NY, UNIT, X0, Y0,
                                       write_hostile_netcdf)

# the labels as bytes (a label file of another mapset may hold anything)
LABELS = {
    1: b'Zand, "fijn";\tgrijs | \'x\' $(touch PWNED_label)',
    2: b"Formatie van Peelo \xff\xc3( \xc4\xb2ssel, Dr\xc3\xa9nthe",
    3: b"Kreftenheye klei\x1b[31m rood",
}
# separator= names and the character each gives
SEPARATORS = {"comma": ",", "pipe": "|", "space": " ", "tab": "\t", ";": ";"}
POINT = f"coordinates={X0 + 50},{Y0 + 50},{X0 + 250},{Y0 + 150}"
LINE = f"coordinates={X0},{Y0},{X0 + 300},{Y0 + 200}"


def as_text(label):
    """What json gives back: the bytes that are no UTF-8 made U+FFFD."""
    return label.decode("utf-8", errors="replace")


def printable(text):
    """What csv gives back: as_text with every control character U+FFFD."""
    return "".join("\ufffd" if ord(c) < 0x20 or 0x7f <= ord(c) <= 0x9f else c
                   for c in text)


def run_module(*args):
    """stdout of a module as text, which must be valid UTF-8."""
    run = subprocess.run(list(args), capture_output=True, timeout=120)
    assert run.returncode == 0, (args, run.stderr.decode(errors="replace")[-2000:])
    return run.stdout.decode("utf-8")


def error_of(*args):
    run = subprocess.run(list(args), capture_output=True, text=True, timeout=120)
    return run.returncode, " ".join(run.stderr.split())


def csv_rows(text, separator):
    """The rows of csv `text`, checked to be as long as the header."""
    rows = list(csv.reader(io.StringIO(text, newline=""), delimiter=separator, strict=True))
    for row in rows:
        assert len(row) == len(rows[0]), (separator, rows[0], row)
    return [dict(zip(rows[0], row)) for row in rows[1:]]


class TestOutputFormats(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_formats_")
        cls.file = os.path.join(cls.tmp, "hostile.nc")
        write_hostile_netcdf(cls.file)
        cls.use_temp_region()
        cls.runModule("r3.sbrt.convert", flags="o", file=cls.file, variable="lithok",
                      properties="kans_5,poro", output="fmt_hostile", preset="none")
        labels = os.path.join(cls.tmp, "labels.txt")
        with open(labels, "wb") as f:
            f.write(b"".join(b"%d:%s\n" % item for item in LABELS.items()))
        cls.runModule("r3.sbrt.support", sbrt="fmt_hostile", labels=labels)
        cls.runModule("r3.sbrt.convert", flags="s", sbrt="fmt_hostile")

    @classmethod
    def tearDownClass(cls):
        gs.run_command("r3.sbrt.manage", remove="fmt_hostile", flags="f", quiet=True)
        cls.del_temp_region()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def assertLabels(self, labels, made):
        """`labels` (class id -> label) are the set labels as `made` gives them."""
        self.assertEqual(labels, {c: made(as_text(LABELS[c])) for c in labels})
        self.assertTrue(labels)

    # r3.sbrt.what

    def test_what_json(self):
        points = json.loads(run_module("r3.sbrt.what", "input=fmt_hostile", POINT,
                                       "format=json"))
        self.assertEqual(len(points), 2)
        self.assertEqual(points[0]["vertical_datum"], DATUM)
        labels = {i["class"]: i["label"] for p in points for i in p["intervals"]}
        self.assertLabels(labels, lambda t: t)
        self.assertIn("kans_5", points[0]["voxels"][0]["values"])

    def test_what_csv_for_every_separator(self):
        for name, separator in SEPARATORS.items():
            for flags in ([], ["-v"]):
                rows = csv_rows(run_module("r3.sbrt.what", "input=fmt_hostile", POINT,
                                           "format=csv", f"separator={name}", *flags),
                                separator)
                layers = [r for r in rows if r.get("kind", "layer") == "layer"]
                self.assertLabels({int(r["class"]): r["label"] for r in layers}, printable)
                self.assertEqual({r["vertical_datum"] for r in rows}, {DATUM}, name)
                self.assertEqual({r["x"] for r in rows}, {str(X0 + 50), str(X0 + 250)})
                if flags:
                    voxels = [r for r in rows if r["kind"] == "voxel"]
                    self.assertTrue(voxels, name)
                    self.assertEqual(voxels[0]["kans_5"], "50", name)

    # r3.sbrt.volume

    def test_volume_json(self):
        report = json.loads(run_module("r3.sbrt.volume", "input=fmt_hostile",
                                       "format=json"))
        labels = {r["classes"][0]: r["labels"][0] for r in report["volumes"]}
        self.assertLabels(labels, lambda t: t)
        self.assertEqual(sum(r["cells"] for r in report["volumes"]), 3 * NX * NY)

    def test_volume_csv_for_every_separator(self):
        for name, separator in SEPARATORS.items():
            rows = csv_rows(run_module("r3.sbrt.volume", "input=fmt_hostile", "format=csv",
                                       f"separator={name}"), separator)
            self.assertLabels({int(r["classes"]): r["labels"] for r in rows}, printable)
            self.assertEqual(sum(int(r["cells"]) for r in rows), 3 * NX * NY, name)

    def test_csv_separators_that_part_no_record_are_refused(self):
        for command in (["r3.sbrt.volume", "input=fmt_hostile"],
                        ["r3.sbrt.what", "input=fmt_hostile", POINT]):
            code, message = error_of(*command, "format=csv", "separator=newline")
            self.assertNotEqual(code, 0)
            self.assertIn("separator=newline", message)

    # r3.sbrt.convert

    def test_convert_report_json(self):
        report = json.loads(run_module("r3.sbrt.convert", "sbrt=fmt_hostile", "format=json"))
        self.assertEqual(report["vertical_datum"], DATUM)
        self.assertEqual((report["rows"], report["cols"]), (NY, NX))
        self.assertLabels({c["class"]: c["label"] for c in report["classes"]},
                          lambda t: t)
        channels = {c["name"]: c for c in report["channels"]}
        self.assertEqual(channels["kans_5"]["unit"], UNIT)
        self.assertEqual(channels["kans_5"]["long_name"], LONG_NAME)
        self.assertEqual(channels["poro"]["unit"], "m\n3")  # the newline kept
        # -p gives the same json
        self.assertEqual(json.loads(run_module("r3.sbrt.convert", "-p", "sbrt=fmt_hostile",
                                               "format=json")), report)

    def test_convert_shell_is_g(self):
        g = run_module("r3.sbrt.convert", "-g", "sbrt=fmt_hostile")
        self.assertEqual(run_module("r3.sbrt.convert", "sbrt=fmt_hostile", "format=shell"), g)
        self.assertEqual(shell_values(g)["vertical_datum"], DATUM)
        kans = [c for c in shell_records(g, "channel") if c["channel"] == "kans_5"][0]
        self.assertEqual(kans["unit"], UNIT)
        variables = run_module("r3.sbrt.convert", "-g", f"file={self.file}")
        self.assertEqual(run_module("r3.sbrt.convert", "format=shell", f"file={self.file}"),
                         variables)

    def test_convert_file_variables_and_list_json(self):
        variables = json.loads(run_module("r3.sbrt.convert", "-p", f"file={self.file}",
                                          "format=json"))
        lithok = [v for v in variables if v["name"] == "lithok"][0]
        self.assertEqual(lithok["long_name"], LONG_NAME)
        self.assertEqual(lithok["sizes"], [NX, NY, 5])
        listed = json.loads(run_module("r3.sbrt.convert", "-l", "format=json"))
        mapset = gs.gisenv()["MAPSET"]
        self.assertIn({"name": "fmt_hostile", "mapset": mapset,
                       "fullname": f"fmt_hostile@{mapset}"}, listed)

    def test_g_with_another_format_is_an_error(self):
        for command in (["r3.sbrt.convert", "-g", "sbrt=fmt_hostile"],
                        ["r3.sbrt.profile", "-g", "input=fmt_hostile", LINE]):
            code, message = error_of(*command, "format=json")
            self.assertNotEqual(code, 0, command)
            self.assertIn("-g or format=, not both", message)

    # r3.sbrt.profile

    def test_profile_json_and_shell(self):
        g = run_module("r3.sbrt.profile", "-g", "input=fmt_hostile", LINE)
        self.assertEqual(run_module("r3.sbrt.profile", "format=shell", "input=fmt_hostile",
                                    LINE), g)
        shell = shell_values(g)
        profile = json.loads(run_module("r3.sbrt.profile", "format=json",
                                        "input=fmt_hostile", LINE))
        self.assertEqual(profile["elevation_title"], shell["elevation_title"])
        self.assertIn(DATUM, profile["elevation_title"])
        self.assertEqual(profile["title"], shell["title"])
        self.assertAlmostEqual(profile["length"], float(shell["length"]))
        self.assertEqual(profile["classes_cut"],
                         [int(c) for c in shell["classes_cut"].split(",")])

    # r3.sbrt.manage

    def test_manage_list_json_and_csv(self):
        mapset = gs.gisenv()["MAPSET"]
        row = {"name": "fmt_hostile", "mapset": mapset, "fullname": f"fmt_hostile@{mapset}"}
        self.assertIn(row, json.loads(run_module("r3.sbrt.manage", "-l", "mapset=.",
                                                 "format=json")))
        for name, separator in SEPARATORS.items():
            rows = csv_rows(run_module("r3.sbrt.manage", "-l", "mapset=.", "format=csv",
                                       f"separator={name}"), separator)
            self.assertIn(row, rows, name)


if __name__ == "__main__":
    test()
