"""
MODULE:    testsuite/test_r3_sbrt_probability_sum.py (r3.sbrt addon)
PURPOSE:   A sum of probabilities (issue 51, item 2): property=
           kans_5+kans_6+kans_7 is drawn on 0-100 % (the probabilities of
           one voxel sum to 100 at most), not on the sum of the channels'
           ranges: the ramp's ends (the value map's colours, the PNG's
           colour bar, the viewer's legend) are 0 and 100 with the unit "%",
           and a voxel of 100 % is drawn in the ramp's top colour. A sum of
           other channels takes the range of its values, voxel by voxel
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import subprocess
import sys
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "g.gui.sbrt"))
from view_client import ViewServer  # noqa: E402

FILL = -127
NX, NY, NZ = 6, 5, 4
X0, Y0, Z0 = 120000, 480000, -1.75
DX, DY, DZ = 100, 100, 0.5
SUM = "kans_5+kans_6+kans_7"
OTHER = "ha+hb"


def lithok(i, j, k):
    """Solid to the top, but for one column of fills (sea)."""
    return FILL if (i, j) == (5, 4) else 1 + (i + k) % 3


def kans(channel):
    """Probabilities in % of three classes: 100 together in the voxels of
    even i + j + k, 16 in the others; none below 1 (the sum of the
    channels' least values is 10 + 5 + 1 = 16, the old bar's low end)."""
    full = {5: 50, 6: 30, 7: 20}[channel]
    part = {5: 10, 6: 5, 7: 1}[channel]
    return lambda i, j, k: full if (i + j + k) % 2 == 0 else part


def ha(i, j, k):
    return i


def hb(i, j, k):
    """ha + hb is 20 + j: 20 to 24 (the channels' ranges add to 15..29)."""
    return 20 - i + j


CHANNELS = {
    "kans_5": kans(5), "kans_6": kans(6), "kans_7": kans(7), "ha": ha, "hb": hb,
}


def write_netcdf(path):
    def values(f):
        return ", ".join(str(f(i, j, k)) for i in range(NX) for j in range(NY)
                         for k in range(NZ))

    declarations = [f"short lithok(x, y, z) ; lithok:_FillValue = {FILL}s ;"]
    data = [f"lithok = {values(lithok)} ;"]
    for name, f in CHANNELS.items():
        unit = "%" if name.startswith("kans") else "m"
        declarations.append(f'short {name}(x, y, z) ; {name}:_FillValue = {FILL}s ; '
                            f'{name}:units = "{unit}" ;')
        data.append(f"{name} = {values(f)} ;")
    cdl = f"""netcdf probabilities {{
dimensions:
  x = {NX} ; y = {NY} ; z = {NZ} ;
variables:
  int x(x) ; x:standard_name = "projection_x_coordinate" ; x:units = "m" ;
  int y(y) ; y:standard_name = "projection_y_coordinate" ; y:units = "m" ;
  float z(z) ; z:positive = "up" ; z:units = "m" ;
  {" ".join(declarations)}
data:
  x = {", ".join(str(X0 + DX * t) for t in range(NX))} ;
  y = {", ".join(str(Y0 + DY * t) for t in range(NY))} ;
  z = {", ".join(repr(Z0 + DZ * t) for t in range(NZ))} ;
  {" ".join(data)}
}}
"""
    with open(path + ".cdl", "w") as f:
        f.write(cdl)
    subprocess.run(["ncgen", "-k", "nc4", "-o", path, path + ".cdl"], check=True,
                   timeout=60)


def ramp_ends(raster):
    """The low and high end (value, (r, g, b)) of a map's colour rules."""
    rules = []
    for line in gs.read_command("r.colors.out", map=raster).splitlines():
        words = line.split()
        if len(words) == 2 and words[0] not in ("nv", "default"):
            rules.append((float(words[0]), tuple(int(v) for v in words[1].split(":"))))
    return min(rules), max(rules)


def pixel(base, row, col):
    """The RGB of cell (row, col) of maps <base>.red, .green, .blue."""
    rgb = []
    for part in ("red", "green", "blue"):
        rows = gs.read_command("r.out.ascii", input=f"{base}.{part}", flags="h").split("\n")
        rgb.append(int(rows[row].split()[col]))
    return tuple(rgb)


class TestProbabilitySum(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_probability_sum_")
        path = os.path.join(cls.tmp, "probabilities.nc")
        write_netcdf(path)
        cls.runModule("r3.sbrt.convert", file=path, variable="lithok",
                      properties=",".join(CHANNELS), output="psum", preset="none",
                      flags="s")

    @classmethod
    def tearDownClass(cls):
        cls.runModule("r3.sbrt.manage", flags="f", remove="psum")
        cls.del_temp_region()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def render_top(self, prop, name):
        """A top view of `prop` (ambient light only: the colours as drawn
        by the ramp), its value map and PNG."""
        png = os.path.join(self.tmp, name + ".png")
        self.assertModule("r3.sbrt.render", input="psum", view="top", backend="cpu",
                          property=prop, ambient=1, output=name, value=name + "_value",
                          png=png, overwrite=True)
        self.assertTrue(os.path.getsize(png) > 0)
        return png

    def test_sum_of_probabilities_is_drawn_on_0_to_100_percent(self):
        self.render_top(SUM, "psum_top")
        (low, low_rgb), (high, high_rgb) = ramp_ends("psum_top_value")
        self.assertEqual((low, high), (0, 100))
        self.assertEqual(gs.raster_info("psum_top_value")["units"], "%")
        # a column whose top voxel (k = NZ - 1) holds 100 %: i + j odd;
        # row 0 of the view is the north (j = NY - 1)
        values = gs.read_command("r.out.ascii", input="psum_top_value", flags="h",
                                 null_value="*").split("\n")
        full = [(r, i) for r in range(NY) for i in range(NX)
                if values[r].split()[i] == "100"]
        self.assertGreater(len(full), 5)
        for r, i in full:
            self.assertEqual((i + (NY - 1 - r) + NZ - 1) % 2, 0)
            self.assertEqual(pixel("psum_top", r, i), high_rgb, (r, i))
        # a voxel of 16 % lies near the low end, not on it
        low_cells = [(r, i) for r in range(NY) for i in range(NX)
                     if values[r].split()[i] == "16"]
        self.assertTrue(low_cells)
        self.assertNotEqual(pixel("psum_top", *low_cells[0]), low_rgb)

    def test_sum_of_other_channels_takes_the_range_of_its_values(self):
        self.render_top(OTHER, "other_top")
        (low, _), (high, _) = ramp_ends("other_top_value")
        self.assertEqual((low, high), (20, 24))
        self.assertEqual(gs.raster_info("other_top_value")["units"], "m")

    def test_viewer_legend_says_0_to_100_percent(self):
        server = ViewServer()
        try:
            words = ["input=psum", "view=top", "size=60,50"]
            frame = server.render(words + ["property=" + SUM])
            self.assertEqual(tuple(frame.legend), (0.0, 100.0, "%"))
            frame = server.render(words + ["property=" + OTHER])
            self.assertEqual(tuple(frame.legend), (20.0, 24.0, "m"))
            frame = server.render(words)
            self.assertIsNone(frame.legend)
        finally:
            server.close()


if __name__ == "__main__":
    test()
