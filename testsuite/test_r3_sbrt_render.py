"""
MODULE:    testsuite/test_r3_sbrt_render.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.render against GRASS's own tools: the top view equals the
           topmost non-null voxel (r3.to.rast + r.mapcalc), outputs, camera
           errors, missing and corrupt SBRTs
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

HERE = os.path.dirname(os.path.abspath(__file__))
MAKE_GEOMODEL = os.path.join(HERE, "..", "tools", "make_geomodel.sh")


class TestRenderTopView(TestCase):
    depths = 64

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        subprocess.run([MAKE_GEOMODEL, "T", "geo"], check=True)
        cls.runModule("r3.sbrt.convert", input="geo", output="geo")
        # independent: the topmost non-null voxel of every column
        cls.runModule("r3.to.rast", input="geo", output="sl")
        expr = "null()"
        for z in range(1, cls.depths + 1):
            s = f"sl_{z:05d}"
            expr = f"if(isnull({s}), {expr}, {s})"
        cls.runModule("r.mapcalc", expression=f"top_class = int({expr})")
        # elevation of that voxel's top: 640 m / 64 depths = 10 m per voxel
        zexpr = "null()"
        for z in range(1, cls.depths + 1):
            zexpr = f"if(isnull(sl_{z:05d}), {zexpr}, {z * 10})"
        cls.runModule("r.mapcalc", expression=f"top_z = {zexpr}")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def test_material_map_is_topmost_voxel(self):
        self.assertModule(
            "r3.sbrt.render",
            input="geo",
            output="top",
            view="top",
            material="top_mat",
            hit_elevation="top_hz",
        )
        self.assertRastersNoDifference("top_mat", "top_class", precision=0)
        self.assertRastersNoDifference("top_hz", "top_z", precision=1e-6)
        self.assertRasterFitsInfo("top_mat", reference=dict(rows=50, cols=40))

    def test_material_map_carries_labels_and_colours(self):
        self.assertModule(
            "r3.sbrt.render", input="geo", output="lab", view="top", material="lab_mat"
        )
        labels = gs.read_command("r.category", map="lab_mat")
        self.assertIn("13\tTopsoil and till", labels)
        self.assertIn("13 150:200:90", gs.read_command("r.colors.out", map="lab_mat"))

    def test_perspective_outputs(self):
        self.runModule("g.region", rows=60, cols=80)
        self.assertModule(
            "r3.sbrt.render", input="geo", output="persp", depth="persp_d",
            material="persp_m",
        )
        for band in ("red", "green", "blue"):
            self.assertRasterMinMax(f"persp.{band}", refmin=0, refmax=255)
        info = gs.raster_info("persp_d")
        self.assertGreater(info["min"], 0)
        # the default camera frames the model: the corners see background
        univar = gs.parse_command("r.univar", map="persp_m", flags="g")
        self.assertGreater(int(univar["null_cells"]), 0)
        self.assertGreater(int(univar["n"]), 60 * 80 // 4)
        self.runModule("g.region", raster_3d="geo")

    def test_bad_camera_fails(self):
        self.assertModuleFail(
            "r3.sbrt.render", input="geo", output="bad",
            position=[1, 2, 3], target=[1, 2, 3],
        )
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", fov=0)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", fov=180)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", zexag=0)

    def test_missing_and_corrupt_sbrt_fail(self):
        self.assertModuleFail("r3.sbrt.render", input="nosuch", output="bad")
        self.runModule("r3.sbrt.convert", input="geo", output="broken")
        env = gs.gisenv()
        stacks = os.path.join(
            env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], "sbrt", "broken",
            "stacks",
        )
        with open(stacks, "r+b") as f:
            f.truncate(os.path.getsize(stacks) - 7)
        self.assertModuleFail("r3.sbrt.render", input="broken", output="bad")
        self.assertRasterDoesNotExist("bad.red")


if __name__ == "__main__":
    test()
