"""
MODULE:    testsuite/test_r3_sbrt_support_concurrency.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.support on hostile input and at the same time as
           itself (issue 48): 20 changes of one SBRT at once, beside
           readers, all kept (item 3); rules naming ids the model lacks
           counted and warned of (item 12); /dev/zero, a FIFO, a
           directory or an oversized file as rules= or labels= refused at
           once (item 6); labels made valid UTF-8 where they enter (item 9).
           Every run has a time limit.
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import fcntl
import os
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

LIMIT = 5  # seconds: the bound on refusing a hostile file
CHANGES = 20
CLASSES = 20  # class k is depth k


def run(args, timeout=60, **kwargs):
    """A module run: its return code and messages, one space between words
    (GRASS wraps them at 80 columns)."""
    done = subprocess.run(args, capture_output=True, timeout=timeout, **kwargs)
    return done.returncode, " ".join(done.stderr.decode("utf-8", "replace").split())


def legend(name):
    """{id: (r:g:b text, label)} of r3.sbrt.convert -p's material table."""
    out = gs.read_command("r3.sbrt.convert", flags="p", sbrt=name)
    rows, inside = {}, False
    for line in out.splitlines():
        if line.startswith("Materials:"):
            inside = True
            continue
        if inside and not line.startswith("  "):
            break
        if inside:
            head, _, rest = line.strip().partition("  ")
            rest = rest.strip()
            rows[int(head)] = (rest[:11].replace(" ", ""), rest[11:].strip())
    return rows


class TestSupportConcurrency(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule("g.region", n=40, s=0, e=40, w=0, b=0, t=CLASSES, res=10,
                      res3=10, tbres=1)
        cls.runModule("r3.mapcalc", expression="conc_v = depth()", overwrite=True)
        cls.tmp = tempfile.mkdtemp(prefix="sbrt_support_conc_")
        env = gs.gisenv()
        cls.element = os.path.join(env["GISDBASE"], env["LOCATION_NAME"],
                                   env["MAPSET"], "sbrt")

    @classmethod
    def tearDownClass(cls):
        cls.runModule("g.remove", flags="f", type="raster_3d", name="conc_v")
        cls.runModule("g.remove", flags="f", type="raster", name="conc_2d")
        shutil.rmtree(cls.tmp, ignore_errors=True)
        cls.del_temp_region()

    def fresh(self, name):
        gs.run_command("r3.sbrt.convert", input="conc_v", output=name,
                       overwrite=True, quiet=True)
        return name

    def write(self, name, data):
        path = os.path.join(self.tmp, name)
        with open(path, "wb") as f:
            f.write(data.encode() if isinstance(data, str) else data)
        return path

    def member(self, name, member):
        with open(os.path.join(self.element, name, member), "rb") as f:
            return f.read()

    def test_twenty_changes_at_once_are_all_kept(self):
        """Item 3: each run changes its own class (even k a label, odd k a
        colour); before the lock, half the changes were lost with rc 0."""
        name = self.fresh("conc")
        changes = []
        for k in range(1, CHANGES + 1):
            if k % 2 == 0:
                option = "labels=" + self.write(f"labels_{k}", f"{k}:label_{k}\n")
            else:
                option = "rules=" + self.write(f"rules_{k}", f"{k} {k}:{2 * k}:{3 * k}\n")
            changes.append(["r3.sbrt.support", f"sbrt={name}", option, "--quiet"])
        readers = [["r3.sbrt.convert", "-p", f"sbrt={name}"]] * 3
        runs = [subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
                for args in changes + readers]
        try:
            results = [(p.wait(timeout=120), p.stderr.read().decode()) for p in runs]
        finally:
            for p in runs:
                if p.poll() is None:
                    p.kill()
                    p.wait()
                p.stderr.close()
        for (code, message), args in zip(results, changes + readers):
            self.assertEqual(code, 0, f"{args}: {message}")
        rows = legend(name)
        for k in range(1, CHANGES + 1):
            if k % 2 == 0:
                self.assertEqual(rows[k][1], f"label_{k}", f"class {k}")
            else:
                self.assertEqual(rows[k][0], f"{k}:{2 * k}:{3 * k}", f"class {k}")
        hist = self.member(name, "hist").decode()
        changed = [line for line in hist.splitlines()
                   if line.startswith("legend changed:")]
        self.assertEqual(len(changed), CHANGES, hist)
        # the lock lies beside the SBRT, not in it
        self.assertTrue(os.path.isfile(os.path.join(self.element, ".conc.lock")))
        self.assertNotIn(".conc.lock", os.listdir(os.path.join(self.element, name)))

    def test_label_rules_naming_no_class_are_counted(self):
        """Item 12: 100,000 lines for an id the model lacks, and one that
        names a class: rc 0, the counts said, a warning for the rest."""
        name = self.fresh("conc_count")
        path = self.write("many_labels", "999:nothing\n" * 100000 + "3:clay\n")
        code, message = run(["r3.sbrt.support", f"sbrt={name}", f"labels={path}"])
        self.assertEqual(code, 0, message)
        self.assertIn(f"labels={path}: 1 of 100001 lines applied, changing 1 of the "
                      f"{CLASSES} classes",
                      message)
        self.assertIn(f"labels={path}: 100000 of 100001 lines named no class of "
                      f"SBRT <{name}> and changed nothing (the first names 999; its "
                      f"{CLASSES} classes have ids 1 to {CLASSES})", message)
        self.assertEqual(legend(name)[3][1], "clay")
        # a range reaching a class is applied, one between classes is not
        path = self.write("ranges", "2:4:low\n30:40:none\n")
        code, message = run(["r3.sbrt.support", f"sbrt={name}", f"labels={path}"])
        self.assertEqual(code, 0, message)
        self.assertIn("1 of 2 lines applied, changing 3 of the 20 classes", message)
        self.assertIn("1 of 2 lines named no class", message)
        self.assertIn("the first names 30:40", message)

    def test_colour_rules_naming_no_class_are_counted(self):
        name = self.fresh("conc_colours")
        before = legend(name)
        path = self.write("many_rules", "999 red\n" * 100000)
        code, message = run(["r3.sbrt.support", f"sbrt={name}", f"rules={path}"])
        self.assertEqual(code, 0, message)
        self.assertIn(f"rules={path}: 0 of 100000 lines applied, changing 0 "
                      "of the 20 classes",
                      message)
        self.assertIn("100000 of 100000 lines named no class of SBRT <conc_colours>",
                      message)
        self.assertEqual(legend(name), before)
        # between two rules, classes take the colour between theirs: a rule
        # is applied when a class lies between it and its neighbour
        path = self.write("between", "3 0:0:255\n3.5 0:255:0\n4 255:0:0\n"
                                     "nv white\n100 0:0:0\n")
        code, message = run(["r3.sbrt.support", f"sbrt={name}", f"rules={path}"])
        self.assertEqual(code, 0, message)
        self.assertIn("3 of 4 lines applied", message)
        self.assertIn("1 of 4 lines named no class", message)
        self.assertIn("the first names 3.5", message)

    def test_hostile_files_are_refused_at_once(self):
        """Item 6: nothing waits on a FIFO or reads /dev/zero to its end."""
        name = self.fresh("conc_hostile")
        fifo = os.path.join(self.tmp, "fifo")
        os.mkfifo(fifo)
        directory = os.path.join(self.tmp, "a_directory")
        os.mkdir(directory)
        big = os.path.join(self.tmp, "big")
        with open(big, "wb") as f:
            f.truncate(17 << 20)  # sparse: 17 MiB that take no room
        cases = [("/dev/zero", "a character device"), (fifo, "a FIFO (named pipe)"),
                 (directory, "a directory"), (big, f"{17 << 20} bytes, more than")]
        for key in ("rules", "labels"):
            for path, what in cases:
                code, message = run(["r3.sbrt.support", f"sbrt={name}", f"{key}={path}"],
                                    timeout=LIMIT)
                self.assertNotEqual(code, 0, f"{key}={path}")
                self.assertIn(f"{key}={path}: {what}", message)
        # GRASS's rule parser copies the value and the colour into 80 bytes
        # unbounded: a longer word aborted the module (buffer overflow).
        # The project's reader takes a long number as a number (a rule that
        # names no class) and refuses a long colour by its line's number,
        # never quoting it
        path = self.write("long_value", "3" * 200 + " red\n")
        code, message = run(["r3.sbrt.support", f"sbrt={name}", f"rules={path}"],
                            timeout=LIMIT)
        self.assertEqual(code, 0, message)
        self.assertIn("1 of 1 lines named no class", message)
        path = self.write("long_colour", "3 " + "b" * 300 + "\n")
        code, message = run(["r3.sbrt.support", f"sbrt={name}", f"rules={path}"],
                            timeout=LIMIT)
        self.assertEqual(code, 1, message)
        self.assertIn(f"rules={path}: line 1: the colour is not", message)
        self.assertNotIn("bbbb", message)
        self.assertEqual(self.member(name, "hist").decode().count("legend changed"), 1)

    def test_standard_input_still_read(self):
        name = self.fresh("conc_stdin")
        code, message = run(["r3.sbrt.support", f"sbrt={name}", "labels=-"],
                            input=b"5:from standard input\n")
        self.assertEqual(code, 0, message)
        self.assertIn("labels=-: 1 of 1 lines applied", message)
        code, message = run(["r3.sbrt.support", f"sbrt={name}", "rules=-"],
                            input=b"6 1:2:3\n")
        self.assertEqual(code, 0, message)
        rows = legend(name)
        self.assertEqual(rows[5][1], "from standard input")
        self.assertEqual(rows[6][0], "1:2:3")

    def test_labels_are_made_valid_utf8(self):
        """Item 9: bytes that are no UTF-8, from labels= or another map's
        categories, are stored as U+FFFD."""
        name = self.fresh("conc_utf8")
        path = self.write("bad_utf8", b"4:cl\xffay\n")
        code, message = run(["r3.sbrt.support", f"sbrt={name}", f"labels={path}"])
        self.assertEqual(code, 0, message)
        self.runModule("r.mapcalc", expression="conc_2d = row()", overwrite=True)
        self.runModule("r.category", map="conc_2d", separator=":",
                       rules=self.write("cats_2d", b"7:gr\xfeavel\n"))
        code, message = run(["r3.sbrt.support", f"sbrt={name}", "raster=conc_2d"])
        self.assertEqual(code, 0, message)
        cats = self.member(name, "cats").decode("utf-8")  # raises if not UTF-8
        self.assertIn("4:cl\ufffday", cats.splitlines())
        self.assertIn("7:gr\ufffdavel", cats.splitlines())

    def test_every_writer_waits_for_the_lock(self):
        """convert's output, manage's copy, rename and remove take the same
        writers' lock as support: none of them changes the SBRT while
        another writer holds it; each goes on once it is let go."""
        writers = {
            "convert --overwrite": ["r3.sbrt.convert", "input=conc_v", "output={name}",
                                    "--overwrite"],
            "manage copy": ["r3.sbrt.manage", "copy=conc_src,{name}", "--overwrite"],
            "manage rename": ["r3.sbrt.manage", "rename={name},{name}_moved", "--overwrite"],
            "manage remove": ["r3.sbrt.manage", "remove={name}", "-f"],
        }
        self.fresh("conc_src")
        for label, words in writers.items():
            name = self.fresh("conc_locked")
            stacks = os.stat(os.path.join(self.element, name, "stacks")).st_ino
            lock_path = os.path.join(self.element, f".{name}.lock")
            with open(lock_path, "a+") as lock:
                fcntl.flock(lock, fcntl.LOCK_EX)
                writer = subprocess.Popen([w.format(name=name) for w in words],
                                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
                with self.assertRaises(subprocess.TimeoutExpired, msg=label):
                    writer.wait(timeout=2)
                # held: the SBRT is as it was, a reader is not kept waiting
                self.assertEqual(os.stat(os.path.join(self.element, name, "stacks")).st_ino,
                                 stacks, label)
                code, message = run(["r3.sbrt.convert", "-p", f"sbrt={name}"], timeout=LIMIT)
                self.assertEqual(code, 0, message)
                fcntl.flock(lock, fcntl.LOCK_UN)
            self.assertEqual(writer.wait(timeout=60), 0, (label, writer.stderr.read()))
            writer.stderr.close()
            gs.run_command("r3.sbrt.manage", remove=f"{name}_moved", flags="f", quiet=True,
                           errors="ignore")


if __name__ == "__main__":
    test()
