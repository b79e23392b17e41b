"""
MODULE:    testsuite/test_r3_sbrt_long_titles.py (r3.sbrt addon)
PURPOSE:   Issue 48, items 4, 1, 11 and 12 on r3.sbrt.profile and
           r3.sbrt.surface: a title longer than GRASS's 1024-byte buffer
           (a profile along a line of 60 or 100 vertices, a class set with
           a 1,500-character label) aborted the module with the map half
           written; -g values with a datum from the model's file ran under
           `eval`; -g into a full disk exited 0; a region that misses the
           model gave all-null maps without a word
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from shell_output import shell_values

LIMIT = 120  # seconds for any run: the model is tiny
# 12 x 8 cells of 10 m at UTM-size coordinates, 6 levels of 1 m: class 1
# below, 2 above
W, S = 450000, 5800000
REGION = dict(n=S + 80, s=S, e=W + 120, w=W, b=0, t=6, res=10, res3=10, tbres=1)
TITLE_BUFFER = 1024  # GRASS 8.2: Rast_put_cell_title, Rast_read_cats
FIRST_VERTEX = f"Profile of lt_model along A ({W + 1.37} {S + 10.3}) - B ("
LONG_LABEL = "Sand " + "x" * 1495  # 1,500 characters


def run(*args, **kwargs):
    """Return code, standard output and messages (one space between words:
    GRASS wraps them) of a run with a time limit."""
    done = subprocess.run(list(args), capture_output=True, text=True, timeout=LIMIT,
                          **kwargs)
    return done.returncode, done.stdout, " ".join(done.stderr.split())


def zigzag(count, step):
    """`count` vertices across the model, alternating south and north."""
    return [(W + 1.37 + k * step, S + (10.3 if k % 2 == 0 else 70.7)) for k in range(count)]


class TestLongTitles(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", **REGION)
        cls.runModule("r3.mapcalc", expression="lt_voxels = if(depth() <= 3, 1, 2)",
                      overwrite=True)
        for args in (["r3.sbrt.convert", "input=lt_voxels", "output=lt_model"],
                     ["r3.sbrt.manage", "copy=lt_model,lt_long"]):
            subprocess.run(args + ["--overwrite", "--quiet"], check=True, timeout=LIMIT)
        cls.tmp = tempfile.mkdtemp(prefix="lt_")
        labels = os.path.join(cls.tmp, "labels.txt")
        with open(labels, "w") as f:
            f.write(f"1:{LONG_LABEL}\n2:Clay\n")
        subprocess.run(["r3.sbrt.support", "sbrt=lt_long", f"labels={labels}", "--quiet"],
                       check=True, timeout=LIMIT)
        # the 100-vertex line as a vector map
        vertices = zigzag(100, 1.15)
        gs.write_command("v.in.ascii", input="-", format="standard", flags="n",
                         output="lt_line", quiet=True, overwrite=True,
                         stdin=f"L {len(vertices)} 1\n"
                               + "".join(f" {x} {y}\n" for x, y in vertices) + " 1 1\n")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        gs.run_command("g.remove", flags="f", type="raster", pattern="lt_*", quiet=True)
        gs.run_command("g.remove", flags="f", type="raster_3d", name="lt_voxels", quiet=True)
        gs.run_command("g.remove", flags="f", type="vector", name="lt_line", quiet=True)
        gs.run_command("r3.sbrt.manage", remove="lt_model,lt_long", flags="f", quiet=True)
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def title_of(self, name):
        """The map's title as r.info -e gives it."""
        code, out, err = run("r.info", "-e", f"map={name}")
        self.assertEqual(code, 0, err)
        for line in out.splitlines():
            if line.startswith("title="):
                return line[len("title="):].strip('"')
        self.fail(f"no title in r.info -e of <{name}>: {out}")

    def assert_whole_map(self, name, title_start):
        """Map `name` is there, its title cut to fit GRASS's buffer."""
        self.assertTrue(gs.find_file(name, element="cell")["name"], name)
        title = self.title_of(name)
        self.assertLess(len(title.encode()), TITLE_BUFFER)
        self.assertTrue(title.startswith(title_start), title)
        self.assertTrue(title.endswith("..."), title)  # cut, not dropped
        code, out, err = run("r.info", "-h", f"map={name}")
        self.assertEqual(code, 0, err)
        self.assertIn("SBRT lt_", out)  # the history written after the title

    def test_profile_of_a_60_vertex_line(self):
        coordinates = ",".join(f"{x},{y}" for x, y in zigzag(60, 1.9))
        code, _, err = run("r3.sbrt.profile", "input=lt_model", f"coordinates={coordinates}",
                           "output=lt_profile60", "--overwrite")
        self.assertEqual(code, 0, err)
        self.assert_whole_map("lt_profile60", FIRST_VERTEX)

    def test_profile_of_a_100_vertex_line_map(self):
        code, _, err = run("r3.sbrt.profile", "input=lt_model", "line=lt_line",
                           "output=lt_profile100", "--overwrite")
        self.assertEqual(code, 0, err)
        self.assert_whole_map("lt_profile100", FIRST_VERTEX)

    def test_surface_of_a_class_with_a_long_label(self):
        code, _, err = run("r3.sbrt.surface", "input=lt_long", "classes=1",
                           "thickness=lt_thick", "--overwrite")
        self.assertEqual(code, 0, err)
        self.assert_whole_map("lt_thick", "Thickness of 1 (Sand xxx")

    def test_surface_outside_the_model_warns(self):
        self.runModule("g.region", n=1080, s=1000, e=5120, w=5000, res=10)
        try:
            code, _, err = run("r3.sbrt.surface", "input=lt_model", "classes=1",
                               "thickness=lt_off", "--overwrite")
        finally:
            self.runModule("g.region", **REGION)
        self.assertEqual(code, 0, err)
        self.assertIn("misses SBRT <lt_model>", err)
        self.assertIn(f"n={S + 80} s={S} e={W + 120} w={W}", err)  # the model's extent
        self.assertIn("r3.sbrt.convert -s sbrt=lt_model", err)

    def test_surface_inside_the_model_does_not_warn(self):
        code, _, err = run("r3.sbrt.surface", "input=lt_model", "classes=1",
                           "thickness=lt_in", "--overwrite")
        self.assertEqual(code, 0, err)
        self.assertNotIn("misses", err)


class TestProfileShellOutput(TestCase):
    """-g of a model whose vertical datum (a member of its file) is made
    to run commands under eval."""

    LINE = f"coordinates={W + 5},{S + 10},{W + 115},{S + 70}"

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", **REGION)
        cls.runModule("r3.mapcalc", expression="lt_gvoxels = if(depth() <= 3, 1, 2)",
                      overwrite=True)
        subprocess.run(["r3.sbrt.convert", "input=lt_gvoxels", "output=lt_datum",
                        "--overwrite", "--quiet"], check=True, timeout=LIMIT)
        env = gs.gisenv()
        cls.member = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"],
                                  "sbrt", "lt_datum", "datum")
        cls.tmp = tempfile.mkdtemp(prefix="ltg_")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        gs.run_command("g.remove", flags="f", type="raster_3d", name="lt_gvoxels", quiet=True)
        gs.run_command("r3.sbrt.manage", remove="lt_datum", flags="f", quiet=True)
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def set_datum(self, datum):
        with open(self.member, "w") as f:
            f.write(datum + "\n")

    def eval_in_bash(self, script):
        """Runs `script` in bash (PROFILE: the -g command); its output."""
        command = f"r3.sbrt.profile -g input=lt_datum {self.LINE}"
        code, out, err = run("bash", "-c", script.replace("PROFILE", command))
        self.assertEqual(code, 0, err)
        return out

    def test_datum_with_spaces_and_parentheses(self):
        self.set_datum("NAP (Amsterdam)")
        code, out, err = run("r3.sbrt.profile", "-g", "input=lt_datum", self.LINE)
        self.assertEqual(code, 0, err)
        self.assertEqual(shell_values(out)["elevation_title"],
                         "Elevation (map units NAP (Amsterdam))")
        for script in ('eval "$(PROFILE)"; printf %s "$elevation_title"',
                       'eval $(PROFILE); printf %s "$elevation_title"'):
            self.assertEqual(self.eval_in_bash(script),
                             "Elevation (map units NAP (Amsterdam))", script)

    def test_hostile_datum_runs_nothing(self):
        marker = os.path.join(self.tmp, "m")
        for datum in (f"$(touch {marker})", f"`touch {marker}`", f"';touch {marker};'",
                      f"x; touch {marker} #"):
            self.set_datum(datum)
            for script in ('eval "$(PROFILE)"; printf %s "$elevation_title"',
                           'eval $(PROFILE); printf %s "$elevation_title"'):
                out = self.eval_in_bash(script)
                self.assertFalse(os.path.exists(marker), f"{datum!r} ran in {script}")
                self.assertEqual(out, f"Elevation (map units {datum})", script)

    def test_full_disk_fails(self):
        self.set_datum("NAP")
        code, _, err = run("bash", "-c",
                           f"r3.sbrt.profile -g input=lt_datum {self.LINE} > /dev/full")
        self.assertNotEqual(code, 0, err)
        self.assertIn("standard output", err)


if __name__ == "__main__":
    test()
