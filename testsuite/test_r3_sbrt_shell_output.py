"""
MODULE:    testsuite/test_r3_sbrt_shell_output.py (r3.sbrt addon)
PURPOSE:   Issue 48, items 1 and 2: the -g output of every module is read by
           a shell with `eval $(...)` and `eval "$(...)"` and runs nothing,
           with hostile attribute values (units, long names, a vertical
           datum holding command substitutions, quotes, pipes, a newline)
           and hostile labels; the values come back as they were (the
           control characters made U+FFFD); no control character of a
           label reaches a terminal (-p, r3.sbrt.what)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from shell_output import shell_records, shell_values

NX, NY, NZ = 4, 3, 5
X0, Y0, DX = 120000, 480000, 100
UNIT = "%$(touch PWNED_unit)"
LONG_NAME = "x; touch PWNED_long; echo"
TICK_NAME = "it's `touch PWNED_tick` | pipe & amp > gt"
DATUM = "NAP$(touch PWNED_datum)"
# a label with a C0 control, an escape sequence and a command
LABEL = "ctrl\x01\x1b[31mred; $(touch PWNED_label)"
WKT = (
    'COMPD_CS["RD New + {d} height",PROJCS["Amersfoort / RD New",GEOGCS["Amersfoort",'
    'DATUM["Amersfoort",SPHEROID["Bessel 1841",6377397.155,299.1528128]],'
    'PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]],'
    'PROJECTION["Oblique_Stereographic"],PARAMETER["latitude_of_origin",52.1561605555556],'
    'PARAMETER["central_meridian",5.38763888888889],PARAMETER["scale_factor",0.9999079],'
    'PARAMETER["false_easting",155000],PARAMETER["false_northing",463000],'
    'UNIT["metre",1]],VERT_CS["{d} height",VERT_DATUM["Normaal Amsterdams Peil",2005],'
    'UNIT["metre",1],AXIS["Up",UP]]]')


def cdl_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def write_hostile_netcdf(path, datum=DATUM, long_name=LONG_NAME):
    """A GeoTOP-shaped file whose attributes are shell code."""
    column = [1, 1, 2, 2, 3]
    n = NX * NY
    cdl = f"""netcdf hostile {{
dimensions:
  x = {NX} ; y = {NY} ; z = {NZ} ;
variables:
  int x(x) ; x:standard_name = "projection_x_coordinate" ; x:units = "m" ;
  int y(y) ; y:standard_name = "projection_y_coordinate" ; y:units = "m" ;
  float z(z) ; z:positive = "up" ; z:units = "m" ;
  int crs ; crs:crs_wkt = {cdl_string(WKT.replace("{d}", datum))} ;
  short lithok(x, y, z) ; lithok:_FillValue = -127s ; lithok:grid_mapping = "crs" ;
    lithok:long_name = {cdl_string(LONG_NAME)} ;
  short kans_5(x, y, z) ; kans_5:_FillValue = -127s ; kans_5:grid_mapping = "crs" ;
    kans_5:units = {cdl_string(UNIT)} ; kans_5:long_name = {cdl_string(long_name)} ;
  float poro(x, y, z) ; poro:grid_mapping = "crs" ;
    poro:long_name = {cdl_string(TICK_NAME)} ; poro:units = {cdl_string("m" + chr(10) + "3")} ;
data:
  x = {", ".join(str(X0 + DX * i) for i in range(NX))} ;
  y = {", ".join(str(Y0 + DX * j) for j in range(NY))} ;
  z = -4.5, -3.5, -2.5, -1.5, -0.5 ;
  lithok = {", ".join(str(v) for v in column * n)} ;
  kans_5 = {", ".join(str(10 * (k + 1)) for _ in range(n) for k in range(NZ))} ;
  poro = {", ".join("0.25" for _ in range(NZ * n))} ;
}}
"""
    with open(path + ".cdl", "w") as f:
        f.write(cdl)
    subprocess.run(["ncgen", "-k", "nc4", "-o", path, path + ".cdl"], check=True,
                   timeout=60)


class TestShellOutputIsSafeToEval(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_eval_")
        cls.file = os.path.join(cls.tmp, "hostile.nc")
        write_hostile_netcdf(cls.file)
        cls.use_temp_region()
        # -o: the file's CRS is not the XY location's
        cls.runModule("r3.sbrt.convert", flags="o", file=cls.file, variable="lithok",
                      properties="kans_5,poro", output="hostile", preset="none")
        rules = os.path.join(cls.tmp, "labels.txt")
        with open(rules, "w") as f:
            f.write(f"1:{LABEL}\n2:clay, 'stiff' \"grey\"\n")
        cls.runModule("r3.sbrt.support", sbrt="hostile", labels=rules)
        cls.runModule("r3.sbrt.convert", flags="s", sbrt="hostile")

    @classmethod
    def tearDownClass(cls):
        gs.run_command("r3.sbrt.manage", remove="hostile", flags="f", quiet=True)
        cls.del_temp_region()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    COMMANDS = {
        "convert -g sbrt=": ["r3.sbrt.convert", "-g", "sbrt=hostile"],
        "convert -g file=": ["r3.sbrt.convert", "-g", "file={file}"],
        "profile -g": ["r3.sbrt.profile", "-g", "input=hostile",
                       f"coordinates={X0},{Y0},{X0 + 300},{Y0 + 200}"],
    }

    def shell(self, script):
        """bash runs `script` in a fresh folder; returns its output and the
        files it left there."""
        folder = tempfile.mkdtemp(dir=self.tmp)
        run = subprocess.run(["bash", "-c", script], cwd=folder, capture_output=True,
                             text=True, timeout=60)
        return run, sorted(os.listdir(folder))

    def command_line(self, name):
        return " ".join("'" + w.replace("{file}", self.file) + "'"
                        for w in self.COMMANDS[name])

    def test_every_g_output_evaluates_without_running_anything(self):
        for name in self.COMMANDS:
            command = self.command_line(name)
            for quoted in (f"eval \"$({command})\"", f"eval $({command})"):
                run, left = self.shell(f"set -e; {quoted}; echo evaluated")
                self.assertEqual(run.returncode, 0, (name, quoted, run.stderr[-2000:]))
                self.assertIn("evaluated", run.stdout, name)
                self.assertEqual(left, [], (name, quoted, "the shell ran a command"))

    def test_values_come_back_as_they_were(self):
        run, _ = self.shell(
            f"eval \"$({self.command_line('convert -g sbrt=')})\"; "
            "printf '%s\\n' \"$vertical_datum\" \"$north\" \"$channel\"")
        datum, north, channel = run.stdout.splitlines()
        self.assertEqual(datum, DATUM)
        self.assertEqual(float(north), Y0 + (NY - 0.5) * DX)
        self.assertTrue(channel.startswith("poro|type=f32|"), channel)
        # the record's own separator in a value is written as a broken bar
        self.assertIn("long_name=" + TICK_NAME.replace("|", "\u00a6"), channel)
        self.assertIn("unit=m\ufffd3", channel)  # the newline made printable
        run, _ = self.shell(
            f"eval \"$({self.command_line('profile -g')})\"; "
            "printf '%s\\n' \"$elevation_title\"")
        # "m" in a projected location, "map units" in this XY one
        self.assertRegex(run.stdout.strip(), r"^Elevation \((m|map units) NAP\$\(touch PWNED_datum\)\)$")

    def test_python_reads_the_same_values(self):
        output = gs.read_command("r3.sbrt.convert", flags="g", sbrt="hostile")
        self.assertEqual(shell_values(output)["vertical_datum"], DATUM)
        kans = [c for c in shell_records(output, "channel") if c["channel"] == "kans_5"][0]
        self.assertEqual(kans["unit"], UNIT)
        self.assertEqual(kans["long_name"], LONG_NAME)
        variables = shell_records(
            gs.read_command("r3.sbrt.convert", flags="g", file=self.file), "variable")
        lithok = [v for v in variables if v["variable"] == "lithok"][0]
        self.assertEqual((lithok["long_name"], lithok["sizes"]),
                         (LONG_NAME, f"{NX},{NY},{NZ}"))

    def test_texts_an_sbrt_cannot_hold_are_made_to_fit(self):
        """A vertical CRS named over two lines gave an SBRT that nothing
        could read, a long name of 5000 bytes one whose channels nothing
        could read: the import gives no datum (with a warning) and cuts
        the long name, and the SBRT reads."""
        path = os.path.join(self.tmp, "unholdable.nc")
        write_hostile_netcdf(path, datum="NAP\nsecond line", long_name="x" * 5000)
        run = subprocess.run(["r3.sbrt.convert", "-o", f"file={path}", "variable=lithok",
                              "properties=kans_5", "output=unholdable", "preset=none",
                              "--overwrite"], capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stderr[-2000:])
        self.assertIn("no vertical datum", " ".join(run.stderr.split()))
        output = gs.read_command("r3.sbrt.convert", flags="g", sbrt="unholdable")
        self.assertEqual(shell_values(output)["vertical_datum"], "")
        kans = shell_records(output, "channel")[0]
        self.assertEqual(len(kans["long_name"].encode()), 4096)
        self.assertTrue(kans["long_name"].endswith("..."))
        gs.run_command("r3.sbrt.manage", remove="unholdable", flags="f", quiet=True)

    def test_labels_reach_no_terminal_with_control_characters(self):
        point = f"coordinates={X0 + 50},{Y0 + 50}"
        outputs = {
            "convert -p": ["r3.sbrt.convert", "-p", "sbrt=hostile"],
            "what": ["r3.sbrt.what", "input=hostile", point],
            "what csv": ["r3.sbrt.what", "input=hostile", point, "format=csv"],
        }
        for name, command in outputs.items():
            run = subprocess.run(command, capture_output=True, timeout=60)
            self.assertEqual(run.returncode, 0, (name, run.stderr[-2000:]))
            for control in (b"\x01", b"\x1b"):
                self.assertNotIn(control, run.stdout + run.stderr, name)
            text = run.stdout.decode("utf-8")  # valid UTF-8 too
            self.assertIn("ctrl\ufffd\ufffd[31mred", text, name)


if __name__ == "__main__":
    test()
