"""
MODULE:    testsuite/test_r3_sbrt_profile.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.profile against GRASS's own reading of the voxels
           (r3.to.rast slices, r.what at every cell centre): the class
           profile map along a three-vertex line cell by cell, its window
           (distance by elevation, a row per layer), labels and colours;
           the figure's plot pixel by pixel, its ticks where the axes put
           them; the same line from a vector map; a line of 60 vertices
           (titles inside the image, every k-th vertex lettered); the
           vertical datum of a GeoTOP-like file on the elevation axis; bad
           input
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import math
import os
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs
from PIL import Image

from geomodel_fixture import run_in_new_location
from shell_output import shell_values
from test_r3_sbrt_what import write_cats

HERE = os.path.dirname(os.path.abspath(__file__))
GEOTOP_LIKE = os.path.join(HERE, "..", "benchmarks", "geotop_like")

# 30 x 20 cells of 10 m at UTM-size coordinates, 40 voxels of 2 m from -40 m
W, S, RES = 450000.0, 5800000.0, 10.0
COLS, ROWS, DEPTHS, BOTTOM, TB = 30, 20, 40, -40.0, 2.0
N = S + ROWS * RES

# classes 1..5 in bands dipping east and north under an uneven surface,
# a cave, and empty columns in the south-east corner
VOXELS = (
    "prof3d = eval("
    "surface = 10 + 0.6 * col() - 0.9 * row() + 4 * sin(col() * 40), "
    "band = int((z() + 44 + 0.8 * col() + 0.5 * row()) / 7) % 5 + 1, "
    "cave = col() >= 12 && col() <= 15 && depth() >= 10 && depth() <= 12, "
    "hole = col() >= 27 && row() >= 17, "
    "if(z() > surface || cave || hole, null(), band))"
)
LABELS = {1: "Sand", 2: "Clay", 3: "Peat", 4: "Gravel", 5: "Marl"}
# A -> B -> C, the last leg leaving the model through its east edge
LINE = [(W + 13.0, S + 17.0), (W + 155.0, S + 183.0), (W + 317.0, S + 41.0)]


def along(line, d):
    """The map point at distance d along the polyline."""
    for (x0, y0), (x1, y1) in zip(line, line[1:]):
        leg = math.hypot(x1 - x0, y1 - y0)
        if d <= leg:
            return x0 + (x1 - x0) * d / leg, y0 + (y1 - y0) * d / leg
        d -= leg
    return line[-1]


def length(line):
    return sum(math.hypot(x1 - x0, y1 - y0) for (x0, y0), (x1, y1) in zip(line, line[1:]))


def run(*args):
    """A module's return code, standard output and messages (one space
    between words: GRASS wraps them)."""
    done = subprocess.run(list(args), capture_output=True, text=True)
    return done.returncode, done.stdout, " ".join(done.stderr.split())


def numbers(text):
    return [float(v) for v in text.split(",")] if text else []


class TestProfileAgainstVoxels(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=N, s=S, w=W, e=W + COLS * RES, b=BOTTOM,
                      t=BOTTOM + DEPTHS * TB, res=RES, res3=RES, tbres=TB)
        cls.runModule("r3.mapcalc", expression=VOXELS, overwrite=True)
        write_cats("prof3d", LABELS)
        gs.run_command("r3.sbrt.convert", input="prof3d", output="prof3d", overwrite=True)
        # GRASS's reading of the voxels: r.what on every level's slice at
        # every cell centre (sl_00001 the lowest)
        cls.runModule("r3.to.rast", input="prof3d", output="prof_sl", overwrite=True)
        levels = [f"prof_sl_{z:05d}" for z in range(1, DEPTHS + 1)]
        centres = [(W + (c + 0.5) * RES, N - (r + 0.5) * RES)
                   for r in range(ROWS) for c in range(COLS)]
        text = gs.read_command("r.what", map=levels, separator="|",
                               coordinates=[v for p in centres for v in p])
        cls.voxels = {}
        for k, line in enumerate(text.splitlines()):
            values = line.split("|")[3:]
            cls.voxels[divmod(k, COLS)] = [None if v == "*" else int(float(v)) for v in values]
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_profile_")
        # the line as a vector map, after a decoy line of another category
        gs.write_command(
            "v.in.ascii", input="-", format="standard", flags="n", output="prof_lines",
            stdin=f"L 2 1\n {W + 5} {S + 5}\n {W + 50} {S + 50}\n 1 7\n"
                  f"L 3 1\n" + "".join(f" {x} {y}\n" for x, y in LINE) + " 1 9\n",
            quiet=True, overwrite=True)

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        gs.run_command("g.remove", flags="f", type="raster", pattern="prof_*", quiet=True)
        gs.run_command("g.remove", flags="f", type="raster_3d", name="prof3d", quiet=True)
        gs.run_command("g.remove", flags="f", type="vector", name="prof_lines", quiet=True)
        gs.run_command("r3.sbrt.manage", remove="prof3d", flags="f", quiet=True)

    def expected_class(self, x, y, z):
        """The voxel's class at map point (x, y, z), GRASS's cell rule (a
        cell holds its west and north edges); None outside or in air."""
        col, row = math.floor((x - W) / RES), math.floor((N - y) / RES)
        depth = math.floor((z - BOTTOM) / TB)
        if not (0 <= col < COLS and 0 <= row < ROWS and 0 <= depth < DEPTHS):
            return None
        return self.voxels[(row, col)][depth]

    def profile(self, *options):
        code, out, err = run("r3.sbrt.profile", "input=prof3d", "--o", "-g", *options)
        self.assertEqual(code, 0, err)
        return shell_values(out), err

    def coordinates(self, line=LINE):
        return "coordinates=" + ",".join(f"{x},{y}" for x, y in line)

    def test_map_equals_the_voxels_under_the_line(self):
        # (the SBRT is paged: its columns read through their blocks)
        g, err = self.profile(self.coordinates(), "output=prof_map", "resolution=7",
                              "--verbose")
        self.assertIn("SBRT <prof3d> paged", err)
        info = gs.raster_info("prof_map")
        total = length(LINE)
        cols = round(total / 7)
        self.assertAlmostEqual(info["west"], 0)
        self.assertAlmostEqual(info["east"], total, places=6)
        self.assertEqual(int(info["cols"]), cols)
        self.assertAlmostEqual(info["nsres"], TB)  # a row per layer
        self.assertAlmostEqual(float(g["map_east"]), total, places=6)
        # every cell against the voxel under its distance, at its height
        self.runModule("g.region", raster="prof_map")  # the profile's own window
        rows = gs.read_command("r.out.ascii", input="prof_map", flags="h",
                               null_value="*").split("\n")
        south, north = info["south"], info["north"]
        self.assertEqual(int(info["rows"]), round((north - south) / TB))
        seen = set()
        for r in range(int(info["rows"])):
            values = rows[r].split()
            self.assertEqual(len(values), cols)
            z = north - (r + 0.5) * TB
            for c, value in enumerate(values):
                x, y = along(LINE, (c + 0.5) * total / cols)
                expected = self.expected_class(x, y, z)
                got = None if value == "*" else int(value)
                self.assertEqual(got, expected, f"row {r} column {c} ({x}, {y}, {z})")
                seen.add(got)
        self.assertTrue({1, 2, 3, 4, 5, None} <= seen, seen)
        # the rows span the layers the line cuts: the top and bottom rows
        # hold a class somewhere
        self.assertNotEqual(set(rows[0].split()), {"*"})
        self.assertNotEqual(set(rows[int(info["rows"]) - 1].split()), {"*"})
        # labels and colours of the model
        cats = gs.read_command("r.category", map="prof_map", separator="|")
        for k, label in LABELS.items():
            self.assertIn(f"{k}|{label}", cats)
        rules = gs.read_command("r.colors.out", map="prof_map")
        for k in LABELS:
            self.assertRegex(rules, rf"(?m)^{k} \d+:\d+:\d+$")

    def test_vector_line_of_a_category_gives_the_same_map(self):
        self.profile(self.coordinates(), "output=prof_coords")
        _, err = self.profile("line=prof_lines", "cat=9", "output=prof_vector")
        self.runModule("g.region", raster="prof_vector")
        self.assertEqual(
            gs.read_command("r.out.ascii", input="prof_vector", null_value="*"),
            gs.read_command("r.out.ascii", input="prof_coords", null_value="*"))
        # without cat= the first line, with a warning
        g, err = self.profile("line=prof_lines", "output=prof_first")
        self.assertIn("2 lines", err)
        self.assertAlmostEqual(float(g["length"]), math.hypot(45, 45), places=6)

    def test_figure_shows_the_voxels_where_its_axes_say(self):
        png = os.path.join(self.tmp, "profile.png")
        g, err = self.profile(self.coordinates(), f"png={png}", "width=600")
        self.assertIn("fitted to the line", err)
        total = length(LINE)
        left, top = int(g["plot_left"]), int(g["plot_top"])
        width, height = int(g["plot_width"]), int(g["plot_height"])
        bottom_z, top_z = float(g["plot_bottom"]), float(g["plot_top_elevation"])
        self.assertEqual(width, 600)
        # the exaggeration makes the plot's height
        self.assertAlmostEqual(height, (top_z - bottom_z) * float(g["zexag"]) * width / total,
                               delta=1)
        image = Image.open(png).convert("RGB")
        self.assertEqual(image.size, (int(g["figure_width"]), int(g["figure_height"])))
        # the classes' colours, as the profile map carries them
        self.profile(self.coordinates(), "output=prof_colours")
        colours = {}
        for line in gs.read_command("r.colors.out", map="prof_colours").splitlines():
            value, _, rgb = line.partition(" ")
            if value.isdigit():
                colours[int(value)] = tuple(int(v) for v in rgb.split(":"))
        # every plot pixel (but the dashed line at the bend) is its voxel's colour
        bend = round(left + float(numbers(g["vertex_distances"])[1]) / total * width)
        cut = set()
        wrong = 0
        for py in range(height):
            z = top_z - (py + 0.5) / height * (top_z - bottom_z)
            for px in range(width):
                if abs(left + px - bend) <= 1:
                    continue
                x, y = along(LINE, (px + 0.5) / width * total)
                expected = self.expected_class(x, y, z)
                cut.add(expected)
                want = (255, 255, 255) if expected is None else colours[expected]
                wrong += image.getpixel((left + px, top + py)) != want
        self.assertEqual(wrong, 0)
        self.assertEqual(numbers(g["classes_cut"]), sorted(c for c in cut if c is not None))
        # ticks: round numbers inside the axes, marked where the axes put them
        ticks = numbers(g["elevation_ticks"])
        step = ticks[1] - ticks[0]
        self.assertEqual(ticks[0], bottom_z)
        self.assertEqual(ticks[-1], top_z)
        tick_rows = numbers(g["elevation_tick_rows"])
        for t, row in zip(ticks, tick_rows, strict=True):
            self.assertAlmostEqual(t / step, round(t / step))
            y = round(top + (top_z - t) / (top_z - bottom_z) * height)
            self.assertEqual(row, y, f"elevation tick {t}")  # its label's row
            self.assertEqual(image.getpixel((left - 3, y)), (0, 0, 0), f"elevation tick {t}")
            self.assertNotEqual(image.getpixel((left - 3, y + 2)), (0, 0, 0))
        distances = numbers(g["distance_ticks"])
        self.assertEqual(distances[0], 0)
        self.assertLessEqual(distances[-1], total)
        tick_columns = numbers(g["distance_tick_columns"])
        for t, column in zip(distances, tick_columns, strict=True):
            x = round(left + t / total * width)
            self.assertEqual(column, x, f"distance tick {t}")  # its label's column
            self.assertEqual(image.getpixel((x, top + height + 3)), (0, 0, 0), f"distance tick {t}")
        # the layers under the line lie inside the plot
        self.assertLessEqual(bottom_z, BOTTOM + TB * min(
            d for col in self.voxels.values() for d, v in enumerate(col) if v is not None))
        units = "map units" if int(gs.region()["projection"]) == 0 else "m"
        self.assertEqual(g["elevation_title"], f"Elevation ({units})")
        self.assertEqual(g["distance_title"], f"Distance along A\u2013B\u2013C ({units})")
        self.assertEqual(g["title"], "Profile A\u2013B\u2013C of prof3d")
        self.assertEqual(g["lettered_vertices"], "0,1,2")

    def test_many_vertices_fit_the_figure(self):
        """A line of 60 vertices (a zigzag across the model): the titles
        name it by its ends and stay inside the image (no dark pixel on its
        left or right edge), and only every k-th vertex is lettered (the
        first and the last always), the letters apart on the plot's edge."""
        line = [(W + 5 + k * 4.9, S + (30 if k % 2 == 0 else 170)) for k in range(60)]
        png = os.path.join(self.tmp, "zigzag.png")
        g, _ = self.profile(self.coordinates(line), f"png={png}")
        self.assertEqual(g["title"], "Profile A\u2013\u2026\u2013H2 of prof3d")
        self.assertTrue(g["distance_title"].startswith("Distance along A\u2013\u2026\u2013H2 ("),
                        g["distance_title"])
        image = Image.open(png).convert("L")
        width, height = image.size
        for x in (0, width - 1):
            dark = [y for y in range(height) if image.getpixel((x, y)) < 128]
            self.assertEqual(dark, [], f"dark pixels on column {x}: text runs off")
        lettered = [int(v) for v in g["lettered_vertices"].split(",")]
        self.assertEqual((lettered[0], lettered[-1]), (0, 59))
        step = lettered[1] - lettered[0]
        self.assertGreater(step, 1)
        self.assertEqual(lettered[:-1], list(range(0, 59, step))[:len(lettered) - 1])
        distances = numbers(g["vertex_distances"])
        left, plot_width = int(g["plot_left"]), int(g["plot_width"])
        columns = [left + distances[k] / distances[-1] * plot_width for k in lettered]
        gaps = [b - a for a, b in zip(columns, columns[1:])]
        self.assertGreaterEqual(min(gaps), 20, gaps)  # two letters of a 13-pixel font

    def test_bad_input_fails_clearly(self):
        far = [(W + 5000, S + 5000), (W + 6000, S + 6000)]
        for options, message in [
            ((self.coordinates(far), "output=prof_bad"), "meets no layer"),
            (("coordinates=450010,5800010,450010,5800010", "output=prof_bad"),
             "two distinct points"),
            (("line=prof_lines", "cat=4", "output=prof_bad"), "no line of category 4"),
            ((self.coordinates(), "png=/tmp/x.png", "zexag=100000"), "pixels high"),
            ((self.coordinates(), "output=prof_bad", "resolution=0"), "above 0"),
            ((self.coordinates(), "output=prof_bad", "resolution=0.00001"), "resolution="),
            # memory= holds the process too: 1 MB is below any
            ((self.coordinates(), "output=prof_bad", "memory=1"), "give memory= at least"),
        ]:
            code, _, err = run("r3.sbrt.profile", "input=prof3d", "--o", *options)
            self.assertNotEqual(code, 0, options)
            self.assertIn(message, err, options)
            self.assertNotIn("Traceback", err)
        self.assertFalse(gs.find_file("prof_bad", element="cell")["name"])


class TestProfileOfAGeotopFile(TestCase):
    def test_datum_labels_the_elevation_axis(self):
        tmp = tempfile.mkdtemp(prefix="sbrt_profile_gt_")
        subprocess.run(["make", "-s", "-C", GEOTOP_LIKE, "build/geotop_like"], check=True)
        path = os.path.join(tmp, "geotop_like.nc")
        subprocess.run([os.path.join(GEOTOP_LIKE, "build", "geotop_like"), "write", path,
                        "24", "18", "60"], check=True)
        png = os.path.join(tmp, "gt.png")
        code, message = run_in_new_location("EPSG:28992", [
            "bash", "-c",
            f"r3.sbrt.convert file={path} variable=lithok output=gt && "
            f"r3.sbrt.convert -p input=gt 1>&2 && "
            f"r3.sbrt.profile input=gt coordinates=13700,306100,15900,307700 png={png} -g 1>&2"])
        self.assertEqual(code, 0, message)
        self.assertIn("(relative to NAP)", message)
        self.assertIn("elevation_title='Elevation (m NAP)'", message)  # one shell word
        self.assertIn("Vertical exaggeration", message)
        self.assertTrue(os.path.exists(png))


if __name__ == "__main__":
    test()
