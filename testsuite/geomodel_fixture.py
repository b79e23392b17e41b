"""
MODULE:    testsuite/geomodel_fixture.py (r3.sbrt addon)
PURPOSE:   The set-up the tests share: the synthetic T model as a 3D
           raster and an SBRT, its slices, the class of its topmost
           non-null voxel per cell (an independent r3.to.rast + r.mapcalc),
           a small model with a probability channel, and 3D rasters
           compared voxel by voxel
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import subprocess

import grass.script as gs

HERE = os.path.dirname(os.path.abspath(__file__))
MAKE_GEOMODEL = os.path.join(HERE, "..", "tools", "make_geomodel.sh")
T_DEPTHS = 64


def error_of(*args):
    """A module run's return code and its messages, one space between words
    (GRASS wraps them at 80 columns)."""
    run = subprocess.run(args, capture_output=True, text=True)
    return run.returncode, " ".join(run.stderr.split())


def run_in_new_location(crs, args):
    """Runs a module (a list of words) in PERMANENT of a new location of
    `crs` (e.g. "EPSG:28992") beside the current one, removed after; gives
    the return code and the messages as error_of does."""
    env = gs.gisenv()
    name = "crs_" + crs.replace(":", "_").lower() + f"_{os.getpid()}"
    location = os.path.join(env["GISDBASE"], name)
    shutil.rmtree(location, ignore_errors=True)
    subprocess.run(["grass", "-c", crs, location, "-e"], check=True,
                   capture_output=True)
    gisrc = os.path.join(location, "gisrc")
    with open(gisrc, "w") as f:
        f.write(f"GISDBASE: {env['GISDBASE']}\nLOCATION_NAME: {name}\n"
                "MAPSET: PERMANENT\n")
    env = dict(os.environ, GISRC=gisrc)
    for region in ("WIND_OVERRIDE", "GRASS_REGION"):  # the test's own region
        env.pop(region, None)
    try:
        run = subprocess.run(args, capture_output=True, text=True, env=env)
    finally:
        shutil.rmtree(location, ignore_errors=True)
    return run.returncode, " ".join(run.stderr.split())


def set_up_t_model(case):
    """In a gunittest TestCase's setUpClass: maps geo (3D raster and SBRT),
    sl_00001.. (slices), top_class; the region saved as geo_region."""
    case.use_temp_region()
    subprocess.run([MAKE_GEOMODEL, "T", "geo"], check=True)
    case.runModule("r3.sbrt.convert", input="geo", output="geo")
    case.runModule("g.region", save="geo_region", overwrite=True)
    case.runModule("r3.to.rast", input="geo", output="sl")
    expr = "null()"
    for z in range(1, T_DEPTHS + 1):
        expr = f"if(isnull(sl_{z:05d}), {expr}, sl_{z:05d})"
    case.runModule("r.mapcalc", expression=f"top_class = int({expr})")


# 12 x 10 cells of 100 m, 12 levels of 2 m
CHANNEL_REGION = dict(n=1000, s=0, e=1200, w=0, t=24, b=0, res=100, res3=100, tbres=2)


def set_up_channel_model(case, classes, probability):
    """In a setUpClass, in CHANNEL_REGION: the 3D raster `classes` (classes
    1-3 up to a ground level 12 to 20 m high; r3.mapcalc counts row(),
    col() and depth() from 1, depth 1 at the bottom), the 3D raster
    `probability` (FCELL in %, titled P(sand)) and the SBRT `classes` with
    `probability` as its channel."""
    case.runModule("g.region", **CHANNEL_REGION)
    ground = "(6 + (row() * 3 + col() * 2) % 5)"
    case.runModule("r3.mapcalc", overwrite=True,
                   expression=f"{classes} = if(depth() > {ground}, null(), "
                              "1 + (depth() / 3 + col() / 4) % 3)")
    case.runModule("r3.mapcalc", overwrite=True,
                   expression=f"{probability} = "
                              "float((row() * 13 + col() * 7 + depth() * 3) % 101)")
    case.runModule("r3.support", map=probability, unit="%", title="P(sand)")
    subprocess.run(["r3.sbrt.convert", f"input={classes}", f"properties={probability}",
                    f"output={classes}", "--overwrite", "--quiet"], check=True)


def image_region(case, cols, rows):
    """Sets the region to the raster window of a cols x rows image of a
    perspective or orthographic view (square cells; r3.sbrt.render centres
    the image in the region), so its maps are read cell for cell; returns
    the size= of that image."""
    case.runModule("g.region", n=rows, s=0, e=cols, w=0, res=1)
    return (cols, rows)


class Raster3dCompare:
    """Voxels where two 3D rasters differ, nulls included (r3.mapcalc)."""

    def count_differences(self, a, b):
        self.runModule(
            "r3.mapcalc",
            overwrite=True,
            expression=f"sbrt_diff = if(isnull({a}) && isnull({b}), 0, "
            f"if(isnull({a}) || isnull({b}), 1, {a} != {b}))",
        )
        stats = gs.parse_command("r3.univar", map="sbrt_diff", flags="g")
        return int(stats["n"]), float(stats["sum"])
