"""
MODULE:    testsuite/test_r3_sbrt_render_server_options.py (r3.sbrt addon)
PURPOSE:   Every option and flag of r3.sbrt.render through the view server
           (issue 50, item 1): the option list is the module's own
           (--interface-description), so an option this test does not
           cover fails it. For each option, one server asks for frame A,
           then frame B with that option changed, then A again: B must be
           the image a fresh r3.sbrt.render draws with B's options (its PNG
           read pixel for pixel) and A again must be A, so no option is
           left out of the session's caches (a stale frame). Options the
           server refuses are listed with the reason.
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import struct
import subprocess
import tempfile
import xml.etree.ElementTree as ET
import zlib

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from server_fixture import RawServer

from geomodel_fixture import CHANNEL_REGION, set_up_channel_model

LIMIT = 60  # seconds for any one reply or process (a loaded CI machine)

# the frame every case starts from: the channel model, small
BASE = ["input=so_lith", "size=64,48"]

# Option (or -flag) -> cases (context words, the changed word, what B is to
# A): "differs" asserts the image changes, "same" that it does not, None
# neither (the GPU's image differs from the CPU's by float rounding).
BOREHOLES = ["boreholes=so_bh", "-b", "borehole_radius=80"]  # the cylinders alone
LOGS = BOREHOLES + ["log_top=dtop", "log_bottom=dbottom", "log_class=cls"]
LINE = ["path=line", "path_map=so_path", "height=30"]
CASES = {
    "input": [([], "input=so_other", "differs")],
    "view": [([], "view=orthographic", "differs"), ([], "view=top", "differs")],
    "size": [([], "size=40,30", "differs")],
    "position": [([], "position=1500,-400,40", "differs")],
    "target": [([], "target=300,700,10", "differs")],
    "azimuth": [([], "azimuth=100", "differs")],
    "elevation": [([], "elevation=60", "differs")],
    "distance": [([], "distance=5000", "differs")],
    "fov": [([], "fov=25", "differs")],
    "ortho_height": [(["view=orthographic"], "ortho_height=900", "differs")],
    "zexag": [([], "zexag=60", "differs")],
    "light": [([], "light=100,20", "differs")],
    "ambient": [([], "ambient=0.8", "differs")],
    "background": [([], "background=black", "differs")],
    "normals": [([], "normals=kernel", "differs")],
    "kernel": [(["normals=kernel"], "kernel=9", "differs")],
    "smooth": [(["normals=kernel"], "smooth=2", "differs")],
    "color": [([], "color=grey", "differs")],
    "rules": [([], "rules={rules}", "differs")],
    "hide": [([], "hide=1", "differs")],
    "opacity": [([], "opacity=1:0.3", "differs")],
    "opacity_length": [(["opacity=1:0.3"], "opacity_length=400", "differs")],
    "plane": [([], "plane=600,500,12,1,0,0", "differs")],
    "section": [([], "section=0,500,1200,500", "differs")],
    "fence": [([], "fence=so_fence", "differs")],
    "boreholes": [(["hide=1"], "boreholes=so_bh", "differs")],  # they show class 1
    "layer": [(BOREHOLES, "layer=2", "differs")],
    "where": [(BOREHOLES, "where=cat=1", "differs")],
    "borehole_radius": [(BOREHOLES, "borehole_radius=150", "differs")],
    "b": [(["boreholes=so_bh"], "-b", "differs")],
    "log_top": [(LOGS, "log_top=dtop2", "differs")],
    "log_bottom": [(LOGS, "log_bottom=dbottom2", "differs")],
    "log_class": [(LOGS[:-1], "log_class=cls", "differs")],
    "log_reference": [(LOGS, "log_reference=depth", "differs")],
    "m": [(LOGS, "-m", "differs")],
    "texture": [([], "texture=so_tex", "differs")],
    "texture_blend": [(["texture=so_tex"], "texture_blend=0.4", "differs")],
    "property": [([], "property=so_prob", "differs")],
    "property_color": [(["property=so_prob"], "property_color=magma", "differs")],
    "select": [([], "select=so_prob>=50", "differs")],
    "fade": [([], "fade=so_prob", "differs")],
    "fade_range": [(["fade=so_prob"], "fade_range=20,60", "differs")],
    # a model with a coarse level draws it; one without draws the exact one
    "detail": [(["input=so_big"], "detail=coarse", "differs"),
               ([], "detail=coarse", "same")],
    "backend": [([], "backend=egl", None)],
    "layout": [(["backend=egl"], "layout=textures", None)],
    # an atlas of 1 MB: rays that meet a block it has no room for are
    # traced on the CPU (its float rounding against the GPU's)
    "gpu_memory": [(["backend=egl"], "gpu_memory=1", None)],
    "nprocs": [([], "nprocs=1", "same")],
    # another budget (memory= holds the process too: the server's own
    # tens of MB, and the model's blocks within the rest)
    "memory": [([], "memory=211", "same")],
    "e": [([], "-e", "same")],
    "n": [([], "-n", "same")],  # the server's frames carry no annotations
    # with frames=1 a path's first frame is the view
    "path": [(["keys={keys}"], "path=keys", "differs")],
    "keys": [(["path=keys", "keys={keys}"], "keys={keys2}", "differs")],
    "path_map": [(LINE, "path_map=so_path2", "differs")],
    "height": [(LINE, "height=60", "differs")],
    "angle": [([], "angle=90", "same")],  # an orbit of one frame is the view
    "range": [([], "range=1-1", "same")],
    "fps": [([], "fps=24", "same")],
}
# what the server refuses, and why: the test asserts the list is exactly
# the module's options left out of CASES
EXCLUDED = {
    "output": "an output map: the server's frame is its reply",
    "material": "an output map: the server's frame is its reply",
    "hit_elevation": "an output map: the server's frame is its reply",
    "depth": "an output map: the server's frame is its reply",
    "value": "an output map: the server's frame is its reply",
    "png": "an output file: the server's frame is its reply",
    "strds": "an animation's output: the server draws one frame",
    "video": "an animation's output: the server draws one frame",
    "frames": "a sequence: the server draws one frame",
    "tile": "the command line's tiles of one image (r.patch)",
}
# GRASS's own flags of every module
STANDARD_FLAGS = {"overwrite", "help", "verbose", "quiet", "ui"}


def module_options():
    """The options and flags of r3.sbrt.render as its interface says."""
    xml = subprocess.run(["r3.sbrt.render", "--interface-description"], capture_output=True,
                         check=True, timeout=LIMIT).stdout
    root = ET.fromstring(xml)
    names = {p.get("name") for p in root.iter("parameter")}
    names |= {f.get("name") for f in root.iter("flag")} - STANDARD_FLAGS
    return names


def read_png(path):
    """(width, height, RGB bytes) of an 8-bit RGB PNG without interlace."""
    with open(path, "rb") as f:
        data = f.read()
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, colour, interlace) == (8, 2, 0), "not 8-bit RGB"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prior = zlib.decompress(idat), width * 3, [], bytearray(width * 3)
    for r in range(height):
        kind, line = raw[r * (stride + 1)], bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = prior[i], prior[i - 3] if i >= 3 else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prior = line
    return width, height, b"".join(rows)


def merged(words, change):
    """`words` with `change` (key=value or -flag) replacing the word of its
    key."""
    key = change.split("=", 1)[0] + "="
    return [w for w in words if not w.startswith(key)] + [change]


def with_context(words, context):
    """`words` with each word of `context` merged in (a context may name
    another input=)."""
    for word in context:
        words = merged(words, word)
    return words


class TestEveryOptionThroughTheServer(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        set_up_channel_model(cls, "so_lith", "so_prob")
        cls.runModule("r3.mapcalc", overwrite=True,
                      expression="so_other = if(depth() > 8 + col() % 3, null(), "
                                 "1 + (depth() + row()) % 3)")
        subprocess.run(["r3.sbrt.convert", "input=so_other", "output=so_other",
                        "--overwrite", "--quiet"], check=True, timeout=LIMIT)
        # the same extent in 500 x 600 cells: an SBRT with a coarse level
        cls.runModule("g.region", **dict(CHANNEL_REGION, res=2, res3=2, tbres=6))
        cls.runModule("r3.mapcalc", overwrite=True,
                      expression="so_big = if(depth() > 1 + (row() / 40 + col() / 70) % 4, "
                                 "null(), 1 + (row() / 23 + col() / 31 + depth()) % 3)")
        subprocess.run(["r3.sbrt.convert", "input=so_big", "output=so_big",
                        "--overwrite", "--quiet"], check=True, timeout=LIMIT)
        cls.runModule("g.region", **CHANNEL_REGION)
        cls.runModule("r.mapcalc", overwrite=True,
                      expression="so_tex = (row() * 37 + col() * 91) % 200")
        cls.runModule("r.colors", map="so_tex", color="rainbow")
        cls.vector("so_fence", "L 3\n 100 150\n 700 600\n 1100 900\n")
        cls.vector("so_path", "L 2\n -300 -200\n 600 500\n")
        cls.vector("so_path2", "L 2\n 1500 1300\n 600 400\n")
        gs.write_command("v.in.ascii", input="-", separator="pipe", x=2, y=3, cat=1,
                         stdin="1|250|250\n2|650|450\n3|950|750\n", output="so_bh",
                         columns="cat int, x double precision, y double precision",
                         overwrite=True, quiet=True)
        # layer 2 holds the first point only
        cls.runModule("v.category", input="so_bh", output="so_bh2", option="add", layer=2,
                      ids="1", overwrite=True)
        cls.runModule("g.rename", vector=("so_bh2", "so_bh"), overwrite=True)
        cls.runModule("db.execute", sql="DROP TABLE IF EXISTS so_log")
        cls.runModule("db.execute", sql="CREATE TABLE so_log (cat integer, "
                      "dtop double precision, dbottom double precision, "
                      "dtop2 double precision, dbottom2 double precision, cls integer)")
        # an interval of elevations (15 to 5) and one of depths (2 to 8)
        for row in ("1, 15, 5, 22, 12, 7", "1, 2, 8, 1, 3, 8", "2, 15, 5, 10, 2, 7",
                    "2, 2, 8, 4, 6, 8", "3, 15, 5, 20, 16, 8"):
            cls.runModule("db.execute", sql=f"INSERT INTO so_log VALUES ({row})")
        cls.runModule("v.db.connect", map="so_bh", table="so_log", layer=1, key="cat",
                      overwrite=True, quiet=True)
        cls.work = tempfile.mkdtemp(prefix="so_options_")
        cls.files = {"rules": os.path.join(cls.work, "rules.txt"),
                     "keys": os.path.join(cls.work, "keys.txt"),
                     "keys2": os.path.join(cls.work, "keys2.txt")}
        with open(cls.files["rules"], "w") as f:
            f.write("1 red\n2 0:120:0\n3 blue\n")
        with open(cls.files["keys"], "w") as f:
            f.write("1800 -600 80 600 500 10\n1900 1600 80 600 500 10\n")
        with open(cls.files["keys2"], "w") as f:
            f.write("-600 1600 60 600 500 10 30\n-600 -600 60 600 500 10\n")
        cls.server = RawServer(LIMIT)

    @classmethod
    def vector(cls, name, text):
        gs.write_command("v.in.ascii", input="-", stdin=text, output=name,
                         format="standard", flags="n", overwrite=True, quiet=True)

    @classmethod
    def tearDownClass(cls):
        cls.server.close()
        shutil.rmtree(cls.work, ignore_errors=True)
        for name in ("so_lith", "so_other", "so_big"):
            cls.runModule("r3.sbrt.manage", flags="f", remove=name)
        cls.runModule("g.remove", flags="f", type="raster_3d",
                      name="so_lith,so_prob,so_other,so_big")
        cls.runModule("g.remove", flags="f", type="raster", name="so_tex")
        cls.runModule("g.remove", flags="f", type="vector",
                      name="so_fence,so_path,so_path2,so_bh")
        cls.del_temp_region()

    def words(self, words):
        return [w.format(**self.files) for w in words]

    def fresh(self, words):
        """(width, height, RGB) of a fresh r3.sbrt.render given `words`
        (its PNG without annotations; a top view's PNG, enlarged by whole
        pixels, taken back to one pixel a cell)."""
        png = os.path.join(self.work, "fresh.png")
        flags = [w for w in words if w.startswith("-")]
        run = subprocess.run(["r3.sbrt.render"] + [w for w in words if w not in flags]
                             + ["png=" + png, "-n" + "".join(f[1:] for f in flags
                                                              if f != "-n"),
                                "--overwrite", "--quiet"],
                             capture_output=True, text=True, timeout=LIMIT)
        self.assertEqual(run.returncode, 0, "%s: %s" % (" ".join(words), run.stderr))
        width, height, rgb = read_png(png)
        if "view=top" in words:
            region = gs.region()
            k = width // int(region["cols"])
            rows = [rgb[r * width * 3:(r + 1) * width * 3] for r in range(0, height, k)]
            rgb = b"".join(row[c * 3:c * 3 + 3] for row in rows for c in range(0, width, k))
            width, height = width // k, height // k
        return width, height, rgb

    @staticmethod
    def difference(got, expected):
        """None where the images are equal, else what differs."""
        if got[:2] != expected[:2]:
            return "%d x %d against %d x %d" % (got[:2] + expected[:2])
        differing = sum(1 for i in range(0, len(got[2]), 3)
                        if got[2][i:i + 3] != expected[2][i:i + 3])
        return "%d of %d pixels differ" % (differing, got[0] * got[1]) if differing else None

    def test_the_cases_cover_every_option(self):
        """An option the module gains fails here until it has a case (or a
        reason the server cannot show it)."""
        options = module_options()
        self.assertEqual(set(CASES) | set(EXCLUDED), options)
        self.assertEqual(set(CASES) & set(EXCLUDED), set())

    def test_the_excluded_options_are_refused_by_the_server(self):
        """What EXCLUDED says: the server answers those with an error."""
        for key in EXCLUDED:
            word = {"frames": "frames=3", "tile": "tile=0,0,8,8"}.get(key, key + "=so_x")
            with self.assertRaisesRegex(AssertionError, "error ", msg=key):
                self.server.render(BASE + [word])

    def test_the_command_lines_rules_hold_in_the_server(self):
        """What G_parser refuses of option pairs on the command line (-b
        without boreholes=, color= with rules=, ...) the server refuses
        too: both read a request through the same parts."""
        for words in (["-b"], ["color=grey", "rules={rules}"], ["log_class=cls"],
                      ["boreholes=so_bh", "log_class=cls", "log_top=dtop"],
                      ["boreholes=so_bh", "-m"]):
            words = self.words(BASE + words)
            with self.assertRaisesRegex(AssertionError, "error ", msg=" ".join(words)):
                self.server.render(words)
            run = subprocess.run(["r3.sbrt.render"] + words + ["png=" + os.path.join(
                self.work, "refused.png"), "--overwrite"], capture_output=True,
                timeout=LIMIT)
            self.assertNotEqual(run.returncode, 0, " ".join(words))

    def test_every_option_changes_the_frame_as_a_fresh_process(self):
        """For each case: A, B, A again from one server; B as a fresh
        process draws it, A again as A. Every problem of every option is
        listed at the end (GRASS 8.2's gunittest drops subTest failures)."""
        problems, bases = [], {}
        for key in sorted(CASES):
            for context, change, expect in CASES[key]:
                a_words = self.words(with_context(BASE, context))
                b_words = self.words(merged(with_context(BASE, context), change))
                a = self.server.render(a_words)
                if tuple(a_words) not in bases:
                    wrong = self.difference(a, self.fresh(a_words))
                    if wrong:
                        problems.append("A %s: %s" % (" ".join(a_words), wrong))
                    bases[tuple(a_words)] = a
                wrong = self.difference(a, bases[tuple(a_words)])
                if wrong:
                    problems.append("A before %s: %s" % (change, wrong))
                b = self.server.render(b_words)
                wrong = self.difference(b, self.fresh(b_words))
                if wrong:  # a stale frame: the option is not in a cache key
                    problems.append("B %s: %s" % (change, wrong))
                if expect == "differs" and a == b:
                    problems.append("%s does not change the image" % change)
                elif expect == "same" and a != b:
                    problems.append("%s changes the image" % change)
                for image, words in ((a, a_words), (b, b_words)):
                    if len(set(image[2][i:i + 3] for i in range(0, len(image[2]), 3))) < 2:
                        problems.append("%s: one colour only" % " ".join(words))
                wrong = self.difference(self.server.render(a_words), a)
                if wrong:
                    problems.append("A again after %s: %s" % (change, wrong))
        self.assertEqual(problems, [])
        self.assertIsNone(self.server.process.poll())

if __name__ == "__main__":
    test()
