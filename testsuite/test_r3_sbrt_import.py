"""
MODULE:    testsuite/test_r3_sbrt_import.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.convert file= variable=: NetCDF variables imported
           through GDAL, in any axis order and direction, against the same
           voxels read by GRASS's own r3.in.ascii; CRS checks; bad files
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import random
import resource
import shutil
import struct
import subprocess
import tempfile
import time
from unittest import mock

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import Raster3dCompare, run_in_new_location
from shell_output import shell_records

FILL = -127
NX, NY, NZ = 30, 60, 100  # 24 kB of doubles a row: memory=1 reads 43 rows
X0, Y0, Z0 = 120000, 480000, -49.75  # cell centres, as in GeoTOP
DX, DY, DZ = 100, 100, 0.5
RD_NEW = "EPSG:28992"


def geotop_like(seed):
    """values[i][j][k], x, y, z ascending: lithoclasses 1-9 in layers under
    a ground level, caves, and columns of fill values (sea)."""
    rnd = random.Random(seed)
    values = []
    for i in range(NX):
        plane = []
        for j in range(NY):
            if rnd.random() < 0.05:
                plane.append([FILL] * NZ)
                continue
            ground = NZ - 1 - rnd.randrange(NZ // 3)
            column = []
            for k in range(NZ):
                if k > ground:
                    column.append(FILL)
                elif 20 <= k < 24 and (i + j) % 11 == 0:
                    column.append(FILL)  # a cave
                else:
                    column.append(1 + (k * 4 // NZ + (i + 2 * j) // 9) % 9)
            plane.append(column)
        values.append(plane)
    return values


def axis_values(start, step, n, descending, negate=False):
    coords = [start + step * t for t in range(n)]
    if descending:
        coords.reverse()
    return [-c for c in coords] if negate else coords


def write_netcdf(path, values, order=("x", "y", "z"), descending=(),
                 depth_down=False, variable_type="short", extra="",
                 coords_override=None, kind="nc4",
                 flags=("1s, 2s, 3s", "anthropogenic peat clay")):
    """A CDL file for ncgen: the variable lithok with dimensions in `order`;
    axes named in `descending` run high to low; `depth_down` stores the
    vertical axis as depths (positive down); `kind` is ncgen's -k (nc4,
    classic, 64-bit-offset, cdf5); `flags` the flag_values and
    flag_meanings."""
    sizes = {"x": NX, "y": NY, "z": NZ}
    coords = {
        "x": axis_values(X0, DX, NX, "x" in descending),
        "y": axis_values(Y0, DY, NY, "y" in descending),
        "z": axis_values(Z0, DZ, NZ, "z" in descending, negate=depth_down),
    }
    if coords_override:
        coords.update(coords_override)
    index = {
        "x": lambda t: NX - 1 - t if "x" in descending else t,
        "y": lambda t: NY - 1 - t if "y" in descending else t,
        "z": lambda t: NZ - 1 - t if "z" in descending else t,
    }
    data = []

    def walk(level, at):
        if level == 3:
            i, j, k = (index[a](at[a]) for a in "xyz")
            data.append(str(values[i][j][k]))
            return
        for t in range(sizes[order[level]]):
            at[order[level]] = t
            walk(level + 1, at)

    walk(0, {})
    positive = "down" if depth_down else "up"
    cdl = f"""netcdf geotop {{
dimensions:
  x = {NX} ; y = {NY} ; z = {NZ} ;
variables:
  int x(x) ; x:standard_name = "projection_x_coordinate" ; x:units = "m" ;
  int y(y) ; y:standard_name = "projection_y_coordinate" ; y:units = "m" ;
  float z(z) ; z:positive = "{positive}" ; z:units = "m" ;
  {variable_type} lithok({", ".join(order)}) ;
    lithok:_FillValue = {FILL}{"s" if variable_type == "short" else ""} ;
    lithok:long_name = "lithoclass" ;
    lithok:flag_values = {flags[0]} ;
    lithok:flag_meanings = "{flags[1]}" ;
{extra}
data:
  x = {", ".join(str(c) for c in coords["x"])} ;
  y = {", ".join(str(c) for c in coords["y"])} ;
  z = {", ".join(repr(c) for c in coords["z"])} ;
  lithok = {", ".join(data)} ;
}}
"""
    cdl_path = path + ".cdl"
    with open(cdl_path, "w") as f:
        f.write(cdl)
    subprocess.run(["ncgen", "-k", kind, "-o", path, cdl_path], check=True)


def write_ascii3d(path, values):
    """The same voxels for r3.in.ascii: levels bottom up, rows north to
    south, columns west to east."""
    lines = [
        f"north: {Y0 + DY * (NY - 1) + DY / 2}",
        f"south: {Y0 - DY / 2}",
        f"east: {X0 + DX * (NX - 1) + DX / 2}",
        f"west: {X0 - DX / 2}",
        f"top: {Z0 + DZ * (NZ - 1) + DZ / 2}",
        f"bottom: {Z0 - DZ / 2}",
        f"rows: {NY}",
        f"cols: {NX}",
        f"levels: {NZ}",
    ]
    for k in range(NZ):
        for j in reversed(range(NY)):
            lines.append(
                " ".join(
                    "*" if values[i][j][k] == FILL else str(values[i][j][k])
                    for i in range(NX)
                )
            )
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def sbrt_dir(name):
    env = gs.gisenv()
    return os.path.join(
        env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], "sbrt", name
    )


def stacks_bytes(name):
    with open(os.path.join(sbrt_dir(name), "stacks"), "rb") as f:
        return f.read()


class TestImportNetcdf(TestCase, Raster3dCompare):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_import_")
        cls.values = geotop_like(7)
        cls.reference = os.path.join(cls.tmp, "geotop.nc")
        write_netcdf(cls.reference, cls.values)
        ascii3d = os.path.join(cls.tmp, "geotop.txt")
        write_ascii3d(ascii3d, cls.values)
        cls.runModule("r3.in.ascii", input=ascii3d, output="source", overwrite=True)
        cls.runModule("g.region", raster_3d="source")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.tmp, name)

    def test_round_trip_equals_r3_in_ascii(self):
        """file -> SBRT (two bands: memory=1) -> -r equals the voxels as
        r3.in.ascii reads them, nulls included; the frame is the file's."""
        self.assertModule(
            "r3.sbrt.convert", file=self.reference, variable="lithok",
            output="geotop", memory=1,
        )
        frame = gs.parse_command("r3.sbrt.convert", flags="g", sbrt="geotop")
        region = gs.region(region3d=True)
        for key in ("north", "south", "east", "west", "top", "bottom"):
            self.assertAlmostEqual(
                float(frame[key]), float(region[key[0]]), places=6
            )
        self.assertEqual(
            (int(frame["rows"]), int(frame["cols"]), int(frame["depths"])),
            (NY, NX, NZ),
        )
        self.assertModule("r3.sbrt.convert", flags="r", sbrt="geotop", output="back")
        n, differing = self.count_differences("source", "back")
        self.assertEqual(n, NX * NY * NZ)
        self.assertEqual(differing, 0)
        nulls = sum(v == FILL for p in self.values for c in p for v in c)
        univar = gs.parse_command("r3.univar", map="back", flags="g")
        self.assertEqual(int(univar["null_cells"]), nulls)

    def test_a_model_taller_than_a_band_is_written_band_by_band(self):
        """180 rows read 43 at a time (memory=1) are written as bands of
        whole 64-row blocks while the file is read (issue 49: the model is
        never held whole): the stacks are those of one band (memory=300),
        and -r gives back every voxel."""
        tall = [plane * 3 for plane in self.values]  # rows repeated thrice
        with mock.patch.dict(globals(), {"NY": 3 * NY}):
            write_netcdf(self.path("tall.nc"), tall)
            write_ascii3d(self.path("tall.txt"), tall)
        self.runModule("r3.in.ascii", input=self.path("tall.txt"), output="tall_source",
                       overwrite=True)
        for name, memory in (("tall_bands", 1), ("tall_one", 300)):
            self.assertModule("r3.sbrt.convert", file=self.path("tall.nc"),
                              variable="lithok", output=name, memory=memory)
        self.assertEqual(stacks_bytes("tall_bands"), stacks_bytes("tall_one"))
        self.runModule("g.region", raster_3d="tall_source")
        try:
            self.assertModule("r3.sbrt.convert", flags="r", sbrt="tall_bands",
                              output="tall_back")
            n, differing = self.count_differences("tall_source", "tall_back")
            self.assertEqual(n, NX * 3 * NY * NZ)
            self.assertEqual(differing, 0)
        finally:
            self.runModule("g.region", raster_3d="source")

    def test_any_axis_order_and_direction_gives_the_same_stacks(self):
        """z fastest or slowest, x/y descending, depths positive down: the
        same SBRT, byte for byte."""
        self.assertModule(
            "r3.sbrt.convert", file=self.reference, variable="lithok",
            output="ref",
        )
        expected = stacks_bytes("ref")
        variants = {
            "zyx": dict(order=("z", "y", "x")),
            "yxz_desc": dict(order=("y", "x", "z"), descending=("x", "y")),
            "depth": dict(order=("x", "z", "y"), descending=("z",), depth_down=True),
        }
        for name, kwargs in variants.items():
            path = self.path(name + ".nc")
            write_netcdf(path, self.values, **kwargs)
            self.assertModule(
                "r3.sbrt.convert", file=path, variable="lithok", output=name,
                memory=1,
            )
            self.assertEqual(stacks_bytes(name), expected, name)

    def test_labels_come_from_flag_meanings(self):
        self.assertModule(
            "r3.sbrt.convert", file=self.reference, variable="lithok",
            output="labelled",
        )
        report = gs.read_command("r3.sbrt.convert", flags="p", sbrt="labelled")
        self.assertIn("anthropogenic", report)
        self.assertIn("peat", report)
        with open(os.path.join(sbrt_dir("labelled"), "cats")) as f:
            self.assertIn("3:clay", f.read())

    def test_p_lists_the_variables(self):
        listing = gs.read_command("r3.sbrt.convert", flags="p", file=self.reference)
        self.assertIn("lithok", listing)
        self.assertIn("Int16", listing)
        self.assertIn("(x,y,z) = (30,60,100)", listing)
        shell = gs.read_command("r3.sbrt.convert", flags="g", file=self.reference)
        lithok = [v for v in shell_records(shell, "variable") if v["variable"] == "lithok"]
        self.assertEqual(len(lithok), 1)
        self.assertEqual((lithok[0]["type"], lithok[0]["dimensions"], lithok[0]["sizes"]),
                         ("Int16", "x,y,z", "30,60,100"))

    def test_float_variable_needs_rules(self):
        path = self.path("float.nc")
        write_netcdf(path, self.values, variable_type="float")
        self.assertModuleFail("r3.sbrt.convert", file=path, variable="lithok",
                              output="f")
        run = subprocess.run(
            ["r3.sbrt.convert", f"file={path}", "variable=lithok", "output=f"],
            capture_output=True, text=True,
        )
        self.assertIn("rules=", run.stderr)
        rules = self.path("rules.txt")
        with open(rules, "w") as f:
            f.write("1:3:1:shallow\n4:9:2:deep\n")
        self.assertModule("r3.sbrt.convert", file=path, variable="lithok",
                          output="f", rules=rules)
        report = gs.read_command("r3.sbrt.convert", flags="p", sbrt="f")
        self.assertIn("Materials:     2", report)
        self.assertIn("shallow", report)
        # values no rule covers become empty, counted voxel by voxel
        with open(rules, "w") as f:
            f.write("1:3:1:shallow\n")
        uncovered = sum(3 < v for p in self.values for c in p for v in c)
        run = subprocess.run(
            ["r3.sbrt.convert", f"file={path}", "variable=lithok",
             "output=f3", f"rules={rules}"],
            capture_output=True, text=True,
        )
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn(f"{uncovered} voxels matched no rule", " ".join(run.stderr.split()))


def error_of(*args, timeout=120, limit_memory=None):
    """rc and stderr (one line) of r3.sbrt.convert; a run past `timeout`
    seconds fails the test (a hang); `limit_memory` bytes of address space
    (ulimit -v) where given."""
    def limit():
        if limit_memory:
            resource.setrlimit(resource.RLIMIT_AS, (limit_memory, limit_memory))

    run = subprocess.run(["r3.sbrt.convert", *args], capture_output=True, text=True,
                         timeout=timeout, preexec_fn=limit)
    return run.returncode, " ".join(run.stderr.split())


class TestImportBadFiles(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_import_bad_")
        cls.values = geotop_like(3)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def refused(self, path, expected, variable="lithok", output="bad"):
        code, message = error_of(f"file={path}", f"variable={variable}",
                                 f"output={output}")
        self.assertNotEqual(code, 0, message)
        self.assertIn(expected, message)
        self.assertNotIn("terminate", message)
        self.assertFalse(os.path.exists(sbrt_dir(output)), path)
        return message

    def cdl(self, name, text):
        path = os.path.join(self.tmp, name + ".nc")
        with open(path + ".cdl", "w") as f:
            f.write(text)
        subprocess.run(["ncgen", "-k", "nc4", "-o", path, path + ".cdl"], check=True)
        return path

    def test_missing_variable_lists_the_others(self):
        path = os.path.join(self.tmp, "ok.nc")
        write_netcdf(path, self.values)
        message = self.refused(path, "has no variable 'strat'", variable="strat")
        self.assertIn("lithok", message)

    def test_2d_variable(self):
        path = self.cdl("flat", """netcdf flat { dimensions: x = 2 ; y = 2 ;
variables: int x(x) ; int y(y) ; short top(y, x) ;
data: x = 1, 2 ; y = 1, 2 ; top = 1, 2, 3, 4 ; }""")
        self.refused(path, "has 2 dimensions", variable="top")

    def test_irregular_and_non_monotonic_coordinates(self):
        path = os.path.join(self.tmp, "irregular.nc")
        xs = axis_values(X0, DX, NX, False)
        xs[5] += 30
        write_netcdf(path, self.values, coords_override={"x": xs})
        self.refused(path, "not evenly spaced")
        path = os.path.join(self.tmp, "zigzag.nc")
        ys = axis_values(Y0, DY, NY, False)
        ys[3], ys[4] = ys[4], ys[3]
        write_netcdf(path, self.values, coords_override={"y": ys})
        self.refused(path, "not monotonic")

    def test_dimension_of_length_zero(self):
        path = self.cdl("empty", """netcdf empty { dimensions: x = 2 ; y = 2 ;
z = UNLIMITED ; variables: int x(x) ; int y(y) ; float z(z) ;
short lithok(z, y, x) ; data: x = 1, 2 ; y = 1, 2 ; }""")
        self.refused(path, "has length 0")

    def test_truncated_and_garbage_files(self):
        good = os.path.join(self.tmp, "good.nc")
        write_netcdf(good, self.values)
        with open(good, "rb") as f:
            data = f.read()
        truncated = os.path.join(self.tmp, "truncated.nc")
        with open(truncated, "wb") as f:
            f.write(data[: len(data) * 2 // 3])
        code, message = error_of(f"file={truncated}", "variable=lithok",
                                 "output=bad")
        self.assertNotEqual(code, 0)
        self.assertTrue("truncated" in message or "cannot be read" in message,
                        message)
        self.assertFalse(os.path.exists(sbrt_dir("bad")))
        garbage = os.path.join(self.tmp, "garbage.nc")
        with open(garbage, "wb") as f:
            f.write(b"CDF\x01" + bytes(range(256)) * 4)
        self.refused(garbage, "cannot be read as a multidimensional file")
        self.refused(os.path.join(self.tmp, "absent.nc"), "absent.nc")

    def test_crs_is_checked_against_the_location(self):
        path = os.path.join(self.tmp, "rd.nc")
        write_netcdf(
            path, self.values,
            extra=f'  int crs ; crs:epsg_code = "{RD_NEW}" ;\n'
            '  lithok:grid_mapping = "crs" ;',
        )
        message = self.refused(path, "differs from the location's")
        self.assertIn("28992", message)
        self.assertIn("-o", message)
        self.assertModule("r3.sbrt.convert", flags="o", file=path,
                          variable="lithok", output="rd_forced")
        # in a location of the file's CRS it goes in without -o
        code, message = run_in_new_location(
            RD_NEW, ["r3.sbrt.convert", f"file={path}", "variable=lithok",
                     "output=rd"])
        self.assertEqual(code, 0, message)


def classic_header_only(path, nx, ny, nz):
    """A CDF-2 (64-bit offset) file, byte by byte as the netCDF format
    specification lays it out, that declares lithok(x, y, z) short of
    nx x ny x nz after the coordinates x, y, z but ends after these: the
    lithoclasses were never written (a copy cut short)."""
    def be32(v):
        return struct.pack(">I", v)

    def name(text):
        b = text.encode()
        return be32(len(b)) + b + b"\0" * (-len(b) % 4)

    def header(begin):
        h = b"CDF\x02" + be32(0)
        h += be32(10) + be32(3)
        h += name("x") + be32(nx) + name("y") + be32(ny) + name("z") + be32(nz)
        h += be32(0) + be32(0)  # no global attributes
        h += be32(11) + be32(4)
        at = begin
        for var, dims, nc_type, size in (
            ("x", [0], 4, 4 * nx), ("y", [1], 4, 4 * ny), ("z", [2], 5, 4 * nz),
            ("lithok", [0, 1, 2], 3, 2 * nx * ny * nz),
        ):
            h += name(var) + be32(len(dims)) + b"".join(be32(d) for d in dims)
            h += be32(0) + be32(0) + be32(nc_type)
            h += be32(min(size, 0xFFFFFFFF)) + struct.pack(">Q", at)
            at += size
        return h

    body = header(len(header(0)))
    body += b"".join(struct.pack(">i", X0 + DX * i) for i in range(nx))
    body += b"".join(struct.pack(">i", Y0 + DY * j) for j in range(ny))
    body += b"".join(struct.pack(">f", Z0 + DZ * k) for k in range(nz))
    with open(path, "wb") as f:
        f.write(body)
    return len(body), len(header(0)) + 4 * (nx + ny + nz) + 2 * nx * ny * nz


class TestImportHostileFiles(TestCase):
    """Issue 28: files that declare more than they hold, labels that do not
    pair; each refused (or warned about) at once, never imported wrong."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_import_hostile_")
        cls.values = geotop_like(5)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.tmp, name)

    def test_truncated_classic_files_are_refused(self):
        """CDF-1, CDF-2 and CDF-5 files cut short: the netCDF library reads
        zeros for the missing part, which imported as a block of class 0.
        (the GDAL here, 3.6, opens no CDF-5 file: that one is refused whole or cut, the
        cut one by its length.)"""
        for kind in ("classic", "64-bit-offset", "cdf5"):
            whole = self.path(f"whole_{kind}.nc")
            write_netcdf(whole, self.values, kind=kind)
            if kind != "cdf5":
                self.assertModule("r3.sbrt.convert", file=whole, variable="lithok",
                                  output=f"whole_{kind.replace('-', '_')}")
            size = os.path.getsize(whole)
            with open(whole, "rb") as f:
                data = f.read()
            cut = self.path(f"cut_{kind}.nc")
            with open(cut, "wb") as f:
                f.write(data[: size * 2 // 3])
            code, message = error_of(f"file={cut}", "variable=lithok", "output=cut",
                                     timeout=10)
            self.assertNotEqual(code, 0, kind)
            self.assertIn(f"file is truncated: header declares {size} bytes, file "
                          f"has {size * 2 // 3}", message)
            self.assertIn("lithok", message)
            self.assertFalse(os.path.exists(sbrt_dir("cut")), kind)

    def test_classic_file_declaring_a_huge_grid_is_refused_at_once(self):
        """30000 x 30000 x 313 declared, the coordinates written: refused by
        the length the header declares, before GDAL reads a value."""
        path = self.path("huge_classic.nc")
        has, declares = classic_header_only(path, 30000, 30000, 313)
        start = time.monotonic()
        code, message = error_of(f"file={path}", "variable=lithok", "output=huge",
                                 timeout=10)
        self.assertLess(time.monotonic() - start, 5, message)
        self.assertNotEqual(code, 0)
        self.assertIn(f"file is truncated: header declares {declares} bytes, file "
                      f"has {has}", message)
        self.assertFalse(os.path.exists(sbrt_dir("huge")))

    def test_netcdf4_grid_beyond_memory_fails_at_once_with_the_figure(self):
        """A netCDF-4 file declaring 30000 x 30000 x 313 with no lithoclass
        written (chunks never stored read as fill values) sat at 0 % for
        45 s; with 4 GiB of address space (ulimit -v) the import needs more
        than the process can have and says so before it reads."""
        path = self.path("huge.nc")
        n, nz = 30000, 313
        cdl = f"""netcdf huge {{
dimensions: x = {n} ; y = {n} ; z = {nz} ;
variables:
  int x(x) ; x:standard_name = "projection_x_coordinate" ;
  int y(y) ; y:standard_name = "projection_y_coordinate" ;
  float z(z) ; z:positive = "up" ;
  short lithok(x, y, z) ; lithok:_FillValue = -127s ;
    lithok:_ChunkSizes = 16, 16, {nz} ;
data:
  x = {", ".join(str(X0 + DX * i) for i in range(n))} ;
  y = {", ".join(str(Y0 + DY * j) for j in range(n))} ;
  z = {", ".join(repr(Z0 + DZ * k) for k in range(nz))} ;
}}
"""
        with open(path + ".cdl", "w") as f:
            f.write(cdl)
        subprocess.run(["ncgen", "-k", "nc4", "-o", path, path + ".cdl"], check=True)
        start = time.monotonic()
        code, message = error_of(f"file={path}", "variable=lithok", "output=huge4",
                                 timeout=10, limit_memory=4 << 30)
        self.assertLess(time.monotonic() - start, 5, message)
        self.assertNotEqual(code, 0)
        self.assertIn("(30000 x 30000 x 313 voxels) needs at least 4.5 GB of memory",
                      message)
        self.assertIn("900000000 cells", message)
        self.assertRegex(message, r"this machine has [0-9.]+ GB available")
        self.assertFalse(os.path.exists(sbrt_dir("huge4")))

    def test_flag_counts_that_do_not_pair_warn_and_label_nothing(self):
        """three flag_values against eight flag_meanings were taken silently,
        the first three meanings labelling classes 1-3."""
        path = self.path("flags.nc")
        write_netcdf(path, self.values,
                     flags=("1s, 2s, 3s", "a_1 b_2 c_3 d_4 e_5 f_6 g_7 h_8"))
        code, message = error_of(f"file={path}", "variable=lithok",
                                 "output=flags", timeout=60)
        self.assertEqual(code, 0, message)
        self.assertIn("flag_values has 3 values and flag_meanings 8 words", message)
        self.assertIn("no labels", message)
        with open(os.path.join(sbrt_dir("flags"), "cats")) as f:
            self.assertNotIn("a 1", f.read())

    def test_long_output_name_is_refused_up_front(self):
        """a 300-character name failed after the import with
        "AtomicDirectory: ... File name too long"."""
        path = self.path("ok.nc")
        write_netcdf(path, self.values)
        code, message = error_of(f"file={path}", "variable=lithok",
                                 "output=" + "n" * 300, timeout=60)
        self.assertNotEqual(code, 0)
        self.assertIn("has 300 characters; at most 239 are allowed", message)
        self.assertNotIn("AtomicDirectory", message)
        self.assertNotIn("Converting", message)
        # the longest name allowed goes in, and is found again
        longest = "n" * 239
        code, message = error_of(f"file={path}", "variable=lithok",
                                 f"output={longest}", timeout=60)
        self.assertEqual(code, 0, message)
        self.assertTrue(os.path.isdir(sbrt_dir(longest)))

    def test_s_sets_the_region_to_the_imported_sbrt(self):
        """-s with output=: the region (2D and 3D) becomes the file's grid."""
        self.use_temp_region()
        try:
            path = self.path("region.nc")
            write_netcdf(path, self.values)
            self.runModule("g.region", n=1, s=0, e=1, w=0, t=1, b=0, res=1,
                           res3=1, tbres=1)
            self.assertModule("r3.sbrt.convert", flags="s", file=path,
                              variable="lithok", output="region_s")
            region = gs.region(region3d=True)
            self.assertEqual((region["rows3"], region["cols3"], region["depths"]),
                             (NY, NX, NZ))
            self.assertEqual((region["rows"], region["cols"]), (NY, NX))
            self.assertAlmostEqual(region["b"], Z0 - DZ / 2)
        finally:
            self.del_temp_region()

if __name__ == "__main__":
    test()
