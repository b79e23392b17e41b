"""
MODULE:    testsuite/test_r3_sbrt_render.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.render against GRASS's own tools: the top view equals the
           topmost non-null voxel (r3.to.rast + r.mapcalc), outputs, camera
           errors, missing and corrupt SBRTs
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import glob
import os
import re
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import T_DEPTHS, image_region, set_up_t_model


class TestRenderTopView(TestCase):
    depths = T_DEPTHS

    @classmethod
    def setUpClass(cls):
        set_up_t_model(cls)
        # elevation of that voxel's top: 640 m / 64 depths = 10 m per voxel
        zexpr = "null()"
        for z in range(1, cls.depths + 1):
            zexpr = f"if(isnull(sl_{z:05d}), {zexpr}, {z * 10})"
        cls.runModule("r.mapcalc", expression=f"top_z = {zexpr}")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def setUp(self):
        # whatever region a failed test left
        self.runModule("g.region", region="geo_region")

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
        size = image_region(self, 80, 60)
        self.assertModule(
            "r3.sbrt.render", size=size, input="geo", output="persp", depth="persp_d",
            material="persp_m", background="30:60:90", light=[315, 45], ambient=0.35,
        )
        # the image against the class colours of the source 3D raster (the
        # r3.colors rules of make_geomodel.sh), not the renderer's: a miss is
        # the background; a hit on class k is k's colour times one shading
        # factor f = ambient + (1 - ambient) * lambert in [0.35, 1] for all
        # three channels, within a level (rounding; the GPU shades in float)
        colours = {}
        for line in gs.read_command("r3.colors.out", map="geo").splitlines():
            value, rgb = line.split()
            if value not in ("nv", "default"):
                colours[int(float(value))] = [int(c) for c in rgb.split(":")]
        stats = gs.read_command(
            "r.stats", flags="c", input="persp_m,persp.red,persp.green,persp.blue"
        )
        misses = hits = 0
        factors = []  # the range of f each hit's colour allows
        for line in stats.splitlines():
            cls, *rgb, count = line.split()
            if cls == "*" and rgb == ["*"] * 3:
                continue  # the region beyond the maps' extent
            rgb = [int(c) for c in rgb]
            if cls == "*":
                self.assertEqual(rgb, [30, 60, 90], msg="a miss is the background")
                misses += int(count)
                continue
            low, high = 0.35 - 1e-9, 1 + 1e-9
            for level, full in zip(rgb, colours[int(cls)]):
                low = max(low, (level - 1) / full)
                high = min(high, (level + 1) / full)
            self.assertLessEqual(
                low, high, msg=f"class {cls}: {rgb} is not {colours[int(cls)]} shaded"
            )
            factors.append((low, high))
            hits += int(count)
        self.assertGreater(misses, 0)
        self.assertGreater(hits, 60 * 80 // 4)
        # tops under the light at 45 degrees: f = 0.35 + 0.65 sin 45; faces
        # turned from it: the ambient share alone
        top = 0.35 + 0.65 * 0.5**0.5
        self.assertTrue(any(low <= top <= high for low, high in factors),
                        msg=f"no top lit at f = {top:.4f}")
        self.assertTrue(any(low < 0.35 + 1e-6 for low, _ in factors),
                        msg="no face in the ambient light alone")
        info = gs.raster_info("persp_d")
        self.assertGreater(info["min"], 0)
        # the default camera frames the model: the corners see background
        univar = gs.parse_command("r.univar", map="persp_m", flags="g")
        self.assertGreater(int(univar["null_cells"]), 0)
        self.assertGreater(int(univar["n"]), 60 * 80 // 4)
        self.runModule("g.region", region="geo_region")

    def render_pair(self, name, **options):
        """The same view through two backends: material and depth maps."""
        for backend in ("cpu", name):
            self.assertModule(
                "r3.sbrt.render", input="geo", output=f"{backend}_img",
                material=f"{backend}_mat", depth=f"{backend}_dep",
                backend=backend, overwrite=True, **options,
            )

    def differing_cells(self, a, b):
        self.runModule(
            "r.mapcalc", overwrite=True,
            expression=f"diff = if(isnull({a}) != isnull({b}) || "
            f"(!isnull({a}) && {a} != {b}), 1, 0)",
        )
        return int(float(gs.parse_command("r.univar", map="diff", flags="g")["sum"]))

    def test_gl_backends_agree_with_cpu(self):
        """EGL and OSMesa (llvmpipe here) against the exact CPU tracer."""
        size = image_region(self, 120, 90)
        # twice the model's height: below its diagonal (3265 m), so the
        # depth tolerance 1e-4 * size is stricter than the issue's
        extent = 2 * 640.0
        backends = ["egl"]
        if os.path.exists("/usr/include/GL/osmesa.h"):  # built in (lib/gl_config.make)
            backends.append("osmesa")
        views = [
            dict(),
            dict(azimuth=100, elevation=3),  # grazing
            dict(view="orthographic", azimuth=10, elevation=60),
            dict(position=[200, 250, 300], target=[300, 100, 200]),  # inside
        ]
        for backend in backends:
            for view in views:
                self.render_pair(backend, size=size, **view)
                # agree: both miss, or the same material at the same depth
                self.runModule(
                    "r.mapcalc", overwrite=True,
                    expression=f"disagree = if(isnull(cpu_mat) && isnull({backend}_mat), 0, "
                    f"if(isnull(cpu_mat) || isnull({backend}_mat), 1, "
                    f"cpu_mat != {backend}_mat || "
                    f"abs(cpu_dep - {backend}_dep) >= {1e-4 * extent}))",
                )
                cells = 90 * 120
                disagree = gs.parse_command("r.univar", map="disagree", flags="g")
                self.assertLessEqual(int(float(disagree["sum"])), cells // 1000,
                                     msg=f"{backend} {view}")
                self.assertEqual(int(disagree["n"]), cells)
        self.runModule("g.region", region="geo_region")

    def test_texture_layout_gives_the_same_maps(self):
        """layout=textures (1-Textures) against layout=ssbo and the CPU."""
        size = image_region(self, 90, 70)
        view = dict(azimuth=100, elevation=25)
        for layout in ("ssbo", "textures"):
            self.assertModule(
                "r3.sbrt.render", size=size, input="geo", output=f"lay_{layout}",
                material=f"lay_{layout}_m", depth=f"lay_{layout}_d", backend="egl",
                layout=layout, overwrite=True, **view,
            )
        self.render_pair("egl", size=size, **view)
        self.assertEqual(self.differing_cells("lay_ssbo_m", "lay_textures_m"), 0)
        self.assertRastersNoDifference("lay_ssbo_d", "lay_textures_d", precision=0)
        self.assertLessEqual(self.differing_cells("cpu_mat", "lay_textures_m"),
                             70 * 90 // 1000)
        run = subprocess.run(
            ["r3.sbrt.render", "size=%d,%d" % size, "input=geo", "output=lay_v", "backend=egl",
             "layout=textures", "--overwrite", "--verbose"],
            capture_output=True, text=True, check=True,
        )
        self.assertIn("GPU memory, layout=textures:", run.stderr)
        self.runModule("g.region", region="geo_region")

    def test_gl_top_view_is_topmost_voxel(self):
        self.assertModule(
            "r3.sbrt.render", input="geo", output="gtop", view="top",
            material="gtop_mat", backend="egl",
        )
        self.assertRastersNoDifference("gtop_mat", "top_class", precision=0)

    def test_verbose_names_backend_and_renderer(self):
        for backend, name in (("egl", "Backend: egl"), ("cpu", "Backend: cpu")):
            run = subprocess.run(
                ["r3.sbrt.render", "input=geo", "output=vb", f"backend={backend}", "size=40,30",
                 "--overwrite", "--verbose"],
                capture_output=True, text=True, check=True,
            )
            self.assertIn(name, run.stderr)
            if backend != "cpu":
                self.assertIn("GL_VERSION: 4.", run.stderr)
                self.assertIn("GL_RENDERER: ", run.stderr)

    def test_skipping_keeps_the_image_and_reports_what_it_skipped(self):
        # a close view of one corner, strata hidden, a plane: much to skip
        size = image_region(self, 80, 60)
        view = dict(input="geo", position=(-300, -300, 900), target=(500, 600, 200),
                    fov=30, hide="13", plane=(1000, 1250, 300, 1, 0, 0), backend="cpu")
        text = {k: ",".join(map(str, v)) if isinstance(v, tuple) else v
                for k, v in view.items()}
        run = subprocess.run(
            ["r3.sbrt.render", "size=%d,%d" % size, "output=sk", "material=sk_m", "depth=sk_d",
             "--overwrite", "--verbose"] + [f"{k}={v}" for k, v in text.items()],
            capture_output=True, text=True, check=True,
        )
        # hidden while tracing (no pass over the model), on the CPU and
        # the GPU alike
        for line in ("1 hidden strata: crossed as air while tracing", "Empty-space skipping:",
                     "First pass: ", "Streamed: "):
            self.assertIn(line, run.stderr)
        self.assertNotIn("Skipped, 1 hidden strata:", run.stderr)
        # the CPU never reads what no ray reaches: only the GPU path prunes
        self.assertNotIn("Skipped, out of the view:", run.stderr)
        gl = subprocess.run(
            ["r3.sbrt.render", "size=%d,%d" % size, "output=skg", "material=skg_m", "--overwrite",
             "--verbose"] + [f"{k}={v}" for k, v in text.items() if k != "backend"]
            + ["backend=egl", "layout=textures"],  # the whole model (ssbo: its blocks as reached)
            capture_output=True, text=True, check=True,
        )
        for line in ("Skipped, out of the view:", "Skipped, cut away by the planes:",
                     "1 hidden strata: crossed as air while tracing"):
            self.assertIn(line, gl.stderr)
        self.runModule("r.mapcalc", overwrite=True,
                       expression="skg_diff = if(isnull(sk_m) != isnull(skg_m) || "
                                  "sk_m != skg_m, 1, 0)")
        differ = gs.parse_command("r.univar", map="skg_diff", flags="g")
        # float32 on the GPU: a few pixels on edges may differ
        self.assertLess(float(differ["sum"]), 0.01 * float(differ["n"]))
        self.assertModule("r3.sbrt.render", size=size, flags="e", output="ns", material="ns_m",
                          depth="ns_d", overwrite=True, **view)
        hits = int(gs.parse_command("r.univar", map="sk_m", flags="g")["n"])
        self.assertGreater(hits, 600)
        # the same image with every cell walked
        for a, b in (("sk_m", "ns_m"), ("sk.red", "ns.red"), ("sk_d", "ns_d")):
            self.runModule("r.mapcalc", overwrite=True,
                           expression=f"sk_diff = if(isnull({a}) != isnull({b}) || "
                                      f"abs({a} - {b}) > 0.000001, 1, 0)")
            self.assertRasterMinMax("sk_diff", refmin=0, refmax=0, msg=f"{a} vs {b}")
        self.runModule("g.region", region="geo_region")

    def test_missing_gl_is_a_clear_error(self):
        # glvnd without any EGL vendor: EGL cannot work at all
        env = dict(os.environ, __EGL_VENDOR_LIBRARY_FILENAMES="/nonexistent.json")
        run = subprocess.run(
            ["r3.sbrt.render", "input=geo", "output=noegl", "backend=egl", "size=40,30"],
            capture_output=True, text=True, env=env,
        )
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("backend=egl", run.stderr)
        self.assertIn("egl (surfaceless)", run.stderr)
        self.assertRasterDoesNotExist("noegl.red")
        # auto falls back and still renders
        run = subprocess.run(
            ["r3.sbrt.render", "input=geo", "output=noegl", "backend=auto", "size=40,30"],
            capture_output=True, text=True, env=env,
        )
        self.assertEqual(run.returncode, 0, msg=run.stderr)
        self.assertRasterExists("noegl.red")

    def test_auto_without_a_gpu_device_takes_the_cpu_at_once(self):
        nodes = glob.glob("/dev/dri/renderD*") + [
            n for n in ("/dev/nvidiactl", "/dev/dxg") if os.path.exists(n)]
        run = subprocess.run(
            ["r3.sbrt.render", "input=geo", "output=auto_img", "backend=auto", "size=40,30",
             "--verbose", "--overwrite"],
            capture_output=True, text=True,
        )
        self.assertEqual(run.returncode, 0, msg=run.stderr)
        if nodes:  # a GPU may be there: EGL is tried
            self.assertNotIn("No GPU device", run.stderr)
        else:  # Mesa is not even loaded
            self.assertIn("No GPU device", run.stderr)
            self.assertIn("Backend: cpu", run.stderr)
            self.assertNotIn("software", run.stderr)

    def test_kernel_normals_shade_but_keep_materials(self):
        size = image_region(self, 80, 60)
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="nf", material="nf_m")
        self.assertModule(
            "r3.sbrt.render", size=size, input="geo", output="nk", material="nk_m",
            normals="kernel", kernel=7, smooth=1.5,
        )
        self.assertEqual(self.differing_cells("nf_m", "nk_m"), 0)
        self.assertGreater(self.differing_cells("nf.red", "nk.red"), 100)
        # without smoothing the GPU finds the kernel normals itself: the
        # CPU's image but for float rounding on a few pixels
        for backend in ("cpu", "egl"):
            run = subprocess.run(
                ["r3.sbrt.render", "size=%d,%d" % size, "input=geo", f"output=nk_{backend}",
                 "normals=kernel", "kernel=5", f"backend={backend}", "--overwrite",
                 "--verbose"],
                capture_output=True, text=True,
            )
            self.assertEqual(run.returncode, 0, msg=run.stderr)
        self.assertIn("Shading: on the GPU", run.stderr)
        self.runModule(
            "r.mapcalc", overwrite=True,
            expression="nk_far = abs(nk_cpu.red - nk_egl.red) > 1 || "
            "abs(nk_cpu.green - nk_egl.green) > 1",
        )
        far = int(float(gs.parse_command("r.univar", map="nk_far", flags="g")["sum"]))
        self.assertLessEqual(far, 80 * 60 // 100)
        self.assertGreater(self.differing_cells("nk_egl.red", "nf.red"), 100)
        self.assertModuleFail("r3.sbrt.render", size=size, input="geo", output="bad",
                              normals="kernel", kernel=4)
        self.runModule("g.region", region="geo_region")

    def test_color_rules_recolour_materials(self):
        rules = gs.tempfile()
        with open(rules, "w") as f:
            f.write("13 255:0:0\ndefault 0:0:255\n")
        self.assertModule(
            "r3.sbrt.render", input="geo", output="rul", view="top",
            material="rul_m", rules=rules, ambient=1,
        )
        # ambient=1: no shading, the pixel is the rule's colour
        stats = gs.read_command("r.stats", flags="n", input="rul_m,rul.red,rul.blue")
        for line in stats.splitlines():
            cls, red, blue = (int(v) for v in line.split())
            if cls == 13:
                self.assertEqual((red, blue), (255, 0))
        self.assertIn("13 255:0:0", gs.read_command("r.colors.out", map="rul_m"))
        self.assertModule("r3.sbrt.render", input="geo", output="gry", view="top",
                          color="grey", ambient=1)
        self.runModule("r.mapcalc", overwrite=True,
                       expression="notgrey = gry.red != gry.green || gry.red != gry.blue")
        self.assertRasterMinMax("notgrey", refmin=0, refmax=0)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad",
                              color="grey", rules=rules)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad",
                              rules="/nonexistent/rules.txt")

    def test_hidden_strata_give_the_subcrop_map(self):
        """view=top with hide= is the first visible class from the top."""
        hidden = (13, 12)
        expr = "null()"
        for z in range(1, self.depths + 1):
            sl = f"sl_{z:05d}"
            # ||| is true when one side is, even if the other is null
            skip = " ||| ".join([f"isnull({sl})"] + [f"{sl} == {h}" for h in hidden])
            expr = f"if({skip}, {expr}, {sl})"
        self.runModule("r.mapcalc", expression=f"subcrop = int({expr})", overwrite=True)
        self.assertModule(
            "r3.sbrt.render", input="geo", output="sub", view="top",
            material="sub_mat", hide=["13", "conglomerate"],  # an id and a label
        )
        self.assertRastersNoDifference("sub_mat", "subcrop", precision=0)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", hide="nosuch")
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", hide="99")

    def test_horizontal_plane_is_a_voxel_slice(self):
        """view=top cut at the centre of voxel level k: r3.to.rast's slice k,
        and below the slice's nulls the first class further down."""
        for level in (20, 41):  # 1-based like r3.to.rast
            z0 = (level - 0.5) * 10.0
            expr = "null()"
            for z in range(1, level + 1):
                sl = f"sl_{z:05d}"
                expr = f"if(isnull({sl}), {expr}, {sl})"
            self.runModule("r.mapcalc", expression=f"cut_want = int({expr})",
                           overwrite=True)
            for backend in ("cpu", "egl"):
                self.assertModule(
                    "r3.sbrt.render", input="geo", output="cut", view="top",
                    material="cut_mat", plane=[0, 0, z0, 0, 0, 1], backend=backend,
                    hit_elevation="cut_z", overwrite=True,
                )
                self.assertRastersNoDifference("cut_mat", "cut_want", precision=0)
                # where the slice holds a class, the hit is on the plane
                self.runModule(
                    "r.mapcalc", overwrite=True,
                    expression=f"cut_off = if(isnull(sl_{level:05d}), null(), abs(cut_z - {z0}))",
                )
                # float on the GPU: 1e-3 m in 640 m
                self.assertRasterMinMax("cut_off", refmin=0, refmax=1e-3)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad",
                              plane=[0, 0, 10, 0, 0, 0])
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad",
                              plane=[0, 0, 10, 0, 0])
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad",
                              section=[10, 10, 10, 10])

    def test_section_removes_the_side_facing_the_camera(self):
        size = image_region(self, 80, 60)
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="whole", depth="whole_d")
        # a north-south section 200 m east of the west edge, seen from the
        # south-west (default camera): the west part is removed, so what is
        # seen lies farther away on average
        self.assertModule(
            "r3.sbrt.render", size=size, input="geo", output="cut", depth="cut_d",
            section=[200, 0, 200, 500], overwrite=True,
        )
        whole = gs.parse_command("r.univar", map="whole_d", flags="g")
        cut = gs.parse_command("r.univar", map="cut_d", flags="g")
        self.assertGreater(float(cut["mean"]), float(whole["mean"]))
        self.runModule("g.region", region="geo_region")

    def test_maps_are_lz4_unless_grass_compressor_says_otherwise(self):
        size = image_region(self, 40, 30)
        env = {k: v for k, v in os.environ.items() if k != "GRASS_COMPRESSOR"}
        subprocess.run(["r3.sbrt.render", "size=%d,%d" % size, "input=geo", "output=lz", "material=lz_m",
                        "--overwrite", "--quiet"], env=env, check=True)
        subprocess.run(["r3.sbrt.render", "size=%d,%d" % size, "input=geo", "output=zs", "--overwrite",
                        "--quiet"], env=dict(env, GRASS_COMPRESSOR="ZSTD"), check=True)
        for name, method in (("lz.red", "LZ4"), ("lz_m", "LZ4"), ("zs.red", "ZSTD")):
            line = gs.read_command("r.compress", map=name, flags="g").strip()
            self.assertEqual(line.split("|")[2], method, msg=line)
        # the same pixels whatever the compressor
        self.assertRastersNoDifference("lz.red", "zs.red", precision=0)
        self.runModule("g.region", region="geo_region")

    def test_png_file_holds_the_image(self):
        from PIL import Image

        size = image_region(self, 40, 30)
        png = gs.tempfile() + ".png"
        # -n: the image alone (annotated PNGs: test_r3_sbrt_grass_native.py)
        self.assertModule("r3.sbrt.render", size=size, input="geo", output="pn", png=png,
                          flags="n")
        self.assertFalse(os.path.exists(png + ".tmp"))
        with Image.open(png) as image:
            self.assertEqual(image.format, "PNG")
            self.assertEqual((image.size, image.mode), ((40, 30), "RGB"))
            pixels = list(image.getdata())
        # the pixels, decoded by Pillow, against the red, green, blue maps
        for k, band in enumerate(("red", "green", "blue")):
            text = gs.read_command("r.out.ascii", input=f"pn.{band}", flags="h")
            want = [int(v) for v in text.split()]
            self.assertEqual([p[k] for p in pixels], want, msg=band)
        self.assertGreater(len(set(pixels)), 10, msg="a picture, not a flat colour")
        self.runModule("g.region", region="geo_region")

    def test_bad_camera_fails(self):
        self.assertModuleFail(
            "r3.sbrt.render", input="geo", output="bad",
            position=[1, 2, 3], target=[1, 2, 3],
        )
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", fov=0)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", fov=180)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", zexag=0)
        # a top view of a region away from the model: an error, not a blank map
        self.runModule("g.region", n=9000, s=8000, e=9000, w=8000, res=100)
        self.assertModuleFail("r3.sbrt.render", input="geo", output="bad", view="top")
        self.assertRasterDoesNotExist("bad.red")
        self.runModule("g.region", region="geo_region")

    def test_image_too_large_for_memory_is_a_clear_error(self):
        # streamed, an image needs two bands of memory; kernel normals may
        # read the whole image: 60,000 x 60,000 pixels would need some 450 GB
        run = subprocess.run(
            ["r3.sbrt.render", "input=geo", "output=huge", "backend=cpu",
             "normals=kernel", "size=60000,60000"],
            capture_output=True, text=True,
        )
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("60000 x 60000 pixels needs about", run.stderr)
        self.assertIn("size=", run.stderr)
        self.assertRasterDoesNotExist("huge.red")

    def test_missing_and_corrupt_sbrt_fail(self):
        # (not through pygrass: it checks input= against the SBRTs itself)
        run = subprocess.run(["r3.sbrt.render", "input=nosuch", "output=bad"],
                             capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("SBRT <nosuch> not found", run.stderr)
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


class TestRenderReadsOnlyTheRegion(TestCase):
    """A top view of part of an SBRT decompresses only the blocks under it."""

    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        # 200 rows x 160 cols: 4 x 3 blocks of 64 x 64 cells
        cls.runModule("g.region", n=2000, s=0, e=1600, w=0, res=10, t=120, b=0,
                      res3=10, tbres=10)
        cls.runModule(
            "r3.mapcalc",
            expression="blocks = if(depth() > 6 + (row() + col()) % 5, null(), "
            "1 + (row() / 17 + col() / 13 + depth()) % 5)",
        )
        cls.runModule("r3.sbrt.convert", input="blocks", output="blocks")
        cls.runModule("r3.sbrt.render", input="blocks", output="rw_whole", view="top",
                      material="rw_whole_m", hit_elevation="rw_whole_z", depth="rw_whole_d")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def render_part(self, *extra, model="blocks"):
        # rows 70..110, cols 50..90: grown by a cell, block row 1, block cols 0 and 1
        self.runModule("g.region", n=1300, s=890, e=910, w=500, res=10)
        run = subprocess.run(
            ["r3.sbrt.render", "--verbose", "--o", "input=" + model, "output=rw_part",
             "view=top", "material=rw_part_m", "hit_elevation=rw_part_z", *extra],
            capture_output=True, text=True,
        )
        self.assertEqual(run.returncode, 0, run.stderr)
        return run.stderr

    def assert_part_is_the_whole(self):
        for whole, part in (("rw_whole_m", "rw_part_m"), ("rw_whole_z", "rw_part_z"),
                            ("rw_whole.red", "rw_part.red"), ("rw_whole.green", "rw_part.green"),
                            ("rw_whole.blue", "rw_part.blue")):
            self.assertRastersNoDifference(part, whole, precision=0)

    def test_part_equals_the_whole_render_there(self):
        stderr = self.render_part()
        # paged (the CPU draws it): every ray from above stops in its
        # column's top interval, which the SBRT's tops member holds: no
        # block is decoded
        self.assertIn("Paged model: 0 of the 12 blocks decoded", stderr)
        self.assert_part_is_the_whole()

    def test_without_the_tops_the_blocks_under_the_region_are_read(self):
        # an SBRT written before the tops member: the rays decode the two
        # blocks under the region, and draw the same
        self.runModule("r3.sbrt.manage", copy=["blocks", "blocks_untopped"], overwrite=True)
        os.remove(os.path.join(gs.gisenv()["GISDBASE"], gs.gisenv()["LOCATION_NAME"],
                               gs.gisenv()["MAPSET"], "sbrt", "blocks_untopped", "tops"))
        stderr = self.render_part(model="blocks_untopped")
        self.assertIn("Paged model: 2 of the 12 blocks decoded", stderr)
        self.assert_part_is_the_whole()

    def test_depth_map_is_measured_from_above_the_whole_model(self):
        # the depth of a top view is measured from a camera above the whole
        # model: the model is paged (each column's range and top interval
        # read from its members), and no block is decoded
        stderr = self.render_part("depth=rw_part_d")
        self.assertIn("SBRT <blocks> paged: its 12 blocks", stderr)
        self.assertIn("Paged model: 0 of the 12 blocks decoded", stderr)
        self.assertRastersNoDifference("rw_part_d", "rw_whole_d", precision=1e-9)

    def test_memory_bounds_the_process(self):
        # memory= holds the process itself (its code, GRASS, the image's
        # buffers) beside the model's blocks: 1 MB is refused, with the
        # least that works, and no map is written; that least renders
        self.runModule("g.region", n=1300, s=890, e=910, w=500, res=10)
        args = ["r3.sbrt.render", "--o", "input=blocks", "output=rw_mem", "view=top",
                "backend=cpu", "material=rw_mem_m"]
        run = subprocess.run(args + ["memory=1"], capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        error = " ".join(run.stderr.split())
        self.assertIn("the rest of this process", error)
        least = re.search(r"give memory= at least (\d+)", error)
        self.assertTrue(least, error)
        self.assertRasterDoesNotExist("rw_mem_m")
        # (the process is not measured at the same moment: some room)
        run = subprocess.run(args + ["memory=%d" % (int(least.group(1)) + 20)],
                             capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertRastersNoDifference("rw_mem_m", "rw_whole_m", precision=0)


if __name__ == "__main__":
    test()
