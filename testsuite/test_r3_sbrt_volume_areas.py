"""
MODULE:    testsuite/test_r3_sbrt_volume_areas.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.volume areas= counts a cell for every category whose
           area holds its centre (overlapping polygons, a hole, an island
           in the hole), against a count in Python of the model's formula;
           a failed write to standard output, a region that misses the
           model, hostile labels in JSON, CSV and the plain table
           (issue 48, items 2, 7, 8, 11, 12)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import csv
import io
import json
import os
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

# 30 x 20 cells of 10 m, 10 levels of 2 m; column (r, c) (0-based, r from
# the north) holds 1 + (r + c + 2) % 5 voxels from the bottom, of class
# 1 + (r + 1 + depth) % 2 (depth 1 at the bottom)
REGION = dict(n=200, s=0, w=0, e=300, b=0, t=20, res=10, res3=10, tbres=2)
ROWS, COLS, DEPTHS = 20, 30, 10
MODEL = ("geo = if(depth() <= 1 + (row() + col()) % 5, "
         "1 + (row() + depth()) % 2, null())")
VOXEL = 10.0 * 10.0 * 2.0

# edges off the cell centres (5 + 10 k); 1 and 2 overlap, 3 has a hole
# with an island of its own in it, 4 crosses 3's ring, hole and island
RECT1 = [(12.3, 13.7), (151.1, 13.7), (151.1, 121.9), (12.3, 121.9)]
RECT2 = [(81.2, 52.1), (231.7, 52.1), (231.7, 181.3), (81.2, 181.3)]
OUTER3 = [(163.7, 4.1), (296.2, 11.3), (288.9, 141.7), (171.4, 128.3)]
HOLE3 = [(191.3, 31.7), (268.8, 33.9), (262.1, 112.6), (196.6, 109.4)]
ISLAND3 = [(215.3, 55.2), (244.9, 57.7), (241.1, 86.3), (217.8, 84.9)]
BAND4 = [(181.1, 61.3), (281.7, 61.3), (281.7, 74.4), (181.1, 74.4)]
AREAS = {1: [RECT1], 2: [RECT2], 3: [OUTER3, HOLE3, ISLAND3], 4: [BAND4]}

HOSTILE = b'Sa"nd, \x1b[31mred\xff;x'
LONG = "Clay, silty, with shells and thin peat layers (Holocene)"


def closed(ring):
    return [list(p) for p in ring + ring[:1]]


def geojson():
    features = []
    for cat, rings in AREAS.items():
        if cat == 3:  # the island as a polygon of its own, same category
            geometry = {"type": "MultiPolygon",
                        "coordinates": [[closed(OUTER3), closed(HOLE3)],
                                        [closed(ISLAND3)]]}
        else:
            geometry = {"type": "Polygon", "coordinates": [closed(r) for r in rings]}
        features.append({"type": "Feature", "properties": {"cat": cat},
                         "geometry": geometry})
    return json.dumps({"type": "FeatureCollection", "features": features})


def inside(rings, x, y):
    """Even-odd over all rings, the rule of v.to.rast at a cell centre."""
    hits = 0
    for ring in rings:
        for (ax, ay), (bx, by) in zip(ring, ring[1:] + ring[:1]):
            if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
                hits += 1
    return hits % 2 == 1


def expected_rows():
    """{(category, class): (volume, cells)} by the model's formula."""
    rows = {}
    for cat, rings in AREAS.items():
        for k in (1, 2):
            volume, cells = 0.0, 0
            for r in range(ROWS):
                for c in range(COLS):
                    if not inside(rings, 5 + 10 * c, 195 - 10 * r):
                        continue
                    n = sum(1 for d in range(1, 2 + (r + c + 2) % 5)
                            if 1 + (r + 1 + d) % 2 == k)
                    volume += n * VOXEL
                    cells += n > 0
            rows[(cat, k)] = (volume, cells)
    return rows


def run(*args, **kwargs):
    return subprocess.run(["r3.sbrt.volume"] + list(args), capture_output=True,
                          timeout=120, **kwargs)


class TestVolumeAreas(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        os.environ["GRASS_OVERWRITE"] = "1"
        gs.run_command("g.region", **REGION)
        gs.mapcalc3d(MODEL)
        env = gs.gisenv()
        cats = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"],
                            "grid3", "geo", "cats")
        with open(cats, "wb") as f:
            f.write(b"# 2 categories\nTest\n\n0.00 0.00 0.00 0.00\n1:" + HOSTILE +
                    b"\n2:" + LONG.encode() + b"\n")
        gs.run_command("r3.sbrt.convert", input="geo", output="geo", quiet=True)
        path = os.path.join(gs.tempdir(), "areas.geojson")
        with open(path, "w") as f:
            f.write(geojson())
        # -o: the XY location has no CRS; v.in.ogr cuts the overlaps into
        # areas of their own whose centroid holds both categories
        gs.run_command("v.in.ogr", flags="o", input=path, output="areas", key="cat",
                       quiet=True)

    def test_each_category_counts_every_cell_its_areas_cover(self):
        expected = expected_rows()
        # the model as r3.mapcalc made it: the formula's voxels
        voxels = int(gs.parse_command("r3.univar", map="geo", flags="g")["n"])
        self.assertEqual(voxels, sum(1 + (r + c + 2) % 5
                                     for r in range(ROWS) for c in range(COLS)))
        out = run("input=geo", "areas=areas", "format=json")
        self.assertEqual(out.returncode, 0, out.stderr)
        rows = json.loads(out.stdout)["volumes"]
        got = {(row["area"], row["classes"][0]): (row["volume"], row["cells"])
               for row in rows}
        self.assertEqual(sorted(got), sorted(expected))
        for key, (volume, cells) in expected.items():
            self.assertGreater(cells, 0, key)
            self.assertEqual(got[key][1], cells, key)
            self.assertAlmostEqual(got[key][0], volume, places=6, msg=key)
        # polygon 2 counts the overlap with 1 (issue 48, item 7): 15 x 13 cells
        self.assertEqual(sum(got[(2, k)][1] > 0 for k in (1, 2)), 2)
        whole = run("input=geo", "areas=areas", "classes=1,2", "format=csv")
        table = list(csv.DictReader(io.StringIO(whole.stdout.decode())))
        self.assertEqual(int(table[1]["area"]), 2)
        self.assertEqual(int(table[1]["cells"]), 15 * 13)

    def test_uncut_overlapping_areas_both_count(self):
        """Boundaries that cross without a node (v.in.ascii, no cleaning):
        two areas that overlap, the cells of the overlap count for both,
        where v.to.rast gives them to one."""
        text = ""
        for cat, ring in ((1, RECT1), (2, RECT2)):
            points = closed(ring)
            text += f"B {len(points)}\n" + "".join(f" {x} {y}\n" for x, y in points)
            # each centroid outside the other area
            x, y = ring[0] if cat == 1 else (ring[2][0] - 2.6, ring[2][1] - 2.6)
            text += f"C 1 1\n {x + 1.3} {y + 1.3}\n 1 {cat}\n"
        gs.write_command("v.in.ascii", input="-", output="uncut", format="standard",
                         flags="n", stdin=text, quiet=True)
        out = run("input=geo", "areas=uncut", "format=json")
        self.assertEqual(out.returncode, 0, out.stderr)
        expected = expected_rows()
        rows = json.loads(out.stdout)["volumes"]
        self.assertEqual([(r["area"], r["classes"]) for r in rows],
                         [(1, [1]), (1, [2]), (2, [1]), (2, [2])])
        for row in rows:
            volume, cells = expected[(row["area"], row["classes"][0])]
            self.assertEqual(row["cells"], cells, row)
            self.assertAlmostEqual(row["volume"], volume, places=6, msg=row)

    def test_full_standard_output_fails(self):
        if not os.path.exists("/dev/full"):
            self.skipTest("no /dev/full")
        for fmt in ("plain", "json", "csv"):
            with open("/dev/full", "w") as full:
                out = subprocess.run(["r3.sbrt.volume", "input=geo", "areas=areas",
                                      f"format={fmt}"], stdout=full,
                                     stderr=subprocess.PIPE, timeout=120)
            self.assertNotEqual(out.returncode, 0, fmt)
            self.assertIn("cannot write to standard output",
                          " ".join(out.stderr.decode().split()).lower())

    def test_region_outside_the_model_warns(self):
        gs.run_command("g.region", n=5000, s=4000, w=3000, e=4000, res=10)
        try:
            out = run("input=geo", "format=json")
        finally:
            gs.run_command("g.region", **REGION)
        self.assertEqual(out.returncode, 0, out.stderr)
        err = " ".join(out.stderr.decode().split())
        self.assertIn("WARNING", err)
        self.assertIn("north 200, south 0, east 300, west 0", err)
        self.assertIn("r3.sbrt.convert -s sbrt=geo", err)
        self.assertTrue(all(row["volume"] == 0 for row in json.loads(out.stdout)["volumes"]))
        # in the model: no warning
        self.assertNotIn("WARNING", run("input=geo").stderr.decode())

    def test_hostile_label_gives_valid_json_csv_and_a_clean_table(self):
        out = run("input=geo", "areas=areas", "classes=1", "format=json")
        self.assertEqual(out.returncode, 0, out.stderr)
        rows = json.loads(out.stdout.decode("utf-8"))["volumes"]  # strict UTF-8
        self.assertEqual(rows[0]["labels"], ['Sa"nd, \x1b[31mred\ufffd;x'])
        out = run("input=geo", "areas=areas", "classes=1", "format=csv")
        self.assertEqual(out.returncode, 0, out.stderr)
        table = list(csv.reader(io.StringIO(out.stdout.decode("utf-8"))))
        self.assertEqual(table[0], ["area", "classes", "labels", "volume", "cells"])
        self.assertEqual(len(table), 5)
        for row in table[1:]:
            self.assertEqual(len(row), 5, row)
            self.assertEqual(row[2], 'Sa"nd, \ufffd[31mred\ufffd;x')
        out = run("input=geo", "areas=areas")
        self.assertEqual(out.returncode, 0, out.stderr)
        text = out.stdout.decode("utf-8")
        self.assertNotIn("\x1b", text)
        self.assertIn(LONG, text)
        # a long label keeps the columns aligned (issue 51, item 6): every
        # row as wide as the header
        lines = text.splitlines()
        self.assertEqual({len(line) for line in lines}, {len(lines[0])}, text)


if __name__ == "__main__":
    test()
