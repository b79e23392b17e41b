"""
MODULE:    testsuite/test_r3_sbrt_channels.py (r3.sbrt addon)
PURPOSE:   Property channels (issue 29): r3.sbrt.convert file= properties=
           keeps per-voxel variables beside the classes; -r property=
           expands one back, equal voxel for voxel to the same values read
           by GRASS's own r3.in.ascii (fills and voxels outside the
           classes' columns null); -p/-g list them; -a takes every variable
           on the classes' grid; bad properties are refused by name
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import Raster3dCompare, error_of
from shell_output import shell_records

FILL = -127
NX, NY, NZ = 14, 17, 40
X0, Y0, Z0 = 120000, 480000, -49.75
DX, DY, DZ = 100, 100, 0.5


def lithok(i, j, k):
    """Classes under a ground level, a cave, sea columns (all fill)."""
    if (i * 7 + j * 3) % 23 == 0:
        return FILL
    ground = NZ - 1 - (i * 5 + j * 11) % 13
    if k > ground or (10 <= k < 13 and (i + j) % 5 == 0):
        return FILL
    return 1 + (k // 8 + i // 4 + j // 5) % 9


def kans(i, j, k):
    """A percentage (short with a fill), set in caves too, missing in some
    voxels with a class."""
    if (lithok(i, j, k) == FILL and not (10 <= k < 13)) or (i + j + k) % 17 == 0:
        return FILL
    return (i * 13 + j * 7 + k * 3) % 101


def porosity(i, j, k):
    """Floats with fractions (exact in float32), negative ones included."""
    return ((i * 31 + j * 17 + k * 5) % 97) / 8.0 - 3.0


def packed(i, j, k):
    """A short packed with scale_factor 0.01 and add_offset 5."""
    return (i * 101 + j * 53 + k * 29) % 3000 - 1500


PROPERTIES = {
    "kans_5": ("short", kans, f'kans_5:_FillValue = {FILL}s ; kans_5:units = "%" ; '
               'kans_5:long_name = "kans op lithoklasse 5" ;'),
    "porosity": ("float", porosity, 'porosity:long_name = "porosity" ;'),
    "kh": ("short", packed, 'kh:scale_factor = 0.01 ; kh:add_offset = 5.0 ; '
           'kh:units = "m/d" ;'),
}


def write_netcdf(path, order=("x", "y", "z"), properties=PROPERTIES, extra_vars=""):
    sizes = {"x": NX, "y": NY, "z": NZ}

    def values(f):
        out = []

        def walk(level, at):
            if level == 3:
                out.append(cdl_number(f(at["x"], at["y"], at["z"])))
                return
            for t in range(sizes[order[level]]):
                at[order[level]] = t
                walk(level + 1, at)

        walk(0, {})
        return ", ".join(out)

    dims = ", ".join(order)
    declarations = [f"short lithok({dims}) ; lithok:_FillValue = {FILL}s ;"]
    data = [f"lithok = {values(lithok)} ;"]
    for name, (kind, f, attributes) in properties.items():
        declarations.append(f"{kind} {name}({dims}) ; {attributes}")
        data.append(f"{name} = {values(f)} ;")
    cdl = f"""netcdf channels {{
dimensions:
  x = {NX} ; y = {NY} ; z = {NZ} ; w = 3 ;
variables:
  int x(x) ; x:standard_name = "projection_x_coordinate" ; x:units = "m" ;
  int y(y) ; y:standard_name = "projection_y_coordinate" ; y:units = "m" ;
  float z(z) ; z:positive = "up" ; z:units = "m" ;
  {" ".join(declarations)}
  {extra_vars}
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


def cdl_number(v):
    """A value as CDL writes it (ncgen reads NaN and Infinity)."""
    if v != v:
        return "NaN"
    if v in (float("inf"), float("-inf")):
        return "Infinity" if v > 0 else "-Infinity"
    return repr(v)


def failure_of(*args):
    """A module run's return code and its messages on one line."""
    run = subprocess.run(args, capture_output=True, text=True, timeout=120)
    return run.returncode, " ".join(run.stderr.split())


def temporary_files():
    """The files of the mapset's .tmp (G_tempfile's folder)."""
    env = gs.gisenv()
    tmp = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], ".tmp")
    return {os.path.join(d, f) for d, _, files in os.walk(tmp) for f in files}


def span(i, j):
    """The voxels of column (i, j) that keep channel values."""
    solid = [k for k in range(NZ) if lithok(i, j, k) != FILL]
    return (min(solid), max(solid) + 1) if solid else (0, 0)


def write_reference(path, f, null_value=None, transform=lambda v: v):
    """What -r property= must give: f inside the spans, null elsewhere and
    where f is the fill."""
    lines = [
        f"north: {Y0 + DY * (NY - 1) + DY / 2}", f"south: {Y0 - DY / 2}",
        f"east: {X0 + DX * (NX - 1) + DX / 2}", f"west: {X0 - DX / 2}",
        f"top: {Z0 + DZ * (NZ - 1) + DZ / 2}", f"bottom: {Z0 - DZ / 2}",
        f"rows: {NY}", f"cols: {NX}", f"levels: {NZ}",
    ]
    for k in range(NZ):
        for j in reversed(range(NY)):
            row = []
            for i in range(NX):
                lo, hi = span(i, j)
                v = f(i, j, k)
                row.append("*" if not lo <= k < hi or v == null_value
                           else repr(transform(v)))
            lines.append(" ".join(row))
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


class TestChannels(TestCase, Raster3dCompare):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_channels_")
        cls.file = os.path.join(cls.tmp, "channels.nc")
        write_netcdf(cls.file)
        cls.runModule("r3.sbrt.convert", file=cls.file, variable="lithok",
                      properties="kans_5,porosity,kh", output="with_channels",
                      memory=1, preset="none", flags="s")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def expanded_equals(self, sbrt, channel, f, **reference):
        ascii3d = os.path.join(self.tmp, channel + ".txt")
        write_reference(ascii3d, f, **reference)
        self.runModule("r3.in.ascii", input=ascii3d, output="expected_" + channel,
                       overwrite=True)
        self.assertModule("r3.sbrt.convert", flags="r", sbrt=sbrt, property=channel,
                          output="back_" + channel)
        n, differing = self.count_differences("expected_" + channel, "back_" + channel)
        self.assertEqual(n, NX * NY * NZ)
        self.assertEqual(differing, 0, channel)

    def test_each_channel_expands_to_the_source_values(self):
        """Percentages with their fill (caves keep their values), floats,
        and a packed channel as its meaning (stored * 0.01 + 5)."""
        self.expanded_equals("with_channels", "kans_5", kans, null_value=FILL)
        self.expanded_equals("with_channels", "porosity", porosity)
        self.expanded_equals("with_channels", "kh", packed,
                             transform=lambda v: v * 0.01 + 5.0)
        info = gs.raster3d_info("back_kh")
        self.assertEqual(info["datatype"], '"DCELL"')
        self.assertEqual(gs.raster3d_info("back_kans_5")["datatype"], '"FCELL"')

    def test_any_axis_order_gives_the_same_channels(self):
        """z slowest: the same channels member, byte for byte."""
        other = os.path.join(self.tmp, "zyx.nc")
        write_netcdf(other, order=("z", "y", "x"))
        self.assertModule("r3.sbrt.convert", file=other, variable="lithok",
                          properties="kans_5,porosity,kh", output="zyx",
                          preset="none")
        env = gs.gisenv()
        base = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], "sbrt")
        with open(os.path.join(base, "zyx", "channels"), "rb") as a, open(
                os.path.join(base, "with_channels", "channels"), "rb") as b:
            self.assertEqual(a.read(), b.read())

    def test_p_and_g_list_the_channels(self):
        listing = gs.read_command("r3.sbrt.convert", flags="p", sbrt="with_channels")
        self.assertIn("Property channels: 3", listing)
        self.assertIn("kans_5", listing)
        self.assertIn("kans op lithoklasse 5", listing)
        self.assertIn("value = stored * 0.01 + 5", listing)
        output = gs.read_command("r3.sbrt.convert", flags="g", sbrt="with_channels")
        lines = output.splitlines()
        channels = {c["channel"]: c for c in shell_records(output, "channel")}
        self.assertEqual(sorted(channels), ["kans_5", "kh", "porosity"])
        self.assertEqual(channels["kans_5"]["type"], "i8")  # 0..100, fill -127
        self.assertEqual(channels["kh"]["type"], "i16")
        self.assertEqual(channels["porosity"]["type"], "f32")
        self.assertEqual(float(channels["kans_5"]["max"]), 100)
        self.assertEqual(channels["kans_5"]["unit"], "%")
        voxels = sum(span(i, j)[1] - span(i, j)[0] for i in range(NX) for j in range(NY))
        self.assertEqual(int(channels["porosity"]["voxels"]), voxels)
        self.assertGreater(float(channels["kans_5"]["bytes_per_voxel"]), 0)
        self.assertIn("channels=3", lines)

    def test_a_takes_every_variable_on_the_grid(self):
        other = os.path.join(self.tmp, "extra.nc")
        write_netcdf(other, extra_vars="short flat(x, y) ; short other(w) ;")
        self.assertModule("r3.sbrt.convert", file=other, variable="lithok",
                          flags="a", output="all_channels", preset="none")
        listing = gs.read_command("r3.sbrt.convert", flags="g", sbrt="all_channels")
        names = sorted(c["channel"] for c in shell_records(listing, "channel"))
        self.assertEqual(names, ["kans_5", "kh", "porosity"])

    def test_classes_alone_still_have_no_channels(self):
        self.assertModule("r3.sbrt.convert", file=self.file, variable="lithok",
                          output="classes_only", preset="none")
        self.assertNotIn("channel", gs.read_command("r3.sbrt.convert", flags="g",
                                                    sbrt="classes_only"))
        code, err = error_of("r3.sbrt.convert", "-r", "sbrt=classes_only",
                             "property=kans_5", "output=none_back")
        self.assertNotEqual(code, 0)
        self.assertIn("has no property channels", err)

    def test_top_view_shows_the_topmost_voxels_value(self):
        """property= value= on a top view: every cell's value is the channel's
        at the column's topmost solid voxel (null where that is the fill or
        the column is empty); the packed channel as meant."""
        self.runModule("r3.sbrt.convert", flags="s", sbrt="with_channels")
        self.assertModule("r3.sbrt.render", input="with_channels", view="top",
                          property="kans_5", value="top_kans", material="top_class",
                          png=os.path.join(self.tmp, "top.png"))
        rows = gs.read_command("r.out.ascii", input="top_kans", flags="h",
                               null_value="*").split("\n")
        compared = nulls = 0
        for r in range(NY):
            cells = rows[r].split()
            j = NY - 1 - r
            for i in range(NX):
                solid = [k for k in range(NZ) if lithok(i, j, k) != FILL]
                want = "*" if not solid or kans(i, j, max(solid)) == FILL \
                    else str(kans(i, j, max(solid)))
                self.assertEqual(cells[i], want, (i, j))
                compared += 1
                nulls += want == "*"
        self.assertEqual(compared, NX * NY)
        self.assertGreater(nulls, 0)
        self.assertLess(nulls, compared / 2)
        # the packed channel as meant, the PNG with its colour bar
        self.assertModule("r3.sbrt.render", input="with_channels", view="top",
                          property="kh", value="top_kh")
        stats = gs.parse_command("r.univar", map="top_kh", flags="g")
        self.assertAlmostEqual(float(stats["min"]), min(
            packed(i, j, max(k for k in range(NZ) if lithok(i, j, k) != FILL)) * 0.01 + 5
            for i in range(NX) for j in range(NY)
            if any(lithok(i, j, k) != FILL for k in range(NZ))), places=9)
        self.assertEqual(gs.read_command("r.info", map="top_kans", flags="e")
                         .count("units"), 1)
        with open(os.path.join(self.tmp, "top.png"), "rb") as f:
            header = f.read(24)
        width = int.from_bytes(header[16:20], "big")
        self.assertGreater(width, NX)  # the image and its legend panel

    def test_select_keeps_the_voxels_meeting_the_condition(self):
        """select= on a top view: each cell shows the class (and value) of the
        topmost voxel whose kans_5 is at least 60 (fills never meet it)."""
        self.runModule("r3.sbrt.convert", flags="s", sbrt="with_channels")
        self.assertModule("r3.sbrt.render", input="with_channels", view="top",
                          select="kans_5>=60", material="shell_class", property="kans_5",
                          value="shell_value")
        classes = gs.read_command("r.out.ascii", input="shell_class", flags="h",
                                  null_value="*").split("\n")
        values = gs.read_command("r.out.ascii", input="shell_value", flags="h",
                                 null_value="*").split("\n")
        shown = 0
        for r in range(NY):
            j = NY - 1 - r
            got_classes, got_values = classes[r].split(), values[r].split()
            for i in range(NX):
                meeting = [k for k in range(NZ) if lithok(i, j, k) != FILL
                           and kans(i, j, k) != FILL and kans(i, j, k) >= 60]
                top = max(meeting) if meeting else None
                self.assertEqual(got_classes[i],
                                 "*" if top is None else str(lithok(i, j, top)), (i, j))
                self.assertEqual(got_values[i],
                                 "*" if top is None else str(kans(i, j, top)), (i, j))
                shown += top is not None
        self.assertGreater(shown, NX * NY // 4)

    def test_property_views_on_the_gpu_equal_the_cpu(self):
        """On the GPU (egl, llvmpipe here): select= makes a model of the voxels
        meeting the condition, traced as any other and shaded there;
        property= and fade= of whole-numbered channels are coloured there
        too, and with a value= map on the host at the GPU's hits. Each
        view's class map, value= map and colours equal the CPU's (within
        1/500 of the pixels; a colour level apart)."""
        self.runModule("r3.sbrt.convert", flags="s", sbrt="with_channels")
        size = (96, 72)
        view = ["input=with_channels", "size=%d,%d" % size, "zexag=40", "azimuth=210",
                "elevation=40", "--verbose", "--overwrite"]
        scenes = (("sel", ["select=kans_5>=40"], "Shading: on the GPU"),
                  ("prop", ["property=kans_5",
                            "value=prop_{backend}_v"], "at the GPU's hits"),
                  ("gpuprop", ["property=kans_5"], "Shading: on the GPU"),
                  ("fade", ["fade=kans_5", "fade_range=0,100"], "Shading: on the GPU"))
        pixels = size[0] * size[1]
        for name, options, shading in scenes:
            maps = {}
            for backend in ("egl", "cpu"):
                run = subprocess.run(
                    ["r3.sbrt.render", f"output={name}_{backend}",
                     f"material={name}_{backend}_m", f"backend={backend}"] + view +
                    [o.format(backend=backend) for o in options],
                    capture_output=True, text=True)
                self.assertEqual(run.returncode, 0, run.stderr)
                self.assertIn(f"Backend: {backend}", run.stderr)
                if backend == "egl":
                    self.assertIn(shading, " ".join(run.stderr.split()), name)
                self.runModule("g.region", raster=f"{name}_{backend}_m")
                read = {}
                for suffix in ("_m", ".red", ".green", ".blue") + (
                        ("_v",) if name == "prop" else ()):
                    read[suffix] = gs.read_command(
                        "r.out.ascii", input=f"{name}_{backend}{suffix}", flags="h",
                        null_value="*").split()
                maps[backend] = read
            gpu, cpu = maps["egl"], maps["cpu"]
            self.assertEqual(len(gpu["_m"]), pixels)
            self.assertGreater(sum(1 for v in cpu["_m"] if v != "*"), pixels // 20, name)
            for suffix in gpu:
                if suffix.startswith("."):
                    differing = sum(1 for a, b in zip(gpu[suffix], cpu[suffix])
                                    if abs(int(a) - int(b)) > 1)
                else:
                    differing = sum(1 for a, b in zip(gpu[suffix], cpu[suffix]) if a != b)
                self.assertLessEqual(differing, pixels // 500 + 1, name + suffix)

    def test_fade_greys_the_uncertain_voxels(self):
        """fade=kans_5 on a top view: cells whose topmost voxel has 100 are
        grey, those with 0 keep the colour of the view without fade."""
        self.runModule("r3.sbrt.convert", flags="s", sbrt="with_channels")
        self.assertModule("r3.sbrt.render", input="with_channels", view="top",
                          fade="kans_5", fade_range=(0, 100), output="faded")
        self.assertModule("r3.sbrt.render", input="with_channels", view="top",
                          output="plain")
        bands = {}
        for name in ("faded", "plain"):
            bands[name] = [[row.split() for row in gs.read_command(
                "r.out.ascii", input=f"{name}.{c}", flags="h").split("\n") if row]
                for c in ("red", "green", "blue")]
        checked = 0
        for r in range(NY):
            j = NY - 1 - r
            for i in range(NX):
                solid = [k for k in range(NZ) if lithok(i, j, k) != FILL]
                if not solid:
                    continue
                u = kans(i, j, max(solid))
                faded = [bands["faded"][c][r][i] for c in range(3)]
                plain = [bands["plain"][c][r][i] for c in range(3)]
                if u == 0 or u == FILL:
                    self.assertEqual(faded, plain, (i, j, u))
                    checked += 1
                elif u == 100:
                    self.assertEqual(len(set(faded)), 1, (i, j, faded))
                    checked += 1
        self.assertGreater(checked, 10)

    def test_perspective_property_view_and_sum(self):
        self.assertModule("r3.sbrt.render", input="with_channels", zexag=5,
                          size=(160, 120), property="porosity", property_color="magma",
                          value="persp_value", material="persp_class", output="persp")
        self.runModule("g.region", raster="persp_class")
        # where a class is hit, a value (porosity has no fill); nowhere else
        self.runModule("r.mapcalc", overwrite=True,
                       expression="persp_check = isnull(persp_class) != isnull(persp_value)")
        self.assertEqual(float(gs.parse_command("r.univar", map="persp_check",
                                                flags="g")["sum"]), 0)
        self.assertGreater(int(gs.parse_command("r.univar", map="persp_value",
                                                flags="g")["n"]), 1000)
        rules = os.path.join(self.tmp, "rules.txt")
        with open(rules, "w") as f:
            f.write("0% 0:0:255\n100% 255:0:0\n")
        self.assertModule("r3.sbrt.render", input="with_channels", zexag=5,
                          size=(160, 120), property="kans_5", property_color=rules,
                          value="rules_value", output="rules_view")

    def test_bad_property_views_are_refused_by_name(self):
        cases = [
            (["input=with_channels", "property=nothing"], "no property channel 'nothing'"),
            (["input=with_channels", "property=kans_5+porosity"], "different units"),
            (["input=with_channels", "property=kans_5+kans_5"], "twice"),
            (["input=with_channels", "property=kans_5+"], "joined by +"),
            (["input=with_channels", "value=v_only"], "needs property="),
            (["input=with_channels", "property=kans_5", "property_color=no_such_table"],
             "neither a GRASS colour table"),
            (["input=classes_for_render", "property=kans_5"], "has no property channels"),
            (["input=classes_for_render", "select=kans_5>=60"], "has no property channels"),
            (["input=with_channels", "select=kans_5"], "no condition"),
            (["input=with_channels", "fade=kans_7"], "no property channel 'kans_7'"),
            (["input=with_channels", "fade_range=0,100"], "needs fade="),
            (["input=with_channels", "fade=kans_5", "fade_range=9,1"], "high above low"),
            (["input=with_channels", "select=kans_9>=1"], "no property channel 'kans_9'"),
            (["input=with_channels", "select=kans_5>=lots"], "not a number"),
        ]
        self.runModule("r3.sbrt.convert", file=self.file, variable="lithok",
                       output="classes_for_render", preset="none")
        for args, expected in cases:
            code, err = error_of("r3.sbrt.render", "output=bad_view", "size=40,30", *args)
            self.assertNotEqual(code, 0, args)
            self.assertIn(expected, err, args)
        self.assertFalse(gs.find_file("bad_view.red", element="cell")["name"])

    def test_bad_properties_are_refused_by_name(self):
        code, err = error_of("r3.sbrt.convert", f"file={self.file}", "variable=lithok",
                             "properties=kans_9", "output=bad")
        self.assertNotEqual(code, 0)
        self.assertIn("kans_9", err)
        other = os.path.join(self.tmp, "other_grid.nc")
        write_netcdf(other, properties={}, extra_vars="short small(x, y, w) ;")
        code, err = error_of("r3.sbrt.convert", f"file={other}", "variable=lithok",
                             "properties=small", "output=bad")
        self.assertNotEqual(code, 0)
        self.assertIn("small", err)
        code, err = error_of("r3.sbrt.convert", f"file={self.file}", "variable=lithok",
                             "properties=lithok", "output=bad")
        self.assertIn("class variable itself", err)
        code, err = error_of("r3.sbrt.convert", "-r", "sbrt=with_channels",
                             "property=nothing", "output=bad_back")
        self.assertNotEqual(code, 0)
        self.assertIn("no property channel 'nothing'", err)
        self.assertIn("kans_5, porosity, kh", err)
        # a double that float32 would round
        inexact = os.path.join(self.tmp, "inexact.nc")
        write_netcdf(inexact, properties={
            "fine": ("double", lambda i, j, k: 0.1 + i, 'fine:long_name = "fine" ;')})
        code, err = error_of("r3.sbrt.convert", f"file={inexact}", "variable=lithok",
                             "properties=fine", "output=bad")
        self.assertNotEqual(code, 0)
        self.assertIn("not held exactly", err)
        self.assertNotIn("bad", gs.read_command("r3.sbrt.convert", flags="l"))

    def test_bad_channel_attributes_are_refused_by_name(self):
        """Packing and missing-value attributes that would give wrong
        numbers (NaN or 0 scale, text, several values, infinities) fail
        the import naming the variable and the attribute; nothing is
        written."""
        cases = [
            ("kh:scale_factor = NaN ;", "attribute scale_factor is NaN"),
            ("kh:scale_factor = 0. ;", "attribute scale_factor is 0"),
            ('kh:scale_factor = "0.01" ;', "attribute scale_factor is text ('0.01')"),
            ("kh:scale_factor = 0.01, 0.02 ;",
             "attribute scale_factor is 2 values (0.01, 0.02)"),
            ("kh:scale_factor = 0.01 ; kh:add_offset = Infinity ;",
             "attribute add_offset is Infinity"),
            ("kh:_FillValue = Infinityf ;", "attribute _FillValue is Infinity"),
            ('kh:missing_value = "none" ;', "attribute missing_value is text ('none')"),
            ("kh:missing_value = -Infinity ;", "attribute missing_value is -Infinity"),
            ("kh:valid_range = 10s, -10s ;",
             "attribute valid_range runs from 10 down to -10"),
        ]
        for n, (attributes, expected) in enumerate(cases):
            path = os.path.join(self.tmp, f"refused_attribute_{n}.nc")
            kind, f = ("float", porosity) if "Infinityf" in attributes else ("short", packed)
            write_netcdf(path, properties={"kh": (kind, f, attributes)})
            code, err = failure_of("r3.sbrt.convert", f"file={path}", "variable=lithok",
                                   "properties=kh", f"output=refused_attribute_{n}",
                                   "preset=none")
            self.assertNotEqual(code, 0, attributes)
            self.assertIn("variable 'kh'", err, attributes)
            self.assertIn(expected, err, attributes)
        listing = gs.read_command("r3.sbrt.convert", flags="l")
        self.assertNotIn("refused_attribute", listing)

    def test_infinite_channel_values_are_refused_by_name(self):
        """A float channel holding Infinity inside a column's span fails
        the import (a view would find no colour range for it)."""
        i, j = 3, 4
        lo = span(i, j)[0]
        path = os.path.join(self.tmp, "infinite.nc")
        write_netcdf(path, properties={"porosity": (
            "float", lambda a, b, c: float("inf") if (a, b, c) == (i, j, lo) else
            porosity(a, b, c), "")})
        before = temporary_files()
        code, err = failure_of("r3.sbrt.convert", f"file={path}", "variable=lithok",
                               "properties=porosity", "output=infinite", "preset=none")
        self.assertNotEqual(code, 0)
        self.assertIn("variable 'porosity' holds Infinity", err)
        self.assertIn("valid_max", err)
        self.assertNotIn("infinite", gs.read_command("r3.sbrt.convert", flags="l"))
        # nor the channels half written beside the import
        self.assertEqual(temporary_files() - before, set())

    def test_nan_voxels_are_no_value_in_counts_and_expansion(self):
        """-g's valid count of a float channel with NaN voxels is what -r
        property= expands as non-null (NaN is null in a 3D raster)."""
        def holey(i, j, k):
            return float("nan") if (i + 2 * j + k) % 11 == 0 else porosity(i, j, k)

        path = os.path.join(self.tmp, "holey.nc")
        write_netcdf(path, properties={"porosity": ("float", holey, "")})
        self.assertModule("r3.sbrt.convert", file=path, variable="lithok",
                          properties="porosity", output="holey", preset="none")
        output = gs.read_command("r3.sbrt.convert", flags="g", sbrt="holey")
        channel = shell_records(output, "channel")[0]
        self.assertModule("r3.sbrt.convert", flags="r", sbrt="holey",
                          property="porosity", output="holey_back")
        stats = gs.parse_command("r3.univar", map="holey_back", flags="g")
        self.assertEqual(int(channel["valid"]), int(stats["n"]))
        self.assertLess(int(channel["valid"]), int(channel["voxels"]))
        valid = [porosity(i, j, k) for i in range(NX) for j in range(NY)
                 for k in range(*span(i, j)) if holey(i, j, k) == holey(i, j, k)]
        self.assertEqual(int(channel["valid"]), len(valid))
        self.assertEqual(float(channel["min"]), min(valid))
        self.assertEqual(float(channel["max"]), max(valid))

    def test_missing_value_and_valid_range_are_no_value(self):
        """Voxels a channel's missing_value or valid_range marks are no
        value, as its _FillValue's are."""
        def marked(i, j, k):
            return -999 if (i + j + k) % 7 == 0 else kans(i, j, k)

        path = os.path.join(self.tmp, "marked.nc")
        write_netcdf(path, properties={"kans_7": (
            "short", marked, f"kans_7:_FillValue = {FILL}s ; kans_7:missing_value = "
            "-999s ; kans_7:valid_max = 90s ;")})
        self.assertModule("r3.sbrt.convert", file=path, variable="lithok",
                          properties="kans_7", output="marked", preset="none")
        self.expanded_equals(
            "marked", "kans_7",
            lambda i, j, k: FILL if marked(i, j, k) in (-999, FILL) or
            marked(i, j, k) > 90 else marked(i, j, k), null_value=FILL)

    def test_probability_imported_as_classes_warns(self):
        """variable=kans_5 (units %) makes a class of every percentage: the
        warning says to keep it as a channel with properties=."""
        run = subprocess.run(
            ["r3.sbrt.convert", f"file={self.file}", "variable=kans_5",
             "output=kans_classes", "preset=none"],
            capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stderr)
        err = " ".join(run.stderr.split())
        self.assertIn("Variable kans_5 looks like a probability", err)
        self.assertIn("units %", err)
        self.assertIn("properties=kans_5", err)
        run = subprocess.run(
            ["r3.sbrt.convert", f"file={self.file}", "variable=lithok",
             "output=lithok_classes", "preset=none"],
            capture_output=True, text=True, timeout=120)
        self.assertNotIn("probability", run.stderr)


if __name__ == "__main__":
    test()
