"""
MODULE:    testsuite/test_r3_sbrt_rules_files.py (r3.sbrt addon)
PURPOSE:   Hostile colour rules files, legends and PNG paths (issue 48,
           items 5, 6 and 13): a bad rules= or property_color= file fails
           on the command line and is answered with an error by the view
           server, which serves on; the message names the line number and
           never quotes the line (the file may be /etc/passwd); /dev/zero
           and a FIFO are refused at once; an SBRT's labels, unit and
           title come back from the server as printable lines of intact
           fields; ten renders to one png= at once all succeed and leave
           one valid PNG and no temporary file. Every run has a time limit.
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import subprocess
import tempfile
import time

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from server_fixture import RawServer
from test_r3_sbrt_render_requests import LIMIT

MODEL = "rules_model"
CHANNEL_MODEL = "rules_channel_model"
# (file content, the line number the error names, words it must not show)
BAD_FILES = [
    ("5 300:0:0\n", 1, "300:0:0"),
    ("# classes\n\n1 red\n50 nonsense_colour\n", 4, "nonsense_colour"),
    ("0% blue\n100% red\n7 nan:0:0 x\n", 3, "nan:0:0"),
    ("0% blue\n150% red\n", 2, "150%"),
    ("0 0:0:0\n1e999 red\n", 2, "1e999"),
]


class ServerWithErrors(RawServer):
    """RawServer whose standard error is kept in a file, to be read."""

    def __init__(self, stderr_path):
        self.stderr_file = open(stderr_path, "wb")
        super().__init__(LIMIT, stderr=self.stderr_file)

    def close(self):
        super().close()
        self.stderr_file.close()

    def legend(self, sbrt):
        """The raw lines of the classes reply of SBRT `sbrt`, as bytes."""
        self.process.stdin.write(b"classes input=%s\n" % sbrt.encode())
        self.process.stdin.flush()
        deadline = time.monotonic() + LIMIT
        self._fill(lambda buffer: buffer.count(b"\n") >= 2, deadline)
        lines = []
        for _ in range(2):  # model, classes N
            line, self.buffer = self.buffer.split(b"\n", 1)
            lines.append(line)
        for _ in range(int(lines[-1].split()[1]) + 1):  # classes, channels N
            self._fill(lambda buffer: b"\n" in buffer, deadline)
            line, self.buffer = self.buffer.split(b"\n", 1)
            lines.append(line)
        for _ in range(int(lines[-1].split()[1])):
            self._fill(lambda buffer: b"\n" in buffer, deadline)
            line, self.buffer = self.buffer.split(b"\n", 1)
            lines.append(line)
        return lines


class TestRulesFiles(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=20, s=0, e=30, w=0, b=0, t=8, res=1,
                      res3=1, tbres=1)
        cls.runModule("r3.mapcalc", overwrite=True,
                      expression="rules_layers = if(depth() <= 3, 1, "
                                 "if(depth() <= 5, 2, 3))")
        cls.runModule("r3.mapcalc", overwrite=True,
                      expression="rules_p = float((row() * 13 + col() * 7) % 101)")
        for output, properties in ((MODEL, None), (CHANNEL_MODEL, "rules_p")):
            args = ["r3.sbrt.convert", "input=rules_layers", "output=" + output,
                    "--overwrite", "--quiet"]
            if properties:
                args.append("properties=" + properties)
            subprocess.run(args, check=True, timeout=60)
        cls.dir = tempfile.mkdtemp(prefix="sbrt_rules_")
        cls.bad = []
        for i, (text, line, hidden) in enumerate(BAD_FILES):
            path = os.path.join(cls.dir, "bad_%d.rules" % i)
            with open(path, "w") as f:
                f.write(text)
            cls.bad.append((path, line, hidden))
        # /etc/passwd: a readable file that is not a rules file
        cls.bad.append(("/etc/passwd", 1, "root:"))
        cls.good = os.path.join(cls.dir, "good.rules")
        with open(cls.good, "w") as f:
            f.write("# a ramp\n0% blue\n50% #00ff00\n100% 255 0 0\nnv white\n")
        cls.fifo = os.path.join(cls.dir, "fifo.rules")
        os.mkfifo(cls.fifo)

    @classmethod
    def tearDownClass(cls):
        subprocess.run(["r3.sbrt.manage", "remove=%s,%s" % (MODEL, CHANNEL_MODEL),
                        "-f", "--quiet"], timeout=60)
        cls.runModule("g.remove", flags="f", type="raster_3d",
                      name="rules_layers,rules_p")
        shutil.rmtree(cls.dir, ignore_errors=True)
        cls.del_temp_region()

    def render(self, *args, model=MODEL):
        """rc, messages (one space between words) and seconds of a render."""
        start = time.monotonic()
        result = subprocess.run(
            ["r3.sbrt.render", "input=" + model, "size=20,15", "--overwrite"]
            + list(args), capture_output=True, text=True, timeout=LIMIT,
            stdin=subprocess.DEVNULL)
        return (result.returncode, " ".join(result.stderr.split()),
                time.monotonic() - start)

    def property_args(self, path):
        return ["property=rules_p", "property_color=" + path]

    def test_bad_files_on_the_command_line(self):
        """Items 5: each bad file fails, naming its line, not quoting it."""
        png = os.path.join(self.dir, "cli.png")
        for path, line, hidden in self.bad:
            for args, model in ((["rules=" + path], MODEL),
                                (self.property_args(path), CHANNEL_MODEL)):
                rc, err, _ = self.render("png=" + png, *args, model=model)
                self.assertNotEqual(rc, 0, "%s: %s" % (args, err))
                self.assertIn("line %d:" % line, err, args)
                self.assertNotIn(hidden, err, args)
        # a good file still colours
        rc, err, _ = self.render("png=" + png, "rules=" + self.good)
        self.assertEqual(rc, 0, err)
        rc, err, _ = self.render("png=" + png, *self.property_args(self.good),
                                 model=CHANNEL_MODEL)
        self.assertEqual(rc, 0, err)

    def test_rules_from_standard_input(self):
        """rules=- still reads standard input."""
        with open(self.good, "rb") as rules:
            result = subprocess.run(
                ["r3.sbrt.render", "input=" + MODEL, "size=20,15", "rules=-",
                 "png=" + os.path.join(self.dir, "stdin.png"), "--overwrite"],
                stdin=rules, capture_output=True, text=True, timeout=LIMIT)
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_devices_and_fifos_on_the_command_line(self):
        """Item 6: /dev/zero and a FIFO fail within the limit."""
        png = os.path.join(self.dir, "dev.png")
        for path in ("/dev/zero", self.fifo):
            for args, model in ((["rules=" + path], MODEL),
                                (self.property_args(path), CHANNEL_MODEL)):
                rc, err, seconds = self.render("png=" + png, *args, model=model)
                self.assertNotEqual(rc, 0, args)
                self.assertIn("not a regular file", err, args)
                self.assertLess(seconds, LIMIT)

    def test_the_server_answers_and_serves_on(self):
        """Items 5 and 6: the view server answers an error for each bad,
        device or FIFO file, never quotes a line, and serves the next
        good request."""
        log = os.path.join(self.dir, "server.err")
        server = ServerWithErrors(log)
        try:
            files = self.bad + [("/dev/zero", None, None), (self.fifo, None, None)]
            for path, line, hidden in files:
                for request in (
                        "render input=%s size=16,12 rules=%s" % (MODEL, path),
                        "render input=%s size=16,12 property=rules_p "
                        "property_color=%s" % (CHANNEL_MODEL, path)):
                    head = server.ask(request.encode() + b"\n")
                    self.assertTrue(head.startswith("error "), "%s: %s" % (request, head))
                    if line is None:
                        self.assertIn("not a regular file", head)
                    else:
                        self.assertIn("line %d:" % line, head)
                        self.assertNotIn(hidden, head)
                    self.assertIsNone(server.process.poll(), request)
                    good = server.ask(b"render input=%s size=16,12 rules=%s\n"
                                      % (MODEL.encode(), self.good.encode()))
                    self.assertTrue(good.startswith("frame 16 12 "), good)
        finally:
            server.close()
        with open(log, "rb") as f:
            messages = f.read().decode(errors="replace")
        self.assertNotIn("root:", messages)
        self.assertNotIn("nonsense_colour", messages)

    def test_hostile_legend_texts(self):
        """The classes reply quotes an SBRT's labels, unit and title (maybe
        another user's) as printable lines; a channel's record keeps its
        three fields name|unit|long name whatever '|' the texts hold."""
        self.runModule("r3.support", map="rules_p", unit="m|s", title="P|sand")
        subprocess.run(["r3.sbrt.convert", "input=rules_layers", "properties=rules_p",
                        "output=rules_legend", "--overwrite", "--quiet"], check=True,
                       timeout=60)
        try:
            env = gs.gisenv()
            cats = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"],
                                "sbrt", "rules_legend", "cats")
            with open(cats, "wb") as f:
                f.write(b"1:Clay\rX\x1b[31m|y\n2:two\n3:three\n")
            server = ServerWithErrors(os.path.join(self.dir, "legend.err"))
            try:
                lines = server.legend("rules_legend")
            finally:
                server.close()
        finally:
            subprocess.run(["r3.sbrt.manage", "remove=rules_legend", "-f", "--quiet"],
                           timeout=60)
        for line in lines:
            self.assertNotIn(b"\r", line)
            self.assertNotIn(b"\x1b", line)
            line.decode()  # valid UTF-8
        labels = [line.split(b" ", 4)[4] for line in lines if line.startswith(b"1 ")]
        self.assertEqual(len(labels), 1, lines)
        self.assertTrue(labels[0].startswith(b"Clay"), labels)
        channel = lines[-1].decode().split(" ", 2)[2]
        self.assertEqual(len(channel.split("|")), 3, channel)
        name, unit, title = channel.split("|")
        self.assertEqual(name, "rules_p")
        self.assertIn("m", unit)
        self.assertIn("sand", title)

    def test_parallel_renders_to_one_png(self):
        """Item 13: ten renders to one png= at once all succeed; the PNG
        is whole and no temporary file is left."""
        from PIL import Image

        folder = tempfile.mkdtemp(prefix="png_", dir=self.dir)
        png = os.path.join(folder, "same.png")
        runs = [subprocess.Popen(
            ["r3.sbrt.render", "input=" + MODEL, "size=40,30", "png=" + png,
             "--overwrite", "--quiet"], stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE, stdin=subprocess.DEVNULL) for _ in range(10)]
        failures = []
        for run in runs:
            _, err = run.communicate(timeout=60)
            if run.returncode != 0:
                failures.append(err.decode(errors="replace"))
        self.assertEqual(failures, [])
        with Image.open(png) as image:
            image.load()
            # the view and its legend (annotations widen the image)
            self.assertGreaterEqual(image.size[0], 40)
            self.assertGreaterEqual(image.size[1], 30)
        self.assertEqual(os.listdir(folder), ["same.png"])
        os.remove(png)
        os.rmdir(folder)


if __name__ == "__main__":
    test()
