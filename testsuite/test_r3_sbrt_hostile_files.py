"""
MODULE:    testsuite/test_r3_sbrt_hostile_files.py (r3.sbrt addon)
PURPOSE:   SBRTs whose members are no regular files (issue 28, items 1
           and 2): a FIFO, a symbolic link or a directory as stacks or cats
           is refused at once, with the member's name, by r3.sbrt.render,
           r3.sbrt.convert -p and -r and the view server (which answers an
           error line and goes on serving); a FIFO as header or hist, which
           no reader opens, hangs nothing. Every run has a time limit, so
           a read that waits fails the test instead of hanging it.
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import select
import shutil
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

LIMIT = 5  # seconds: issue 28's bound on any hang

# each way of reading an SBRT, with {name} for the SBRT
READERS = {
    "render": ["r3.sbrt.render", "input={name}", "output=hostile_img",
               "size=40,30", "--overwrite", "--quiet"],
    "convert -p": ["r3.sbrt.convert", "-p", "sbrt={name}"],
    "convert -r": ["r3.sbrt.convert", "-r", "sbrt={name}",
                   "output=hostile_voxels", "--overwrite", "--quiet"],
}


class HostileFixture(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=20, s=0, e=10, w=0, b=0, t=6, res=1,
                      res3=1, tbres=1)
        cls.runModule("r3.mapcalc", overwrite=True,
                      expression="hostile_layers = if(depth() <= 2, 1, 2)")
        gs.run_command("r3.sbrt.convert", input="hostile_layers",
                       output="hostile_good", overwrite=True, quiet=True)
        env = gs.gisenv()
        cls.element = os.path.join(env["GISDBASE"], env["LOCATION_NAME"],
                                   env["MAPSET"], "sbrt")

    @classmethod
    def tearDownClass(cls):
        for name in os.listdir(cls.element):
            if name.startswith("hostile_") and name != "hostile_good":
                cls.remove_entry(os.path.join(cls.element, name))
        cls.runModule("g.remove", flags="f", type="raster_3d",
                      name="hostile_layers,hostile_voxels")
        cls.del_temp_region()

    @staticmethod
    def remove_entry(path):
        if os.path.islink(path) or not os.path.isdir(path):
            os.remove(path)
        else:
            shutil.rmtree(path)

    def hostile(self, name, member, kind):
        """SBRT `name`: a copy of hostile_good with `member` made a `kind`
        (fifo, symlink to the good one's file, directory)."""
        directory = os.path.join(self.element, name)
        if os.path.lexists(directory):
            self.remove_entry(directory)
        shutil.copytree(os.path.join(self.element, "hostile_good"), directory)
        path = os.path.join(directory, member)
        os.remove(path)
        if kind == "fifo":
            os.mkfifo(path)
        elif kind == "symlink":
            os.symlink(os.path.join(self.element, "hostile_good", member), path)
        else:
            os.mkdir(path)
        return path

    def run_reader(self, reader, name):
        """The finished reader process, its messages unwrapped; a reader
        still running after LIMIT seconds fails the test (and is killed)."""
        args = [word.format(name=name) for word in READERS[reader]]
        try:
            run = subprocess.run(args, capture_output=True, text=True,
                                 timeout=LIMIT)
        except subprocess.TimeoutExpired:
            self.fail(f"{reader} of {name} still ran after {LIMIT} s")
        run.messages = " ".join(run.stderr.split())
        return run


class TestHostileMembers(HostileFixture):
    # no subTest: GRASS 8.2's gunittest result drops subtests' failures

    def assertRefused(self, member, kind, what):
        """Each reader of an SBRT whose `member` is a `kind` fails in time
        with `what` said of the member."""
        name = f"hostile_{kind}_{member}"
        path = self.hostile(name, member, kind)
        for reader in READERS:
            run = self.run_reader(reader, name)
            self.assertNotEqual(run.returncode, 0, f"{reader}: {run.messages}")
            self.assertIn(f"{path}: {what}, not a regular file", run.messages,
                          reader)

    def test_good_sbrt_reads(self):
        """The control: each reader reads the SBRT the others are made of."""
        for reader in READERS:
            run = self.run_reader(reader, "hostile_good")
            self.assertEqual(run.returncode, 0, f"{reader}: {run.messages}")

    def test_fifo_stacks_is_refused_at_once(self):
        self.assertRefused("stacks", "fifo", "a FIFO (named pipe)")

    def test_fifo_cats_is_refused_at_once(self):
        self.assertRefused("cats", "fifo", "a FIFO (named pipe)")

    def test_symlinked_stacks_is_not_followed(self):
        self.assertRefused("stacks", "symlink", "a symbolic link")

    def test_symlinked_cats_is_not_followed(self):
        self.assertRefused("cats", "symlink", "a symbolic link")

    def test_directory_as_stacks_or_cats_is_refused(self):
        self.assertRefused("stacks", "directory", "a directory")
        self.assertRefused("cats", "directory", "a directory")

    def test_fifo_header_or_hist_hangs_nothing(self):
        # no reader opens them: the SBRT reads as the good one
        for member in ("header", "hist"):
            self.hostile(f"hostile_fifo_{member}", member, "fifo")
            for reader in READERS:
                run = self.run_reader(reader, f"hostile_fifo_{member}")
                self.assertEqual(run.returncode, 0,
                                 f"{member}, {reader}: {run.messages}")


class TestHostileMembersInTheViewServer(HostileFixture):
    """The view server answers `error ...` for such an SBRT and goes on."""

    def setUp(self):
        self.server = subprocess.Popen(
            ["r3.sbrt.render", "--serve"], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)

    def tearDown(self):
        self.server.kill()
        self.server.wait()

    def line(self):
        """The server's next line; fails the test after LIMIT seconds."""
        ready, _, _ = select.select([self.server.stdout], [], [], LIMIT)
        if not ready:
            self.fail(f"the view server did not answer within {LIMIT} s")
        return self.server.stdout.readline().decode(errors="replace")

    def ask(self, request):
        self.server.stdin.write(request.encode() + b"\n")
        self.server.stdin.flush()
        return self.line()

    def test_fifo_and_symlink_get_an_error_line(self):
        cases = [("stacks", "fifo", "a FIFO (named pipe)"),
                 ("cats", "fifo", "a FIFO (named pipe)"),
                 ("stacks", "symlink", "a symbolic link")]
        for member, kind, what in cases:
            name = f"hostile_serve_{kind}_{member}"
            path = self.hostile(name, member, kind)
            answer = self.ask(f"render input={name} size=40,30")
            self.assertTrue(answer.startswith("error "), answer)
            self.assertIn(f"{path}: {what}, not a regular file", answer)
        # still serving: a frame of the good SBRT, whole
        head = self.ask("render input=hostile_good size=40,30").split()
        self.assertEqual(head[:3], ["frame", "40", "30"])
        rgb = self.server.stdout.read(40 * 30 * 3)
        self.assertEqual(len(rgb), 40 * 30 * 3)


if __name__ == "__main__":
    test()
