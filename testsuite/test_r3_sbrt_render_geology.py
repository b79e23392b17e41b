"""
MODULE:    testsuite/test_r3_sbrt_render_geology.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.render's geological operations against GRASS's own tools
           on the same voxels: a head-on section and a fence curtain equal
           r3.cross.rast, boreholes show the stack at their points (and
           their logs), translucent strata, drape; bad vector and texture
           input
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import image_region, set_up_t_model

# the T model: 40 x 50 cells of 50 m, 64 voxels of 10 m from 0 to 640 m
DEPTHS, TB, RES = 64, 10.0, 50.0
# the row of cell centres the sections run along (row 20 from the north)
Y0 = 2500 - 20.5 * RES
# vertical exaggeration that makes a voxel 50 m tall: one pixel per voxel
ZEXAG = RES / TB


class TestGeologicalOperations(TestCase):
    @classmethod
    def setUpClass(cls):
        set_up_t_model(cls)
        # the vertical section along y = Y0 by r3.cross.rast, level by
        # level: a constant elevation at each voxel centre, read along the
        # line (r3.cross.rast takes its sample positions from the 2D grid,
        # so one run cannot hold a vertical section)
        levels = []
        for k in range(DEPTHS):
            z = DEPTHS * TB - (k + 0.5) * TB  # image row k, top down
            cls.runModule("r.mapcalc", expression=f"xs_elev = {z}", overwrite=True)
            cls.runModule("r3.cross.rast", input="geo", elevation="xs_elev",
                          output=f"xs_{k}", overwrite=True)
            levels.append(f"xs_{k}")
        coords = [(RES * (c + 0.5), Y0) for c in range(40)]
        values = [[] for _ in range(DEPTHS)]
        for line in gs.read_command("r.what", map=levels, coordinates=coords,
                                    separator="|").splitlines():
            fields = line.split("|")[3:]
            for k, v in enumerate(fields):
                values[k].append(None if v == "*" else int(float(v)))
        cls.xsec = values
        # the image region: one pixel per cell east-west, one per voxel
        # (square cells: the image's own window)
        cls.runModule("g.region", n=Y0 + 25 * DEPTHS, s=Y0 - 25 * DEPTHS, w=0, e=2000,
                      rows=DEPTHS, cols=40)
        cls.runModule("g.region", save="xs_region", overwrite=True)
        cls.runModule("g.region", region="geo_region")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def setUp(self):
        self.runModule("g.region", region="geo_region")

    def head_on(self, **options):
        """An orthographic view of the plane y = Y0 from the south, one
        pixel per cell and voxel of it (in the section's region)."""
        self.runModule("g.region", region="xs_region")
        self.assertModule(
            "r3.sbrt.render", input="geo", view="orthographic", zexag=ZEXAG,
            size=(40, DEPTHS),
            position=[1000, Y0 - 5000, 320], target=[1000, Y0, 320],
            ortho_height=DEPTHS * TB * ZEXAG, overwrite=True, **options,
        )

    def lines_map(self, name, text):
        """Vector map `name` from v.in.ascii's standard format."""
        gs.write_command("v.in.ascii", input="-", stdin=text, output=name,
                         format="standard", flags="n", overwrite=True, quiet=True)

    def points_map(self, name, rows, more_columns=""):
        """Vector map `name` of points from rows cat|x|y[|...]."""
        gs.write_command("v.in.ascii", input="-", stdin=rows, output=name, separator="pipe",
                         x=2, y=3, cat=1, columns="cat int, x double precision, "
                         "y double precision" + more_columns, overwrite=True, quiet=True)

    def count(self, expression):
        self.runModule("r.mapcalc", expression=f"cnt = {expression}", overwrite=True)
        return int(float(gs.parse_command("r.univar", map="cnt", flags="g")["sum"]))

    def grid(self, name):
        """A map of the section's region as rows of ints (None for null)."""
        text = gs.read_command("r.out.ascii", input=name, flags="h", null_value="*")
        return [[None if v == "*" else int(float(v)) for v in line.split()]
                for line in text.splitlines()]

    def test_head_on_section_equals_r3_cross_rast(self):
        for backend in ("cpu", "egl"):
            self.head_on(output="xs", material="xs_mat", backend=backend,
                         section=[0, Y0, 2000, Y0])
            got = self.grid("xs_mat")
            # where the section holds a class, the render shows it; where it
            # is null (air, caves) the render sees what lies behind
            pairs = [(g, w) for gr, wr in zip(got, self.xsec) for g, w in zip(gr, wr)
                     if w is not None]
            self.assertGreater(len(pairs), 40 * DEPTHS // 2)
            self.assertEqual([p for p in pairs if p[0] != p[1]], [], msg=backend)

    def test_fence_curtain_equals_r3_cross_rast(self):
        self.lines_map("fence_line", f"L 2\n 0 {Y0}\n 2000 {Y0}\n")
        self.head_on(output="fc", material="fc_mat", fence="fence_line")
        # only the curtain is drawn: nulls of the section are holes in it
        self.assertEqual(self.grid("fc_mat"), self.xsec)

    def test_boreholes_show_the_stack_at_their_points(self):
        # two at cell centres, one outside the model
        self.points_map("bh", "1|525|1225|a\n2|1475|1975|b\n3|5000|5000|c\n",
                        ", name varchar(8)")
        run = subprocess.run(
            ["r3.sbrt.render", "input=geo", "output=bh", "view=top", "-b",
             "boreholes=bh", "material=bh_mat", "--overwrite"],
            capture_output=True, text=True,
        )
        self.assertEqual(run.returncode, 0, msg=run.stderr)
        self.assertIn("outside the model", run.stderr)
        # radius 0.4 cell: only the two cells' centre pixels see a cylinder
        # top, the class at the top of the stack there
        self.assertEqual(self.count("if(isnull(bh_mat), 0, 1)"), 2)
        self.assertEqual(self.count("if(isnull(bh_mat), 0, bh_mat != top_class)"), 0)
        # where= selects one of them
        self.assertModule("r3.sbrt.render", input="geo", output="bh1", view="top",
                          flags="b", boreholes="bh", where="cat = 2",
                          material="bh1_mat", overwrite=True)
        self.assertEqual(self.count("if(isnull(bh1_mat), 0, 1)"), 1)
        # without -b the cylinders are inside the model: the same top view
        self.assertModule("r3.sbrt.render", input="geo", output="bh2", view="top",
                          boreholes="bh", material="bh2_mat", overwrite=True)
        self.assertRastersNoDifference("bh2_mat", "top_class", precision=0)

    def test_overlays_alone_on_the_gpu_equal_the_cpu(self):
        """A fence diagram and boreholes alone (-b), traced and shaded on the
        GPU (llvmpipe here): the CPU's class map."""
        self.lines_map("gpu_fence", "L 3\n 150 300\n 900 1400\n 1800 1600\n")
        self.points_map("gpu_bh", "1|525|1225\n2|1475|1975\n3|1100|700\n")
        size = image_region(self, 90, 70)
        view = ["input=geo", "size=%d,%d" % size, "position=2600,-900,1500",
                "target=1000,1250,400", "fov=40", "--overwrite"]
        for name, scene in (("fence", ["fence=gpu_fence"]),
                            ("alone", ["-b", "boreholes=gpu_bh", "borehole_radius=60"])):
            for backend in ("egl", "cpu"):
                run = subprocess.run(
                    ["r3.sbrt.render", f"output=ov_{name}_{backend}",
                     f"material=ov_{name}_{backend}_m", f"backend={backend}", "--verbose"]
                    + view + scene,
                    capture_output=True, text=True,
                )
                self.assertEqual(run.returncode, 0, msg=run.stderr)
                self.assertIn(f"Backend: {backend}", run.stderr)
            gpu, cpu = f"ov_{name}_egl_m", f"ov_{name}_cpu_m"
            self.assertGreater(self.count(f"if(isnull({cpu}), 0, 1)"), 90 * 70 // 50, msg=name)
            self.assertLessEqual(
                self.count(f"if(isnull({gpu}) != isnull({cpu}) || "
                           f"(!isnull({gpu}) && {gpu} != {cpu}), 1, 0)"),
                90 * 70 // 500 + 1, msg=name)
            self.assertLessEqual(
                self.count(f"if(abs(ov_{name}_egl.red - ov_{name}_cpu.red) > 1 || "
                           f"abs(ov_{name}_egl.green - ov_{name}_cpu.green) > 1, 1, 0)"),
                90 * 70 // 200, msg=name)
        self.runModule("g.region", region="geo_region")

    def test_borehole_logs_replace_the_model_stack(self):
        self.points_map("logged", "1|525|1225\n2|1475|1975\n")
        # one row per logged interval in a table linked by cat
        self.runModule("db.execute", sql="DROP TABLE IF EXISTS bh_log")
        self.runModule("db.execute", sql="CREATE TABLE bh_log (cat integer, "
                       "dtop double precision, dbottom double precision, cls integer)")
        for row in ("1, 0, 40, 99", "1, 40, 300, 3", "2, 20, 90, 5"):
            self.runModule("db.execute", sql=f"INSERT INTO bh_log VALUES ({row})")
        gs.run_command("v.db.connect", map="logged", table="bh_log", layer=1,
                       key="cat", flags="o", quiet=True, stderr=subprocess.DEVNULL)
        self.assertModule(
            "r3.sbrt.render", input="geo", output="lg", view="top", flags="b",
            boreholes="logged", log_top="dtop", log_bottom="dbottom", log_class="cls",
            log_reference="depth", material="lg_mat", hit_elevation="lg_z",
            overwrite=True,
        )
        # depths below the terrain (2D points): the log's top class is seen,
        # 99 (not a class of the model) and 5 below a 20 m gap at point 2
        stats = gs.read_command("r.stats", flags="n", input="lg_mat").split()
        self.assertEqual(sorted(int(v) for v in stats), [5, 99])
        # drawn with the model, on the GPU: the GPU draws the model and the
        # CPU the boreholes' pixels; the class map is the CPU's
        size = image_region(self, 80, 60)
        oblique = ["input=geo", "size=%d,%d" % size, "position=1300,300,1200",
                   "target=525,1225,550", "fov=35", "boreholes=logged", "log_top=dtop",
                   "log_bottom=dbottom", "log_class=cls", "log_reference=depth",
                   "borehole_radius=40", "--overwrite"]
        for backend in ("egl", "cpu"):
            run = subprocess.run(
                ["r3.sbrt.render", f"output=lgo_{backend}", f"material=lgo_{backend}_m",
                 f"backend={backend}", "--verbose"] + oblique,
                capture_output=True, text=True,
            )
            self.assertEqual(run.returncode, 0, msg=run.stderr)
            self.assertIn(f"Backend: {backend}", run.stderr)
        self.assertGreater(self.count("if(isnull(lgo_egl_m), 0, lgo_egl_m == 99)"), 4)
        self.assertLessEqual(
            self.count("if(isnull(lgo_egl_m) != isnull(lgo_cpu_m) || "
                       "(!isnull(lgo_egl_m) && lgo_egl_m != lgo_cpu_m), 1, 0)"),
            80 * 60 // 500 + 1)
        self.runModule("g.region", region="geo_region")
        self.assertModuleFail(
            "r3.sbrt.render", input="geo", output="bad", boreholes="logged",
            log_top="dtop", log_bottom="dbottom", log_class="nosuchcolumn",
        )

    def test_opacity_composes_exactly_with_hide(self):
        size = image_region(self, 80, 60)
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="op0", material="op0_m",
                          opacity="13:0")
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="hd", material="hd_m",
                          hide="13")
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="op1", material="op1_m",
                          opacity="13:1")
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="pl", material="pl_m")
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="oph", material="oph_m",
                          opacity="13:0.5")
        for band in ("red", "green", "blue"):
            # alpha 0 draws nothing, alpha 1 is opaque
            self.assertRastersNoDifference(f"op0.{band}", f"hd.{band}", precision=0)
            self.assertRastersNoDifference(f"op1.{band}", f"pl.{band}", precision=0)
        # a translucent stratum is not hit: the material seen is the one below
        self.assertRastersNoDifference("oph_m", "hd_m", precision=0)
        self.assertGreater(self.count("oph.red != hd.red"), 100)
        # the GPU composes the same light
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="opg", backend="egl",
                          opacity=["13:0.5", "12:0.3"], opacity_length=20)
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="opc", backend="cpu",
                          opacity=["13:0.5", "12:0.3"], opacity_length=20)
        self.assertLessEqual(
            self.count("abs(opg.red - opc.red) > 2 || abs(opg.green - opc.green) > 2"),
            60 * 80 // 1000,
        )
        for bad in ("13:1.5", "13", "nosuch:0.5", ":0.5"):
            self.assertModuleFail("r3.sbrt.render", size=size, input="geo", output="bad",
                                  opacity=bad)

    def test_drape_puts_the_texture_on_the_terrain(self):
        self.runModule("r.mapcalc", expression="tr = col() * 5", overwrite=True)
        self.runModule("r.mapcalc", expression="tg = row() * 4", overwrite=True)
        self.runModule("r.mapcalc", expression="tb = 77", overwrite=True)
        self.assertModule("r3.sbrt.render", input="geo", output="dr", view="top",
                          texture=["tr", "tg", "tb"], ambient=1, overwrite=True)
        # a top view sees the terrain's top at each cell centre, where the
        # bilinear texture is the cell's own value
        for band, want in (("red", "tr"), ("green", "tg"), ("blue", "tb")):
            self.assertEqual(self.count(f"if(isnull(top_class), 0, dr.{band} != {want})"), 0)
        # texture_blend=0 is the plain render
        self.assertModule("r3.sbrt.render", input="geo", output="d0", view="top",
                          texture=["tr", "tg", "tb"], texture_blend=0, ambient=1)
        self.assertModule("r3.sbrt.render", input="geo", output="p0", view="top", ambient=1)
        self.assertRastersNoDifference("d0.red", "p0.red", precision=0)
        # a map with a colour table: its colours are draped
        self.runModule("r.colors", map="tr", color="grey")
        self.assertModule("r3.sbrt.render", input="geo", output="dg", view="top",
                          texture="tr", ambient=1)
        self.assertEqual(self.count("if(isnull(top_class), 0, dg.red != dg.green)"), 0)
        # the GPU drapes the same texture, tops and walls (an oblique view)
        oblique = dict(input="geo", size=[80, 60], position=[2600, -900, 1500],
                       target=[1000, 1250, 300], fov=30, texture=["tr", "tg", "tb"],
                       texture_blend=0.8, overwrite=True)
        self.assertModule("r3.sbrt.render", output="dre", backend="egl", **oblique)
        self.assertModule("r3.sbrt.render", output="drc", backend="cpu", **oblique)
        self.assertGreater(self.count("dre.green != 0 && abs(dre.blue - 77) < 30"), 80 * 60 // 10)
        self.assertLessEqual(
            self.count("abs(dre.red - drc.red) > 1 || abs(dre.green - drc.green) > 1 || "
                       "abs(dre.blue - drc.blue) > 1"),
            80 * 60 // 200,
        )
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad",
                              texture="nosuchmap")
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad",
                              texture=["tr", "tg"])

    def test_bad_vector_input_fails(self):
        self.lines_map("only_lines", "L 2\n 100 100\n 900 900\n")
        self.points_map("one_point", "1|525|1225\n")
        for options in (
            dict(boreholes="only_lines"),       # lines where points are needed
            dict(fence="one_point"),            # points where lines are needed
            dict(boreholes="one_point", where="cat = 99"),  # no point selected
            dict(boreholes="one_point", layer="abc"),  # no layer of that name
            dict(boreholes="nosuchmap"),
            dict(flags="b"),                    # -b needs boreholes=
        ):
            self.assertModuleFail("r3.sbrt.render", input="geo", output="bad",
                                  **options)
        self.assertRasterDoesNotExist("bad.red")


if __name__ == "__main__":
    test()
