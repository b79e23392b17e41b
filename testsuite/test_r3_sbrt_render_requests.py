"""
MODULE:    testsuite/test_r3_sbrt_render_requests.py (r3.sbrt addon)
PURPOSE:   Hostile render requests (issue 28, items 4, 5, 7 and 9): every
           request line of the list gets an answer from the view server
           (r3.sbrt.render --serve, spoken to over raw pipes, so a server
           that exits is seen, not restarted as the viewer's client does)
           and the same process serves a frame afterwards; on the command
           line, an image past the machine's memory, an over-wide png=
           pattern and an exaggeration too large for the model fail at once
           with clear messages. Every exchange has a time limit.
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import subprocess
import tempfile
import time

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from server_fixture import RawServer

LIMIT = 5  # seconds: issue 28's bound on any hang


class TestHostileRequests(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=20, s=0, e=30, w=0, b=0, t=8, res=1,
                      res3=1, tbres=1)
        cls.runModule("r3.mapcalc", overwrite=True,
                      expression="req_layers = if(depth() <= 3, 1, if(depth() <= 5, 2, 3))")
        gs.run_command("r3.sbrt.convert", input="req_layers", output="req_model",
                       overwrite=True, quiet=True)
        env = gs.gisenv()
        damaged = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"],
                               "sbrt", "req_damaged")
        gs.run_command("r3.sbrt.convert", input="req_layers", output="req_damaged",
                       overwrite=True, quiet=True)
        with open(os.path.join(damaged, "stacks"), "r+b") as stacks:
            stacks.truncate(40)

    @classmethod
    def tearDownClass(cls):
        gs.run_command("r3.sbrt.manage", remove="req_model,req_damaged", flags="f",
                       quiet=True)
        cls.runModule("g.remove", flags="f", type="raster_3d", name="req_layers")
        cls.del_temp_region()

    def setUp(self):
        self.server = RawServer(LIMIT)

    def tearDown(self):
        self.server.close()

    def assertStillServing(self):
        head = self.server.ask(b"render input=req_model size=32,24\n")
        self.assertTrue(head.startswith("frame 32 24 "), head)
        self.assertIsNone(self.server.process.poll())

    def test_every_request_of_the_list_is_answered(self):
        """Issue 28's list, item 4: each line gets an error naming what was
        wrong, and the server serves on."""
        expected = [
            (b"render input=req_model size=0,0", "size="),
            (b"render input=req_model size=100000,100000", "size="),
            (b"render input=req_model size=abc", "size"),
            (b"render input=req_model fov=500", "fov=500"),
            (b"render input=req_model zexag=nan", "zexag"),
            (b"render input=no_such_sbrt", "no_such_sbrt"),
            (b"render input=req_model hide=no_such_stratum", "no_such_stratum"),
            (b"render input=req_model opacity=3:7", "opacity=3:7"),
            (b"render input=req_model plane=1,2,3", "plane="),
            (b"render input=req_model section=1,1,1,1", "section="),
            (b"render input=req_model kernel=4", "kernel=4"),
            (b"render input=req_model fence=no_such_lines", "no_such_lines"),
            (b"render input=req_model boreholes=no_such_points", "no_such_points"),
            (b"render input=req_model texture=no_such_raster", "no_such_raster"),
            (b"render input=req_model rules=/no/such/rules", "rules="),
            (b"render input=req_damaged", "req_damaged"),
            (b"render input=req_model position=5,5,20 target=5,5,20", "same point"),
            (b"", "empty request"),
            (b"render input=req_model\0 size=10,10", "NUL"),
            (b"render input=req_model output=req_out", "output="),
            (b"render input=req_model png=/tmp/req.png", "png="),
            (b"render input=req_model size=10,10 size=20,20", "twice"),
            (b"render input=req_model zexag=1e300", "too large"),
            (b"render input=req_model frames=3", "command line"),
            (b"flip input=req_model", "unknown request"),
        ]
        # no subTest: GRASS 8.2's gunittest drops failures inside one
        for line, words in expected:
            head = self.server.ask(line + b"\n")
            self.assertTrue(head.startswith("error "), "%r: %s" % (line[:60], head))
            self.assertIn(words, head, "%r" % line[:60])
            self.assertIsNone(self.server.process.poll(), "the server exited at %r" % line[:60])
        self.assertStillServing()

    def test_a_huge_token_is_not_echoed_whole(self):
        """A 10 MB word is refused in a reply of readable length."""
        for line in (b"render input=req_model " + b"x" * 10_000_000,
                     b"render input=req_model hide=" + b"y" * 60_000,
                     b"render input=" + b"z" * 60_000):
            head = self.server.ask(line + b"\n")
            self.assertTrue(head.startswith("error "), head[:200])
            self.assertLess(len(head), 2100)
        self.assertStillServing()

    def test_frames_after_errors_are_right(self):
        """An error leaves the session as it was: the frame after it equals
        the frame before it."""
        first = self.server.ask(b"render input=req_model size=32,24 azimuth=100\n")
        self.server.ask(b"render input=req_model size=32,24 hide=no_such\n")
        second = self.server.ask(b"render input=req_model size=32,24 azimuth=100\n")
        self.assertEqual(first.split()[:3], second.split()[:3])
        self.assertEqual(first.split()[4:], second.split()[4:])

    def run_module(self, *args):
        """rc and stderr of r3.sbrt.render with `args`, within LIMIT."""
        start = time.monotonic()
        result = subprocess.run(["r3.sbrt.render", "input=req_model", "--overwrite"]
                                + list(args), capture_output=True, text=True,
                                timeout=LIMIT)
        # GRASS wraps its messages at 80 columns: one space between words
        return result.returncode, " ".join(result.stderr.split()), time.monotonic() - start

    def test_an_image_past_the_memory_is_refused_at_once(self):
        """Item 5: size=65536,65536 png= is checked against the memory
        before the first pixel, with the figure."""
        rc, err, seconds = self.run_module("size=65536,65536", "png=req_huge.png")
        self.assertNotEqual(rc, 0)
        self.assertIn("GB", err)
        self.assertIn("65536 x 65536", err)
        self.assertFalse(os.path.exists("req_huge.png"))
        self.assertLess(seconds, LIMIT)

    def test_a_wide_frame_pattern_is_refused(self):
        """Item 7: png=f_%99999999d.png is refused, no file written."""
        rc, err, _ = self.run_module("size=20,15", "frames=2", "png=req_f_%99999999d.png")
        self.assertNotEqual(rc, 0)
        self.assertIn("too wide", err)
        self.assertFalse([f for f in os.listdir(".") if f.startswith("req_f_")])

    def test_a_huge_exaggeration_says_so(self):
        """Item 9: zexag=1e300 names the exaggeration, not the camera."""
        rc, err, _ = self.run_module("size=20,15", "output=req_img", "zexag=1e300")
        self.assertNotEqual(rc, 0)
        self.assertIn("too large", err)
        self.assertNotIn("must differ", err)

    def test_frames_read_the_model_once(self):
        """Frames of one model read it once: the memory= a request without
        one gets (a share of the memory available, which the blocks held
        change) is found once a server, not per line, so it keeps the
        model's key."""
        handle, log = tempfile.mkstemp(suffix=".log")
        os.close(handle)
        verbose = os.environ.get("GRASS_VERBOSE")
        os.environ["GRASS_VERBOSE"] = "3"
        try:
            with open(log, "wb") as err:
                server = RawServer(LIMIT, stderr=err)
                try:
                    for azimuth in (10, 70, 130):
                        head = server.ask(("render input=req_model backend=cpu "
                                           "size=32,24 azimuth=%d\n" % azimuth).encode())
                        self.assertTrue(head.startswith("frame 32 24 "), head)
                finally:
                    server.close()
        finally:
            if verbose is None:
                del os.environ["GRASS_VERBOSE"]
            else:
                os.environ["GRASS_VERBOSE"] = verbose
        with open(log, encoding="utf-8", errors="replace") as f:
            text = f.read()
        os.remove(log)
        self.assertEqual(text.count("SBRT <req_model> paged"), 1, text)


if __name__ == "__main__":
    test()
