"""
MODULE:    testsuite/test_r3_sbrt_surface_datum.py (r3.sbrt addon)
PURPOSE:   The vertical datum of a GeoTOP-like file (NAP) where the maps
           and logs show heights (issue 51, item 5): r3.sbrt.surface's top
           and base maps carry it and their unit (r.info: "Vertical datum:
           NAP", units m), the depth map says it is measured from the
           model's surface, the thickness map carries the unit alone;
           r3.sbrt.what's plain log, json and csv give "m NAP" and depths
           below the surface. In a new location of EPSG:28992 (metres)
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


HERE = os.path.dirname(os.path.abspath(__file__))
GEOTOP_LIKE = os.path.join(HERE, "..", "benchmarks", "geotop_like")

# the generator's model: 24 x 18 cells of 100 m from 13600, 306000
POINTS = [13650 + 100 * k for k in range(24)]
NORTH = 306950

SCRIPT = """set -e
cd "$1"
r3.sbrt.convert --q file=gt.nc variable=lithok output=gt
r3.sbrt.convert --q -s sbrt=gt
r3.sbrt.surface --q input=gt classes=2 top=gt_top base=gt_base depth=gt_depth \\
    thickness=gt_thick
for map in gt_top gt_base gt_depth gt_thick; do
    r.info -g map=$map >$map.g
    r.info -e map=$map >$map.e
    r.info map=$map >$map.txt
done
coords={coords}
r3.sbrt.what input=gt coordinates=$coords >what.txt
r3.sbrt.what input=gt coordinates=$coords format=json >what.json
r3.sbrt.what input=gt coordinates=$coords format=csv >what.csv
"""


def info_values(text):
    """key -> value of r.info -e/-g output (r.info 8.2 quotes some values,
    not vdatum: one value per line, quotes stripped)."""
    values = {}
    for line in text.splitlines():
        key, _, value = line.partition("=")
        values[key] = value.strip('"')
    return values


def run_in_rd_location(script, work):
    """Runs bash `script` (with `work` as $1) in PERMANENT of a new location
    of EPSG:28992 beside the current one, removed after: the return code
    and the messages."""
    env = gs.gisenv()
    name = f"rd_datum_{os.getpid()}"
    location = os.path.join(env["GISDBASE"], name)
    shutil.rmtree(location, ignore_errors=True)
    subprocess.run(["grass", "-c", "EPSG:28992", location, "-e"], check=True,
                   capture_output=True, timeout=120)
    gisrc = os.path.join(work, "gisrc")
    with open(gisrc, "w") as f:
        f.write(f"GISDBASE: {env['GISDBASE']}\nLOCATION_NAME: {name}\nMAPSET: PERMANENT\n")
    run_env = dict(os.environ, GISRC=gisrc)
    for region in ("WIND_OVERRIDE", "GRASS_REGION"):  # the test's own region
        run_env.pop(region, None)
    try:
        run = subprocess.run(["bash", "-c", script, "datum", work], capture_output=True,
                             text=True, env=run_env, timeout=300)
    finally:
        shutil.rmtree(location, ignore_errors=True)
    return run.returncode, " ".join(run.stderr.split())


class TestDatumOfAGeotopFile(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="sbrt_datum_")
        subprocess.run(["make", "-s", "-C", GEOTOP_LIKE, "build/geotop_like"], check=True,
                       timeout=300)
        subprocess.run([os.path.join(GEOTOP_LIKE, "build", "geotop_like"), "write",
                        os.path.join(cls.work, "gt.nc"), "24", "18", "60"], check=True,
                       timeout=120)
        coords = ",".join(f"{x},{NORTH}" for x in POINTS)
        cls.code, cls.message = run_in_rd_location(SCRIPT.format(coords=coords), cls.work)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def read(self, name):
        with open(os.path.join(self.work, name)) as f:
            return f.read()

    def test_surface_maps_carry_the_datum_and_unit(self):
        self.assertEqual(self.code, 0, self.message)
        for name in ("gt_top", "gt_base"):
            info = info_values(self.read(name + ".e"))
            self.assertEqual(info["units"], "m", name)
            self.assertEqual(info["vdatum"], "NAP", name)
            self.assertTrue(info["title"].startswith("Elevation (m NAP) of the "),
                            info["title"])
            self.assertIn("Vertical datum: NAP", self.read(name + ".txt"))
        depth = info_values(self.read("gt_depth.e"))
        self.assertEqual((depth["units"], depth["vdatum"]), ("m", "model surface"))
        thick = info_values(self.read("gt_thick.e"))
        self.assertEqual(thick["units"], "m")
        self.assertIn(thick["vdatum"], ("none", ""))
        self.assertIn("Vertical datum: (none)", self.read("gt_thick.txt"))

    def test_logs_name_the_datum_and_the_depths(self):
        self.assertEqual(self.code, 0, self.message)
        points = json.loads(self.read("what.json"))
        solid = [p for p in points if p["status"] == "ok"]
        self.assertGreater(len(solid), 3)
        for p in points:
            self.assertEqual((p["elevation_unit"], p["vertical_datum"]), ("m", "NAP"))
        for p in solid:
            surface = p["surface"]
            self.assertEqual(surface, p["intervals"][0]["top"])
            for i in p["intervals"]:
                self.assertAlmostEqual(i["top_depth"], surface - i["top"], places=9)
                self.assertAlmostEqual(i["bottom_depth"], surface - i["bottom"], places=9)
        # plain: the heading names the unit and datum and the surface
        blocks = self.read("what.txt").split("\n\n")
        first = blocks[points.index(solid[0])].splitlines()
        self.assertTrue(first[0].endswith(" m NAP"), first[0])
        self.assertEqual(first[1], "Elevations in m NAP; depths below the surface at "
                         f"{solid[0]['surface']:.3f} m NAP (the top of the highest layer)")
        self.assertIn("top depth", first[2])
        # csv: the unit and datum on every row
        rows = list(csv.DictReader(io.StringIO(self.read("what.csv"))))
        self.assertEqual({(r["elevation_unit"], r["vertical_datum"]) for r in rows},
                         {("m", "NAP")})
        self.assertEqual(len([r for r in rows if r["status"] == "ok"]),
                         sum(len(p["intervals"]) for p in solid))


if __name__ == "__main__":
    test()
