"""
MODULE:    testsuite/test_r3_sbrt_what.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.what against GRASS's own tools: the log of every column
           of a voxel model (caves, an overhang, empty columns, a lens) at
           UTM coordinates equals the voxels that r3.to.rast slices and
           r.what read there, with the heights' unit and datum and depths
           below the surface; property channels voxel by voxel in plain and
           csv only with -v (csv's kind column tells the rows apart); json
           and csv parsed and compared; a horizon
           model's continuous tops equal r.what on the horizons; vector
           points with layer= and where=; bad input fails clearly; hostile
           input (labels with control characters, quotes, commas and bytes
           that are no UTF-8, channel values of +-inf, coordinates of nan
           or inf, layer= no layer, a full standard output) gives valid
           json, csv and plain text or a clear error
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import csv
import io
import json
import os
import re
import struct
import subprocess
import tempfile
import zlib

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

# 8 x 6 cells of 10 m at UTM-size coordinates, 60 voxels of 0.5 m from -20 m
W, N, RES = 500000.0, 5800060.0, 10.0
COLS, ROWS, DEPTHS, BOTTOM, TB = 8, 6, 60, -20.0, 0.5

# bottom up (depth() from 1): classes 1..3 under a sloping surface, a lens
# of 4 in class 2 (row 5), a cave (row 3), an overhang (col 8: nothing in
# the lowest 6 m) and empty columns (col 1, rows 1-2)
VOXELS = (
    "what3d = eval("
    "surface = -2 + 0.5 * col() + row(), "
    "b1 = -15 + 0.5 * col(), b2 = -8 + 0.25 * row(), "
    "cls = 1 + (z() > b1) + (z() > b2), "
    "lens = row() == 5 && depth() >= 15 && depth() <= 18, "
    "cave = row() == 3 && depth() >= 25 && depth() <= 30, "
    "overhang = col() == 8 && depth() <= 12, "
    "hole = col() == 1 && row() <= 2, "
    "if(z() > surface || cave || overhang || hole, null(), if(lens, 4, cls)))"
)
# labels with a comma and quotes: csv must quote them
LABELS = {1: "Gneiss", 2: "Sand, fine", 3: 'Clay "K"', 4: "Peat"}

KEYS = ["point", "x", "y", "cat", "status", "row", "col"]
INTERVAL_KEYS = ["class", "label", "top", "bottom", "thickness"]
# json's and csv's: depths below the surface (the top of the highest layer)
DEPTH_KEYS = ["top_depth", "bottom_depth"]
# the heights' unit and vertical datum, on each json point and csv row
DATUM_KEYS = ["elevation_unit", "vertical_datum"]


def cell_centres():
    """The centre of every cell, row by row from the north."""
    return [
        (W + (c + 0.5) * RES, N - (r + 0.5) * RES)
        for r in range(ROWS)
        for c in range(COLS)
    ]


def reference_log(values):
    """Layers (class, top, bottom), top to bottom, of a column given as
    its voxel values bottom up (None: null), read voxel by voxel: runs of
    one class; nulls (caves, air) are no layer."""
    layers = []
    previous = None
    for z in range(DEPTHS - 1, -1, -1):
        value = values[z]
        if value is not None and value == previous:
            layers[-1][2] = BOTTOM + z * TB
        elif value is not None:
            layers.append([value, BOTTOM + (z + 1) * TB, BOTTOM + z * TB])
        previous = value
    return [tuple(layer) for layer in layers]


def write_cats(name, labels):
    """Labels of 3D raster `name` in GRASS's cats format (8.2 has no
    module that writes a 3D raster's labels)."""
    env = gs.gisenv()
    path = os.path.join(
        env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], "grid3", name, "cats"
    )
    with open(path, "w") as f:
        f.write(f"# {len(labels)} categories\nwhat\n\n0.00 0.00 0.00 0.00\n")
        for k, label in labels.items():
            f.write(f"{k}:{label}\n")


def what_args(flags="", **options):
    return ["r3.sbrt.what"] + (["-" + flags] if flags else []) + [
        f"{k}={','.join(map(str, v)) if isinstance(v, (list, tuple)) else v}"
        for k, v in options.items()
    ]


def what(flags="", **options):
    """r3.sbrt.what's return code, standard output and messages."""
    run = subprocess.run(what_args(flags, **options), capture_output=True, text=True,
                         timeout=120)
    # GRASS wraps its messages: one space between words
    return run.returncode, run.stdout, " ".join(run.stderr.split())


def what_bytes(flags="", **options):
    """r3.sbrt.what's return code, standard output as bytes, messages."""
    run = subprocess.run(what_args(flags, **options), capture_output=True, timeout=120)
    return run.returncode, run.stdout, " ".join(run.stderr.decode(errors="replace").split())


def strict_json(data):
    """bytes parsed as RFC 8259 asks: valid UTF-8, no NaN or Infinity
    (which Python's json takes by default)."""
    def refuse(constant):
        raise ValueError(f"{constant} is no JSON")
    return json.loads(data.decode("utf-8"), parse_constant=refuse)


def patch_first_channel(path, scale=None, offset=None):
    """Sets the scale and offset of the first channel of an SBRT's channels
    member (lib/sbrt/format/channels_file.cpp: a 64-byte header, the
    directory at dir_at with each channel's name, long name and unit, then
    scale and offset as f64) and its checksums: a channel as another
    mapset may hold it, which r3.sbrt.convert would not write."""
    with open(path, "rb") as f:
        data = bytearray(f.read())
    dir_at = struct.unpack_from("<Q", data, 32)[0]
    at = dir_at
    for _ in range(3):  # name, long name, unit: u32 length and bytes
        at += 4 + struct.unpack_from("<I", data, at)[0]
    if scale is not None:
        struct.pack_into("<d", data, at, scale)
    if offset is not None:
        struct.pack_into("<d", data, at + 8, offset)
    struct.pack_into("<I", data, 48, zlib.crc32(data[dir_at:]))
    struct.pack_into("<I", data, 60, zlib.crc32(data[:60]))
    with open(path, "wb") as f:
        f.write(data)


# C0 but line feed, DEL and C1: what may drive a terminal
CONTROL = re.compile("[\x00-\x09\x0b-\x1f\x7f-\x9f]")


def flat(points):
    return [v for p in points for v in p]


class TestWhatVoxelModel(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule(
            "g.region", n=N, s=N - ROWS * RES, w=W, e=W + COLS * RES,
            b=BOTTOM, t=BOTTOM + DEPTHS * TB, res=RES, res3=RES, tbres=TB,
        )
        cls.runModule("r3.mapcalc", expression=VOXELS, overwrite=True)
        write_cats("what3d", LABELS)
        gs.run_command("r3.sbrt.convert", input="what3d", output="what3d", overwrite=True)
        # GRASS's own reading of the voxels: a raster per level (sl_00001
        # the lowest), r.what at every cell centre
        cls.runModule("r3.to.rast", input="what3d", output="sl", overwrite=True)
        levels = [f"sl_{z:05d}" for z in range(1, DEPTHS + 1)]
        cls.voxels = []
        text = gs.read_command(
            "r.what", map=levels, coordinates=flat(cell_centres()), separator="|"
        )
        for line in text.splitlines():
            fields = line.split("|")[3:]
            cls.voxels.append([None if v == "*" else int(float(v)) for v in fields])
        # points as vector points, with a table
        rows = "\n".join(
            f"{k}|{x}|{y}|{'odd' if k % 2 else 'even'}"
            for k, (x, y) in enumerate(cell_centres()[:10], start=1)
        )
        gs.write_command(
            "v.in.ascii", input="-", stdin=rows, output="what_pts", x=2, y=3, cat=1,
            columns="cat integer, x double precision, y double precision, kind varchar(8)",
            quiet=True, overwrite=True,
        )
        cls.runModule("v.mkgrid", map="what_areas", grid=[2, 2], overwrite=True)

    @classmethod
    def tearDownClass(cls):
        cls.runModule("g.remove", flags="f", type="raster_3d", name="what3d")
        cls.runModule("g.remove", flags="f", type="raster", pattern="sl_*")
        cls.runModule("g.remove", flags="f", type="vector", name="what_pts,what_areas")
        cls.runModule("r3.sbrt.manage", flags="f", remove="what3d")
        cls.del_temp_region()

    def json_logs(self, **options):
        rc, out, err = what(input="what3d", format="json", **options)
        self.assertEqual(rc, 0, err)
        return json.loads(out)

    def test_every_column_equals_the_voxels(self):
        self.assertEqual(len(self.voxels), ROWS * COLS)
        points = self.json_logs(coordinates=flat(cell_centres()))
        self.assertEqual(len(points), ROWS * COLS)
        statuses = {"ok": 0, "empty": 0}
        for k, (point, values) in enumerate(zip(points, self.voxels)):
            self.assertEqual(len(values), DEPTHS)
            ref = reference_log(values)
            self.assertEqual(list(point.keys()),
                             KEYS + DATUM_KEYS + ["surface", "intervals"])
            # an XY location, a model without a datum
            self.assertEqual((point["elevation_unit"], point["vertical_datum"]),
                             ("map units", None))
            surface = ref[0][1] if ref else None
            self.assertEqual(point["surface"], surface)
            self.assertEqual(point["point"], k + 1)
            self.assertEqual((point["row"], point["col"]), (k // COLS, k % COLS))
            self.assertEqual(point["status"], "ok" if ref else "empty")
            statuses[point["status"]] += 1
            got = point["intervals"]
            self.assertEqual(len(got), len(ref), f"point {k + 1}: {got} != {ref}")
            for interval, (cls_, top, bottom) in zip(got, ref):
                self.assertEqual(list(interval.keys()), INTERVAL_KEYS + DEPTH_KEYS)
                self.assertEqual(interval["class"], cls_, f"point {k + 1}")
                self.assertEqual(interval["label"], LABELS[cls_])
                self.assertAlmostEqual(interval["top"], top, places=9)
                self.assertAlmostEqual(interval["bottom"], bottom, places=9)
                self.assertAlmostEqual(interval["thickness"], top - bottom, places=9)
                self.assertAlmostEqual(interval["top_depth"], surface - top, places=9)
                self.assertAlmostEqual(interval["bottom_depth"], surface - bottom, places=9)
        self.assertEqual(statuses["empty"], 2)

    def test_columns_are_read_paged_within_memory(self):
        """An SBRT without channels is paged: a column's block is decoded
        when it is read, and memory= holds this process with the blocks;
        a memory= too small is refused with the least that works, and
        nothing is written."""
        points = flat(cell_centres())
        run = subprocess.run(
            what_args(input="what3d", format="json", coordinates=points) + ["--verbose"],
            capture_output=True, text=True, timeout=120)
        out, err = run.stdout, " ".join(run.stderr.split())
        self.assertEqual(run.returncode, 0, err)
        self.assertIn("SBRT <what3d> paged", err)
        self.assertIn("Paged model: 1 of the 1 blocks decoded", err)
        self.assertEqual(json.loads(out), self.json_logs(coordinates=points))
        output = os.path.join(tempfile.mkdtemp(), "logs.json")
        rc, out, err = what(input="what3d", format="json", coordinates=points,
                            output=output, memory=1)
        self.assertNotEqual(rc, 0)
        least = re.search(r"give memory= at least (\d+)", err)
        self.assertTrue(least, err)
        self.assertFalse(os.path.exists(output))
        rc, out, err = what(input="what3d", format="json", coordinates=points,
                            memory=int(least.group(1)) + 20)
        self.assertEqual(rc, 0, err)
        self.assertEqual(json.loads(out), self.json_logs(coordinates=points))

    def test_plain_log_shows_gaps_and_empty_and_outside(self):
        # row 3 (index 2) col 4: a cave; row 1 col 1: empty; far away: outside
        cave = cell_centres()[2 * COLS + 3]
        empty = cell_centres()[0]
        rc, out, err = what(input="what3d", coordinates=flat([cave, empty, (0, 0)]))
        self.assertEqual(rc, 0, err)
        blocks = out.split("\n\n")
        self.assertEqual(len(blocks), 3)
        self.assertIn("row 2, col 3", blocks[0])
        # the heights' unit and datum (an XY location, a model without one)
        # and the surface the depths are measured from
        lines = blocks[0].splitlines()
        ref = reference_log(self.voxels[2 * COLS + 3])
        surface = ref[0][1]
        self.assertRegex(lines[0], r"from [-\d.]+ down to [-\d.]+ map units$")
        self.assertEqual(lines[1], "Elevations in map units (no vertical datum); depths "
                         f"below the surface at {surface:.3f} map units (the top of the "
                         "highest layer)")
        self.assertEqual(lines[2].split(), ["top", "bottom", "thickness", "top", "depth",
                                            "bottom", "depth", "class", "label"])
        self.assertIn("(gap)", blocks[0])
        self.assertIn("1 gap", blocks[0])
        self.assertIn("empty (no layers)", blocks[1])
        self.assertIn("outside the model", blocks[2])
        # the gap runs from the bottom of the layer above it to the top of
        # the layer below: voxels 25..30 (depth() from 1) are the cave
        gap = [line for line in blocks[0].splitlines() if "(gap)" in line][0]
        top, bottom, thickness, top_depth, bottom_depth = map(float, gap.split()[:5])
        self.assertEqual((top, bottom), (BOTTOM + 30 * TB, BOTTOM + 24 * TB))
        self.assertEqual(thickness, 3.0)
        self.assertEqual((top_depth, bottom_depth), (surface - top, surface - bottom))
        # the layers of the plain log are the json's, top to bottom, each
        # with the depths of its top and bottom
        layers = [line.split() for line in lines[3:] if "(gap)" not in line]
        self.assertEqual([int(f[5]) for f in layers], [r[0] for r in ref])
        self.assertEqual([float(f[0]) for f in layers], [r[1] for r in ref])
        self.assertEqual([(float(f[3]), float(f[4])) for f in layers],
                         [(surface - r[1], surface - r[2]) for r in ref])

    def test_csv_has_a_row_per_layer_with_the_json_keys(self):
        coords = flat(cell_centres()[:16] + [(0, 0)])
        rc, out, err = what(input="what3d", coordinates=coords, format="csv")
        self.assertEqual(rc, 0, err)
        rows = list(csv.DictReader(io.StringIO(out)))
        self.assertEqual(list(rows[0].keys()), KEYS + INTERVAL_KEYS + DEPTH_KEYS + DATUM_KEYS)
        self.assertEqual({(r["elevation_unit"], r["vertical_datum"]) for r in rows},
                         {("map units", "")})
        points = self.json_logs(coordinates=coords)
        expected = []
        for p in points:
            head = [str(p["point"]), p["status"]]
            if not p["intervals"]:
                expected.append(head + ["", "", "", "", "", ""])
            for i in p["intervals"]:
                expected.append(head + [str(i["class"]), i["label"], i["top"], i["bottom"],
                                        i["top_depth"], i["bottom_depth"]])
        number = lambda text: float(text) if text else ""  # noqa: E731
        got = [
            [r["point"], r["status"], r["class"], r["label"], number(r["top"]),
             number(r["bottom"]), number(r["top_depth"]), number(r["bottom_depth"])]
            for r in rows
        ]
        self.assertEqual(got, expected)
        self.assertEqual(rows[-1]["status"], "outside")
        self.assertEqual(rows[-1]["row"], "")
        self.assertIn('"Sand, fine"', out)  # quoted: it holds a comma

    def test_channels_voxel_by_voxel(self):
        """With property channels (3D raster maps beside the classes), every
        voxel of a column's solid span, top down, with its class (null in a
        cave) and each channel's value (null where the map is) equal to
        what r3.to.rast and r.what read; csv has the same voxel rows, plain
        a voxel table."""
        prop = ("whatp = float(if(depth() % 13 == 0, null(), "
                "(row() * 7 + col() * 3 + depth()) % 50 - 10))")
        self.runModule("r3.mapcalc", expression=prop, overwrite=True)
        self.runModule("r3.support", map="whatp", unit="%", title="P(peat)")
        self.assertModule("r3.sbrt.convert", input="what3d", properties="whatp",
                          output="what3dp")
        self.runModule("r3.to.rast", input="whatp", output="pp", overwrite=True)
        levels = [f"pp_{z:05d}" for z in range(1, DEPTHS + 1)]
        text = gs.read_command("r.what", map=levels, coordinates=flat(cell_centres()),
                               separator="|")
        props = [[None if v == "*" else float(v) for v in line.split("|")[3:]]
                 for line in text.splitlines()]
        rc, out, err = what(input="what3dp", format="json",
                            coordinates=flat(cell_centres()))
        self.assertEqual(rc, 0, err)
        points = json.loads(out)
        checked = 0
        for k, (point, classes, values) in enumerate(zip(points, self.voxels, props)):
            solid = [z for z in range(DEPTHS) if classes[z] is not None]
            span = range(max(solid), min(solid) - 1, -1) if solid else []
            self.assertEqual([v["level"] for v in point["voxels"]], list(span),
                             f"point {k + 1}")
            for voxel in point["voxels"]:
                z = voxel["level"]
                self.assertEqual(voxel["class"], classes[z])
                self.assertEqual(voxel["values"]["whatp"], values[z], (k, z))
                self.assertAlmostEqual(voxel["bottom"], BOTTOM + z * TB, places=9)
                self.assertAlmostEqual(voxel["top"], BOTTOM + (z + 1) * TB, places=9)
                checked += 1
        self.assertGreater(checked, 500)
        # the cave of row 3 has values, no class
        cave = points[2 * COLS + 3]["voxels"]
        self.assertIn(None, [v["class"] for v in cave])
        # the voxels' depths below the column's surface
        surface = points[2 * COLS + 3]["surface"]
        self.assertEqual([(v["top_depth"], v["bottom_depth"]) for v in cave],
                         [(surface - v["top"], surface - v["bottom"]) for v in cave])
        # csv without -v: the layer rows alone, one kind of row
        one = flat(cell_centres()[2 * COLS + 3:2 * COLS + 4])
        layer_count = len(reference_log(self.voxels[2 * COLS + 3]))
        rc, out, err = what(input="what3dp", format="csv", coordinates=one)
        self.assertEqual(rc, 0, err)
        rows = list(csv.DictReader(io.StringIO(out)))
        self.assertEqual(list(rows[0].keys()), KEYS + INTERVAL_KEYS + DEPTH_KEYS + DATUM_KEYS)
        self.assertEqual(len(rows), layer_count)
        # csv with -v: the layer rows, then a row per voxel, told by "kind"
        rc, out, err = what("v", input="what3dp", format="csv", coordinates=one)
        self.assertEqual(rc, 0, err)
        rows = list(csv.DictReader(io.StringIO(out)))
        self.assertEqual(list(rows[0].keys()), KEYS + INTERVAL_KEYS + DEPTH_KEYS + DATUM_KEYS
                         + ["kind", "level", "whatp"])
        self.assertEqual([r["kind"] for r in rows],
                         ["layer"] * layer_count + ["voxel"] * len(cave))
        voxel_rows = [r for r in rows if r["kind"] == "voxel"]
        self.assertTrue(all(r["level"] for r in voxel_rows))
        self.assertFalse(any(r["level"] or r["whatp"] for r in rows if r["kind"] == "layer"))
        self.assertEqual([int(r["level"]) for r in voxel_rows],
                         [v["level"] for v in cave])
        self.assertEqual([float(r["whatp"]) if r["whatp"] else None for r in voxel_rows],
                         [v["values"]["whatp"] for v in cave])
        self.assertEqual([float(r["top_depth"]) for r in voxel_rows],
                         [v["top_depth"] for v in cave])
        # plain without -v: the layers alone
        rc, out, err = what(input="what3dp", coordinates=one)
        self.assertEqual(rc, 0, err)
        self.assertNotIn("Voxels", out)
        self.assertEqual(len(out.splitlines()), 3 + layer_count + 1)  # and a gap
        # plain with -v: a voxel table with the channel's name, * for no value
        rc, out, err = what("v", input="what3dp", coordinates=one)
        self.assertIn("Voxels with their property channels", out)
        table = out.split("Voxels with their property channels, top down:\n")[1]
        lines = table.splitlines()
        self.assertEqual(lines[0].split(), ["top", "bottom", "class", "whatp"])
        self.assertEqual(len(lines) - 1, len(cave))
        self.runModule("r3.sbrt.manage", flags="f", remove="what3dp")

    def test_vector_points_with_where_and_output_file(self):
        points = self.json_logs(points="what_pts", where="kind = 'odd'")
        self.assertEqual([p["cat"] for p in points], [1, 3, 5, 7, 9])
        # layer= by its name (v.in.ascii names layer 1 after the map)
        self.assertEqual(self.json_logs(points="what_pts", layer="what_pts",
                                        where="kind = 'odd'"), points)
        by_coords = self.json_logs(coordinates=flat(cell_centres()[0:10:2]))
        for a, b in zip(points, by_coords):
            self.assertEqual(a["intervals"], b["intervals"])
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "logs.csv")
            self.assertModule("r3.sbrt.what", input="what3d", points="what_pts",
                              format="csv", output=path)
            with open(path) as f:
                rows = list(csv.DictReader(f))
        self.assertEqual(sorted({int(r["cat"]) for r in rows}), list(range(1, 11)))

    def test_bad_input_fails_clearly(self):
        rc, _, err = what(input="what3d", points="what_areas")
        self.assertNotEqual(rc, 0)
        self.assertIn("needs a vector map of points", err)
        rc, _, err = what(input="what3d", points="no_such_points")
        self.assertNotEqual(rc, 0)
        self.assertIn("<no_such_points> not found", err)
        rc, _, err = what(input="no_such_sbrt", coordinates=[W, N])
        self.assertNotEqual(rc, 0)
        self.assertIn("<no_such_sbrt>", err)
        rc, _, err = what(input="what3d", coordinates=[W + 1, N - 1, W + 2])
        self.assertNotEqual(rc, 0)
        self.assertIn("multiples of 2", err)
        self.assertModuleFail("r3.sbrt.what", input="what3d")
        self.assertModuleFail(
            "r3.sbrt.what", input="what3d", coordinates=[W + 1, N - 1], points="what_pts"
        )
        rc, _, err = what(input="what3d", coordinates=[W + 1, N - 1], format="xml")
        self.assertNotEqual(rc, 0)
        self.assertIn("format", err)


class TestWhatHostileInput(TestCase):
    """What another mapset's SBRT or a careless request may hold: labels
    with control characters, quotes, a comma and a byte that is no UTF-8,
    a channel of +-inf, coordinates of nan or inf, a layer that is none; a
    standard output that takes nothing."""

    # written into the SBRT's cats member as bytes: ESC [31m would turn a
    # terminal red, \r return to the line's start, \xff is no UTF-8, \xc2\x9b
    # is C1's CSI
    HOSTILE = b'ctrl\x01\x1b[31mred, "q" \r\xff\x7f\xc2\x9b end'
    # the label as valid UTF-8 (what json gives back): \xff is U+FFFD
    HOSTILE_TEXT = 'ctrl\x01\x1b[31mred, "q" \r\ufffd\x7f\x9b end'
    # the label printable (plain and csv): every control character U+FFFD
    HOSTILE_PRINTABLE = CONTROL.sub("\ufffd", HOSTILE_TEXT)

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=60, s=0, w=0, e=40, b=-20, t=10, res=10, res3=10,
                      tbres=5)
        cls.runModule("r3.mapcalc", expression="hostile = 1 + (z() > -5) + (z() > 5)",
                      overwrite=True)
        # 2, -2 and 0.5 by column: times a scale of 1e308 (patched in,
        # r3.sbrt.convert refuses such a channel) +inf, -inf and 5e307
        cls.runModule("r3.mapcalc", overwrite=True, expression=(
            "hostile_p = float(if(col() == 1, 2, if(col() == 2, -2, 0.5)))"))
        gs.run_command("r3.sbrt.convert", input="hostile", properties="hostile_p",
                       output="hostile", overwrite=True, quiet=True)
        env = gs.gisenv()
        cls.sbrt_dir = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"],
                                    "sbrt", "hostile")
        patch_first_channel(os.path.join(cls.sbrt_dir, "channels"), scale=1e308)
        with open(os.path.join(cls.sbrt_dir, "cats"), "wb") as f:
            f.write(b"1:Sand, fine\n2:" + cls.HOSTILE + b"\n3:Clay\n")
        gs.write_command("v.in.ascii", input="-", stdin="1|5|55\n2|nan|45\n",
                         output="hostile_nan", x=2, y=3, cat=1, quiet=True, overwrite=True)

    @classmethod
    def tearDownClass(cls):
        cls.runModule("g.remove", flags="f", type="raster_3d", name="hostile,hostile_p")
        cls.runModule("g.remove", flags="f", type="vector", name="hostile_nan")
        cls.runModule("r3.sbrt.manage", flags="f", remove="hostile")
        cls.del_temp_region()

    def test_hostile_label_gives_valid_json_csv_and_plain(self):
        # column 3: a finite channel value; classes 3, 2, 1 from the top
        coords = [25, 55]
        rc, out, err = what_bytes(input="hostile", coordinates=coords, format="json")
        self.assertEqual(rc, 0, err)
        points = strict_json(out)
        # control characters (C0, DEL, C1) escaped: none raw in the output
        self.assertIsNone(CONTROL.search(out.decode("utf-8")), out)
        labels = [i["label"] for i in points[0]["intervals"]]
        self.assertEqual(labels, ["Clay", self.HOSTILE_TEXT, "Sand, fine"])
        rc, out, err = what_bytes(input="hostile", coordinates=coords, format="csv")
        self.assertEqual(rc, 0, err)
        text = out.decode("utf-8")
        self.assertIsNone(CONTROL.search(text), text)
        rows = list(csv.DictReader(io.StringIO(text, newline="")))
        layer_rows = [r for r in rows if r["point"] == "1"]
        self.assertEqual([r["label"] for r in layer_rows],
                         ["Clay", self.HOSTILE_PRINTABLE, "Sand, fine"])
        rc, out, err = what_bytes(input="hostile", coordinates=coords)
        self.assertEqual(rc, 0, err)
        text = out.decode("utf-8")
        self.assertIsNone(CONTROL.search(text), text)
        self.assertIn(self.HOSTILE_PRINTABLE, text)

    def test_infinite_channel_values_are_null_and_empty(self):
        coords = [5, 55, 15, 55, 25, 55]
        rc, out, err = what_bytes(input="hostile", coordinates=coords, format="json")
        self.assertEqual(rc, 0, err)
        points = strict_json(out)
        values = [{v["values"]["hostile_p"] for v in p["voxels"]} for p in points]
        self.assertEqual(values, [{None}, {None}, {5e307}])
        rc, out, err = what_bytes("v", input="hostile", coordinates=coords, format="csv")
        self.assertEqual(rc, 0, err)
        rows = [r for r in csv.DictReader(io.StringIO(out.decode("utf-8")))
                if r["kind"] == "voxel"]
        by_point = {}
        for r in rows:
            by_point.setdefault(r["point"], set()).add(r["hostile_p"])
        self.assertEqual(by_point, {"1": {""}, "2": {""}, "3": {"5e+307"}})
        # add_offset = Infinity: every value none, or the channel refused
        patch_first_channel(os.path.join(self.sbrt_dir, "channels"), scale=1.0,
                            offset=float("inf"))
        try:
            rc, out, err = what_bytes(input="hostile", coordinates=coords, format="json")
        finally:
            patch_first_channel(os.path.join(self.sbrt_dir, "channels"), scale=1e308,
                                offset=0.0)
        if rc == 0:
            values = {v["values"]["hostile_p"] for p in strict_json(out) for v in p["voxels"]}
            self.assertEqual(values, {None})
        else:
            self.assertIn("ERROR:", err)

    def test_non_finite_coordinates_are_refused(self):
        for coords in (["nan", "nan"], ["inf", 45], [5, 55, "-inf", 45]):
            for fmt in ("json", "csv", "plain"):
                rc, out, err = what(input="hostile", coordinates=coords, format=fmt)
                self.assertNotEqual(rc, 0, (coords, out))
                self.assertIn("coordinates=: point", err)
                self.assertIn("not a position", err)
        rc, out, err = what(input="hostile", points="hostile_nan", format="json")
        self.assertNotEqual(rc, 0, out)
        self.assertIn("points=hostile_nan: point 2 (cat 2)", err)

    def test_layer_that_is_none_fails(self):
        rc, out, err = what(input="hostile", points="hostile_nan", layer="abc",
                            where="cat = 1")
        self.assertNotEqual(rc, 0, out)
        rc, out, err = what(input="hostile", points="hostile_nan", layer="abc")
        self.assertNotEqual(rc, 0, out)
        self.assertIn("layer=abc", err)
        self.assertIn("no layer of that name", err)

    def test_full_standard_output_fails(self):
        if not os.path.exists("/dev/full"):
            self.skipTest("no /dev/full")
        for fmt in ("json", "csv", "plain"):
            with open("/dev/full", "w") as full:
                run = subprocess.run(
                    what_args(input="hostile", coordinates=[5, 55], format=fmt),
                    stdout=full, stderr=subprocess.PIPE, text=True, timeout=120)
            self.assertNotEqual(run.returncode, 0, fmt)
            self.assertIn("Cannot write to standard output: No space left on device",
                          " ".join(run.stderr.split()))


class TestWhatHorizonModel(TestCase):
    """Continuous tops: the log of a horizon model gives the horizons'
    heights, not voxel levels."""

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule(
            "g.region", n=N, s=N - ROWS * RES, w=W, e=W + COLS * RES,
            b=BOTTOM, t=BOTTOM + DEPTHS * TB, res=RES, res3=RES, tbres=TB,
        )
        cls.runModule("r.mapcalc", expression="what_h1 = 5.3 + 0.37 * col() + 0.11 * row()",
                      overwrite=True)
        cls.runModule("r.mapcalc", expression="what_h2 = if(col() == 2, null(), "
                      "-7.77 - 0.029 * col() * row())", overwrite=True)
        gs.run_command(
            "r3.sbrt.convert", horizons="what_h1,what_h2", materials=[21, 22],
            bottom=-17.123, output="what_hz", overwrite=True,
        )

    @classmethod
    def tearDownClass(cls):
        cls.runModule("g.remove", flags="f", type="raster", name="what_h1,what_h2")
        cls.runModule("r3.sbrt.manage", flags="f", remove="what_hz")
        cls.del_temp_region()

    def test_tops_are_the_horizons(self):
        centres = cell_centres()
        text = gs.read_command(
            "r.what", map="what_h1,what_h2", coordinates=flat(centres), separator="|"
        )
        rc, out, err = what(input="what_hz", coordinates=flat(centres), format="json")
        self.assertEqual(rc, 0, err)
        points = json.loads(out)
        off_levels = 0
        for line, point in zip(text.splitlines(), points):
            h1, h2 = (None if v == "*" else float(v) for v in line.split("|")[3:])
            ref = [(21, h1)] + ([(22, h2)] if h2 is not None else [])
            got = point["intervals"]
            self.assertEqual([i["class"] for i in got], [r[0] for r in ref])
            bottoms = [r[1] for r in ref[1:]] + [-17.123]
            for i, (_, top), bottom in zip(got, ref, bottoms):
                # float32 local heights: a few micrometres over 30 m
                self.assertAlmostEqual(i["top"], top, delta=1e-5)
                self.assertAlmostEqual(i["bottom"], bottom, delta=1e-5)
                off_levels += abs(i["top"] / TB - round(i["top"] / TB)) > 1e-3
        self.assertEqual(len(points), ROWS * COLS)
        self.assertGreater(off_levels, ROWS * COLS)


if __name__ == "__main__":
    test()
