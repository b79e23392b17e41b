"""
MODULE:    testsuite/test_r3_sbrt_map_colours.py (r3.sbrt addon)
PURPOSE:   Issue 51: a top view (the geological map) shows each class in its
           legend's colour exactly (item 4), on the CPU and the GPU, while
           3D views stay lit; kernel normals keep GeoTOP-like flat tops
           (cells of 100 m, levels of 0.5 m, tops stepping a level up or
           down from cell to cell) at zexag=20 within 10 levels of the face
           normals' image (item 6)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import math

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import image_region

# GeoTOP's lithoclass colours (presets/geotop_lithoclass.rules)
LEGEND = {
    1: (200, 200, 200),  # anthropogenic
    2: (0, 146, 0),  # clay
    3: (157, 78, 64),  # peat
    6: (243, 225, 6),  # medium sand
}
# 50 x 40 cells of 100 m, 20 levels of 0.5 m
REGION = dict(n=4000, s=0, e=5000, w=0, t=10, b=0, res=100, res3=100, tbres=0.5)
# the ring of cells along the model's sides whose class (clay) marks the
# tops near its edges, which the kernel rounds off as it should
RING = 5
# the top level of a cell (depth() from 1 at the bottom): 14, 15 or 16, a
# level up or down from cell to cell as GeoTOP's are
TOP = "(14 + (row() * row() * 31 + col() * 17 + row() * col() * 7) % 3)"
TOP_CLASS = (f"if(row() <= {RING} || row() > 40 - {RING} || col() <= {RING} || "
             f"col() > 50 - {RING}, 2, if(col() <= 25, 6, 1))")
# default light=315,45 and ambient=0.35: L.N of an upward face
TOP_SHARE = 0.35 + 0.65 * math.sin(math.radians(45))
BACKENDS = ("cpu", "egl")  # egl: llvmpipe here, as test_r3_sbrt_render.py


class TestMapColours(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", **REGION)
        cls.runModule(
            "r3.mapcalc", overwrite=True,
            expression=f"steps = if(depth() > {TOP}, null(), if(depth() == {TOP}, "
                       f"{TOP_CLASS}, if(depth() % 4 < 2, 3, 2)))",
        )
        rules = "\n".join(f"{c} {r}:{g}:{b}" for c, (r, g, b) in LEGEND.items())
        cls.runModule("r3.colors", map="steps", rules="-", stdin_=rules + "\n")
        cls.runModule("r3.sbrt.convert", input="steps", output="steps")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def setUp(self):
        self.runModule("g.region", **REGION)

    def colours_of_classes(self, material, image):
        """{class: set of (r, g, b)} of an image's pixels."""
        stats = gs.read_command(
            "r.stats", flags="n",
            input=[material, f"{image}.red", f"{image}.green", f"{image}.blue"],
        )
        found = {}
        for line in stats.splitlines():
            c, r, g, b = (int(w) for w in line.split())
            found.setdefault(c, set()).add((r, g, b))
        return found

    def test_top_view_shows_the_legend_colours(self):
        """Every pixel of a top view is its class's legend colour (with
        kernel normals, of the tops away from the model's sides)."""
        for backend in BACKENDS:
            for normals in ("face", "kernel"):
                name = f"map_{backend}_{normals}"
                self.assertModule(
                    "r3.sbrt.render", input="steps", output=name, view="top",
                    material=f"{name}_m", backend=backend, normals=normals,
                    overwrite=True,
                )
                found = self.colours_of_classes(f"{name}_m", name)
                self.assertEqual(set(found), {1, 2, 6}, msg=name)
                # kernel normals round off the model's edges (the clay ring)
                for c in (1, 2, 6) if normals == "face" else (1, 6):
                    self.assertEqual(found[c], {LEGEND[c]}, msg=f"{name} class {c}")

    def test_perspective_views_stay_lit(self):
        """A 3D view's tops are lit by light= (the map's light is its own)."""
        size = image_region(self, 160, 120)
        self.assertModule(
            "r3.sbrt.render", input="steps", output="lit", material="lit_m",
            size=size, zexag=20, backend="cpu", overwrite=True,
        )
        found = self.colours_of_classes("lit_m", "lit")
        for c in (1, 6):
            top = tuple(math.floor(v * TOP_SHARE + 0.5) for v in LEGEND[c])
            self.assertIn(top, found[c])
            self.assertNotIn(LEGEND[c], found[c])

    def top_grey_differences(self, face, kernel, material):
        """Over the pixels of the inner tops (classes 1 and 6) of the face
        normals' image: the most any channel of the kernel normals' image
        differs, and per class the range of the kernel image's grey."""
        tops = " || ".join(
            f"({material} == {c} && " + " && ".join(
                f"{face}.{band} == {math.floor(v * TOP_SHARE + 0.5)}"
                for band, v in zip(("red", "green", "blue"), LEGEND[c])) + ")"
            for c in (1, 6))
        self.runModule(
            "r.mapcalc", overwrite=True,
            expression=f"tops = if({tops}, {material}, null())")
        self.runModule(
            "r.mapcalc", overwrite=True,
            expression=f"top_far = if(isnull(tops), null(), max("
                       + ", ".join(f"abs({kernel}.{b} - {face}.{b})"
                                   for b in ("red", "green", "blue")) + "))")
        self.runModule(
            "r.mapcalc", overwrite=True,
            expression=f"top_grey = if(isnull(tops), null(), 0.299 * {kernel}.red + "
                       f"0.587 * {kernel}.green + 0.114 * {kernel}.blue)")
        far = gs.parse_command("r.univar", map="top_far", flags="g")
        spreads = {}
        for c in (1, 6):
            self.runModule("r.mapcalc", overwrite=True,
                           expression=f"top_grey_c = if(tops == {c}, top_grey, null())")
            grey = gs.parse_command("r.univar", map="top_grey_c", flags="g")
            spreads[c] = float(grey["max"]) - float(grey["min"])
        return int(far["n"]), float(far["max"]), spreads

    def test_kernel_normals_keep_flat_tops_even(self):
        """GeoTOP-like tops at zexag=20: kernel normals within 10 levels."""
        size = image_region(self, 320, 240)
        for backend in BACKENDS:
            for normals in ("face", "kernel"):
                self.assertModule(
                    "r3.sbrt.render", input="steps", output=f"z_{normals}",
                    material="z_m", size=size, zexag=20, normals=normals, kernel=5,
                    backend=backend, overwrite=True,
                )
            pixels, far, spreads = self.top_grey_differences("z_face", "z_kernel", "z_m")
            self.assertGreater(pixels, 5000, msg=backend)
            self.assertLessEqual(far, 10, msg=backend)
            for c, spread in spreads.items():
                self.assertLessEqual(spread, 10, msg=f"{backend} class {c}")


if __name__ == "__main__":
    test()
