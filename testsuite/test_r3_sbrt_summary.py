"""
MODULE:    testsuite/test_r3_sbrt_summary.py (r3.sbrt addon)
PURPOSE:   Format 2.1 block summaries: r3.sbrt.convert -g, -p and
           format=json, and the view server's classes reply (g.gui.sbrt's
           first question), describe a model from them exactly as from the
           decoded model of the same SBRT as a 2.0 file, without decoding
           a block; a damaged summary is a clear error
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import json
import os
import shutil
import struct
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test

from stacks_fixture import as_format_20, copy_sbrt, sbrt_dir, stacks_path, summary_section

# offsets in the format 2 header (lib/sbrt/format/format_v2.hpp)
AT_TABLE = 124
# the keys whose values come from the file, not the model
FILE_KEYS = ("name", "format", "file_bytes", "file_bytes_per_interval", "file_compression")


def flip_byte(name, at):
    with open(stacks_path(name), "r+b") as f:
        f.seek(at)
        value = f.read(1)[0]
        f.seek(at)
        f.write(bytes([value ^ 0x10]))


def classes(*words):
    """The view server's reply to `classes` with these words."""
    run = subprocess.run(["r3.sbrt.render", "--serve"], capture_output=True, text=True,
                         input="classes " + " ".join(words) + "\nquit\n", timeout=60)
    return run.stdout


def convert(*args):
    return subprocess.run(
        ["r3.sbrt.convert", *args], capture_output=True, text=True, timeout=60
    )


class TestDescribeFromSummaries(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        # 70 x 90 cells: blocks of 64 cells a side, 2 x 2 of them; strata,
        # a cave, air above a slope and an empty corner (an empty block part)
        cls.runModule("g.region", n=70, s=0, e=90, w=0, b=0, t=30, res=1, res3=1, tbres=1)
        cls.runModule(
            "r3.mapcalc",
            expression="strata = if(row() < 8 && col() < 10, null(), "
            "if(depth() > 20 + col() / 10, null(), if(depth() == 6 && row() > 30, "
            "null(), 1 + (depth() + row() / 17) / 5)))",
        )
        cls.runModule("r3.sbrt.convert", input="strata", output="sum21")
        copy_sbrt("sum21", "sum20")
        as_format_20("sum20")

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()
        for name in ("sum21", "sum20", "sum_bad", "sum_block"):
            shutil.rmtree(sbrt_dir(name), ignore_errors=True)

    def shell(self, name):
        run = convert("-g", "sbrt=" + name)
        self.assertEqual(run.returncode, 0, run.stderr)
        return dict(line.split("=", 1) for line in run.stdout.splitlines())

    def test_shell_figures_equal_those_of_the_decoded_model(self):
        new, old = self.shell("sum21"), self.shell("sum20")
        self.assertEqual(new["format"], "2.1")
        self.assertEqual(old["format"], "2.0")
        self.assertEqual(int(new["file_bytes"]), os.path.getsize(stacks_path("sum21")))
        self.assertGreater(int(new["file_bytes"]), int(old["file_bytes"]))
        self.assertEqual(list(new), list(old))
        for key in new:
            if key not in FILE_KEYS:
                self.assertEqual(new[key], old[key], key)
        self.assertGreater(int(new["solid_intervals"]), 0)

    def test_plain_and_json_reports_are_the_same(self):
        plain = [convert("-p", "sbrt=" + n).stdout.splitlines() for n in ("sum21", "sum20")]
        # the model's lines (after the name, before the file's): the same
        on_disk = [lines.index(next(x for x in lines if x.startswith("On disk"))) for lines in plain]
        self.assertEqual(on_disk[0], on_disk[1])
        self.assertEqual(plain[0][1 : on_disk[0]], plain[1][1 : on_disk[1]])
        self.assertGreater(on_disk[0], 10)
        self.assertEqual(plain[0][on_disk[0]], "On disk (format 2.1):")
        self.assertEqual(plain[1][on_disk[1]], "On disk (format 2.0):")
        new, old = (
            json.loads(convert("-p", "format=json", "sbrt=" + n).stdout)
            for n in ("sum21", "sum20")
        )
        for key in FILE_KEYS:
            new.pop(key)
            old.pop(key)
        self.assertEqual(new, old)

    def test_describing_decodes_no_block(self):
        """A damaged block: -g describes the model all the same (its blocks
        are not read), -r, which decodes them, refuses it."""
        copy_sbrt("sum21", "sum_block")
        with open(stacks_path("sum_block"), "rb") as f:
            data = f.read()
        table = struct.unpack_from("<Q", data, AT_TABLE)[0]
        first_block = struct.unpack_from("<Q", data, table)[0]
        flip_byte("sum_block", first_block + 5)
        new, whole = self.shell("sum_block"), self.shell("sum21")
        for key in new:
            if key != "name":
                self.assertEqual(new[key], whole[key], key)
        run = convert("-r", "sbrt=sum_block", "output=sum_block_voxels")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("checksum", run.stderr)

    def test_view_server_classes_equal_those_of_the_decoded_model(self):
        """The extent, fitted exaggeration, voxel flag and classes (as
        color= recolours them) of the summaries equal the decoded model's,
        and a damaged block, not read, changes nothing."""
        copy_sbrt("sum21", "sum_block")
        with open(stacks_path("sum_block"), "rb") as f:
            data = f.read()
        first_block = struct.unpack_from("<Q", data, struct.unpack_from("<Q", data, AT_TABLE)[0])[0]
        flip_byte("sum_block", first_block + 5)
        for extra in ([], ["color=viridis"], ["zexag=3"]):
            old = classes("input=sum20", *extra)
            self.assertTrue(old.startswith("model 70 0 90 0 0 30 "), old)
            self.assertIn("\nclasses ", old)
            self.assertIn("\nchannels 0\n", old)
            for name in ("sum21", "sum_block"):
                self.assertEqual(classes("input=" + name, *extra), old, (name, extra))
        self.assertNotEqual(classes("input=sum20", "color=viridis"), classes("input=sum20"))
        # the decode of the damaged block, where a frame needs it
        frame = subprocess.run(["r3.sbrt.render", "--serve"], capture_output=True, text=True,
                               input="render input=sum_block size=40,30\nquit\n", timeout=60)
        self.assertTrue(frame.stdout.startswith("error "), frame.stdout[:200])
        self.assertIn("checksum", frame.stdout)

    def test_damaged_summary_is_a_clear_error(self):
        copy_sbrt("sum21", "sum_bad")
        with open(stacks_path("sum_bad"), "rb") as f:
            begin, _ = summary_section(f.read())
        flip_byte("sum_bad", begin + 2)
        for flags in ("-g", "-p"):
            run = convert(flags, "sbrt=sum_bad")
            self.assertNotEqual(run.returncode, 0)
            self.assertEqual(run.stdout, "")
            message = " ".join(run.stderr.split())  # GRASS wraps its lines
            self.assertIn("SBRT <sum_bad> is damaged", message)
            self.assertIn("block summaries: checksum mismatch", message)
            self.assertIn("Import its source again with r3.sbrt.convert", message)
            self.assertNotIn("Traceback", message)
        reply = classes("input=sum_bad")
        self.assertTrue(reply.startswith("error "), reply)
        self.assertIn("block summaries: checksum mismatch", reply)


if __name__ == "__main__":
    test()
