"""
MODULE:    testsuite/test_r3_sbrt_grass_native.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.render and r3.sbrt.convert as GRASS users meet them: the
           SBRT drop-down of the dialogs (and no prefix completion on the
           command line), size= (the region untouched, square cells), the
           image as one map with its colours for the Map Display, and the
           PNG's legend, north arrow and scale bar read back with Pillow
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import subprocess
import xml.etree.ElementTree as ET

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import image_region, set_up_t_model


def rgb_of(name):
    """The pixels of an 8-bit map as a list, row by row."""
    text = gs.read_command("r.out.ascii", input=name, flags="h")
    return [int(v) for v in text.split()]


def class_colours(name):
    """class -> (r, g, b) of a map's colour rules (one rule per class)."""
    colours = {}
    for line in gs.read_command("r.colors.out", map=name).splitlines():
        value, rgb = line.split()
        if value not in ("nv", "default"):
            colours[int(float(value))] = tuple(int(c) for c in rgb.split(":"))
    return colours


class TestGrassNative(TestCase):
    @classmethod
    def setUpClass(cls):
        set_up_t_model(cls)
        # a second SBRT whose name the first one's is a prefix of
        cls.runModule("r3.sbrt.convert", input="geo", output="geology")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def setUp(self):
        self.runModule("g.region", region="geo_region")

    # the dialogs' drop-down and the command line
    def interface(self, module):
        run = subprocess.run([module, "--interface-description"], capture_output=True,
                             text=True, check=True)
        return ET.fromstring(run.stdout)

    def test_dialogs_list_the_sbrts_of_the_search_path(self):
        mapset = gs.gisenv()["MAPSET"]
        for module, key in (("r3.sbrt.render", "input"), ("r3.sbrt.convert", "sbrt"),
                            ("r3.sbrt.profile", "input")):
            param = self.interface(module).find(f"parameter[@name='{key}']")
            values = [v.findtext("name").strip() for v in param.iter("value")]
            self.assertEqual(values, ["geo", "geology", f"geo@{mapset}",
                                      f"geology@{mapset}"], msg=module)
            # no gisprompt: the GUI would show "Not selectable element"
            self.assertIsNone(param.find("gisprompt"), msg=module)
        # remove= of r3.sbrt.manage: the current mapset's SBRTs, plain names
        param = self.interface("r3.sbrt.manage").find("parameter[@name='remove']")
        values = [v.findtext("name").strip() for v in param.iter("value")]
        self.assertEqual(values, ["geo", "geology"])
        self.assertIsNone(param.find("gisprompt"))
        # the manual (--html-description) lists none of this location's maps
        run = subprocess.run(["r3.sbrt.render", "--html-description"],
                             capture_output=True, text=True, check=True)
        self.assertNotIn("geology@", run.stdout)

    def test_a_prefix_is_not_completed_into_another_sbrt(self):
        # the list exists only for the dialog: input=geolo is no SBRT (not
        # through pygrass, which checks the list itself)
        run = subprocess.run(["r3.sbrt.render", "input=geolo", "output=pre", "size=8,6"],
                             capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("SBRT <geolo> not found", run.stderr)
        self.assertRasterDoesNotExist("pre.red")
        # geo is geo, not geology (nor an error for being ambiguous)
        self.assertModule("r3.sbrt.render", input="geo", output="pre", size=(8, 6))

    def test_convert_takes_the_sbrt_from_sbrt(self):
        shell = gs.parse_command("r3.sbrt.convert", sbrt="geology", flags="g")
        self.assertEqual(shell["name"], "geology")
        self.assertModule("r3.sbrt.convert", sbrt="geology", output="geology_back",
                          flags="r")
        self.assertRaster3dExists("geology_back")
        # an existing SBRT with output= but no -r: which way is meant?
        self.assertModuleFail("r3.sbrt.convert", sbrt="geology", output="other")
        self.assertModuleFail("r3.sbrt.convert", sbrt="geology", input="geo",
                              output="other")

    # size=
    def test_size_sets_the_image_and_leaves_the_region(self):
        before = gs.parse_command("g.region", flags="g")
        for view in ("perspective", "orthographic"):
            self.assertModule("r3.sbrt.render", input="geo", output="sz", view=view,
                              size=(90, 50), overwrite=True)
            self.assertEqual(gs.parse_command("g.region", flags="g"), before)
            for name in ("sz", "sz.red"):
                info = gs.raster_info(name)
                self.assertEqual((int(info["rows"]), int(info["cols"])), (50, 90),
                                 msg=view)
                # square cells, as large as fit, centred in the region
                self.assertAlmostEqual(info["nsres"], info["ewres"], places=9)
                self.assertGreaterEqual(info["west"], float(before["w"]) - 1e-6)
                self.assertLessEqual(info["east"], float(before["e"]) + 1e-6)
                self.assertAlmostEqual(info["north"] + info["south"],
                                       float(before["n"]) + float(before["s"]), places=6)
                self.assertAlmostEqual(info["east"] + info["west"],
                                       float(before["e"]) + float(before["w"]), places=6)
                self.assertTrue(
                    abs(info["east"] - info["west"] - (float(before["e"]) - float(before["w"]))) < 1e-6
                    or abs(info["north"] - info["south"] - (float(before["n"]) - float(before["s"]))) < 1e-6)
        # the default is m.nviz.image's 640 x 480
        self.assertModule("r3.sbrt.render", input="geo", output="sz", overwrite=True)
        info = gs.raster_info("sz.red")
        self.assertEqual((int(info["rows"]), int(info["cols"])), (480, 640))
        # a top view's maps keep the region's cells (size= is its PNG's)
        run = subprocess.run(["r3.sbrt.render", "input=geo", "output=sz", "view=top",
                              "size=90,50", "--overwrite"], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, msg=run.stderr)
        self.assertNotIn("WARNING", run.stderr)
        info = gs.raster_info("sz.red")
        self.assertEqual((int(info["rows"]), int(info["cols"])),
                         (int(before["rows"]), int(before["cols"])))
        for bad in ("0,10", "10", "10,20,30", "1.5,10", "70000,10"):
            run = subprocess.run(["r3.sbrt.render", "input=geo", "output=bad",
                                  f"size={bad}"], capture_output=True, text=True)
            self.assertNotEqual(run.returncode, 0, msg=bad)
            self.assertIn("size=", run.stderr, msg=bad)
            self.assertRasterDoesNotExist("bad.red")

    # the image as one map
    def assert_colours_of_composite(self, name, tolerance):
        """Every pixel's colour in <name>'s colour table against the .red,
        .green, .blue maps (exact where tolerance is 0)."""
        stats = gs.read_command("r.stats", flags="n", input=f"{name},{name}.red,"
                                f"{name}.green,{name}.blue").splitlines()
        self.assertGreater(len(stats), 10)
        values = "\n".join(line.split()[0] for line in stats)
        colours = subprocess.run(
            ["r.what.color", "-i", f"input={name}", "format=%d:%d:%d"], input=values,
            capture_output=True, text=True, check=True).stdout.splitlines()
        self.assertEqual(len(colours), len(stats))
        worst = [0, 0, 0]
        for line, colour in zip(stats, colours):
            want = [int(v) for v in line.split()[1:]]
            got = [int(v) for v in colour.split(": ")[1].split(":")]
            worst = [max(w, abs(a - b)) for w, a, b in zip(worst, got, want)]
        self.assertLessEqual(max(worst), tolerance, msg=f"{name}: {worst}")
        return worst

    def test_output_map_has_the_image_colours(self):
        size = image_region(self, 80, 60)
        self.assertModule("r3.sbrt.render", input="geo", output="cmp", size=size,
                          normals="kernel", smooth=1)
        self.assertEqual(self.assert_colours_of_composite("cmp", 0), [0, 0, 0])
        # more red-green pairs than colour rules can take: within 2 levels,
        # blue exact (a random drape over a fine top view)
        self.runModule("g.region", region="geo_region")
        self.runModule("g.region", rows=250, cols=200)
        for band in ("nr", "ng", "nb"):
            self.runModule("r.mapcalc", expression=f"{band} = rand(0, 256)", seed=7,
                           overwrite=True)
        self.assertModule("r3.sbrt.render", input="geo", output="many", view="top",
                          texture=["nr", "ng", "nb"], ambient=1)
        worst = self.assert_colours_of_composite("many", 2)
        self.assertEqual(worst[2], 0)

    # the PNG
    def test_png_panel_explains_the_image(self):
        from PIL import Image

        size = image_region(self, 320, 240)
        png = gs.tempfile() + ".png"
        self.assertModule("r3.sbrt.render", input="geo", output="an", size=size,
                          material="an_m", png=png, zexag=2, hide="13")
        colours = class_colours("an_m")
        seen = {int(v) for v in gs.read_command("r.stats", flags="n",
                                                  input="an_m").split()}
        self.assertGreater(len(seen), 3)
        with Image.open(png) as image:
            # as high as the image, or as the legend needs at a readable size
            self.assertGreaterEqual(image.height, 240)
            self.assertGreater(image.width, 320 + 40, msg="no panel")
            pixels = list(image.getdata())
            width = image.width
        # the image part is the maps, pixel for pixel, white below them
        left = [p for i, p in enumerate(pixels[:240 * width]) if i % width < 320]
        for k, band in enumerate(("red", "green", "blue")):
            self.assertEqual([p[k] for p in left], rgb_of(f"an.{band}"), msg=band)
        below = {p for i, p in enumerate(pixels[240 * width:]) if i % width < 320}
        self.assertLessEqual(below, {(255, 255, 255)})
        panel = [p for i, p in enumerate(pixels) if i % width >= 320]
        count = {}
        for p in panel:
            count[p] = count.get(p, 0) + 1
        # a swatch of each class the image shows, none of those it does not
        for cls, rgb in colours.items():
            swatch = count.get(rgb, 0)
            if cls in seen:
                self.assertGreaterEqual(swatch, 25, msg=f"class {cls} {rgb}")
            else:
                self.assertLess(swatch, 5, msg=f"class {cls} {rgb} is not in the image")
        self.assertNotIn(13, seen)
        # the north arrow and the text: dark on the white panel
        dark = sum(n for p, n in count.items() if max(p) < 80 and p not in colours.values())
        self.assertGreater(dark, 300)
        self.assertGreater(count.get((255, 255, 255), 0), len(panel) // 3)

    def test_png_of_a_top_view_has_a_scale_bar(self):
        from PIL import Image

        png = gs.tempfile() + ".png"
        self.runModule("g.region", rows=250, cols=200)
        self.assertModule("r3.sbrt.render", input="geo", output="tp", view="top",
                          png=png)
        with Image.open(png) as image:
            # each cell 3 x 3 pixels: at least 640 on the longer side
            self.assertEqual(image.height, 750)
            panel = image.crop((600, 0, image.width, 750)).convert("L")
            w = panel.width
            rows = [list(panel.getdata())[r * w:(r + 1) * w] for r in range(750)]
        # the bar: a row in the panel's lower third with black and white
        # parts, each at least 5 pixels long
        def runs(row):
            out, start = [], 0
            for i in range(1, len(row) + 1):
                if i == len(row) or (row[i] < 128) != (row[start] < 128):
                    out.append((row[start] < 128, i - start))
                    start = i
            return out
        bars = [r for r in rows[500:] if sum(1 for dark, n in runs(r) if dark and n >= 5) >= 2]
        self.assertTrue(bars, msg="no scale bar")
        # -n: the image alone, enlarged the same
        self.assertModule("r3.sbrt.render", input="geo", output="tp", view="top",
                          png=png, flags="n", overwrite=True)
        with Image.open(png) as image:
            self.assertEqual(image.size, (600, 750))

    def test_png_of_a_small_top_view_is_enlarged_and_readable(self):
        """A top view of few cells (GeoTOP's 100 m cells over a few km):
        each cell k x k pixels in the PNG, k whole, to 640 on the longer
        side or to fit size=; the panel's legend, arrow and scale bar at a
        readable size, the PNG as high as they need."""
        from PIL import Image

        self.runModule("g.region", rows=12, cols=16)
        png = gs.tempfile() + ".png"
        for size, k in ((None, 40), ((200, 100), 8), ((10, 10), 1)):
            extra = {"size": size} if size else {}
            self.assertModule("r3.sbrt.render", input="geo", output="ts", view="top",
                              png=png, overwrite=True, **extra)
            info = gs.raster_info("ts.red")
            self.assertEqual((int(info["rows"]), int(info["cols"])), (12, 16))
            maps = [rgb_of(f"ts.{band}") for band in ("red", "green", "blue")]
            with Image.open(png) as image:
                image = image.convert("RGB")
                self.assertGreaterEqual(image.height, 12 * k)
                self.assertGreater(image.width, 16 * k + 60, msg="no panel")
                # every pixel of the image part is its cell's colour
                for y in range(12 * k):
                    for x in range(16 * k):
                        cell = (y // k) * 16 + x // k
                        self.assertEqual(image.getpixel((x, y)),
                                         tuple(m[cell] for m in maps), msg=(size, x, y))
                panel = image.crop((16 * k, 0, image.width, image.height)).convert("L")
                # text at a readable size: the legend's first line (the
                # bold title) at least 8 pixels high
                dark_rows = [r for r in range(min(40, panel.height))
                             if any(panel.getpixel((c, r)) < 100
                                    for c in range(panel.width))]
                self.assertGreaterEqual(len(dark_rows), 8, msg=size)
                # the scale bar and its text are inside the file
                self.assertGreater(image.height, 150, msg=size)


if __name__ == "__main__":
    test()
