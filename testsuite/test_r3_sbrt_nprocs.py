"""
MODULE:    testsuite/test_r3_sbrt_nprocs.py (r3.sbrt addon)
PURPOSE:   nprocs= has one meaning on every module that uses more than
           one core (convert, what, profile, surface, volume), GRASS 8.4's:
           0 all cores, a negative number all but that many; -1, 0 and a
           negative number beyond the cores are accepted and give what
           nprocs=1 gives, byte for byte (issue 50, smaller items)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import subprocess
import sys

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from geomodel_fixture import set_up_channel_model  # noqa: E402

# 1 is the reference; -1 and 0 as GRASS 8.4 reads them; -1000 leaves
# no core, which is one thread
NPROCS = ("1", "-1", "0", "-1000")
TIMEOUT = 120


def ascii_of(module, name):
    """A map as text (r3.out.ascii and r.out.ascii of GRASS 8.2 take
    output=- as a file name: a file of our own, read and removed)."""
    path = gs.tempfile()
    args = [module, f"input={name}", f"output={path}", "--overwrite", "--quiet"]
    run(*(args + (["-h"] if module == "r3.out.ascii" else ["precision=17"])))
    with open(path) as f:
        text = f.read()
    os.remove(path)
    return text


def run(*args):
    """The standard output of a module run, which must succeed."""
    done = subprocess.run(args, capture_output=True, text=True, timeout=TIMEOUT)
    if done.returncode != 0:
        raise AssertionError(f"{' '.join(args)} failed: {done.stderr}")
    return done.stdout


class TestNprocs(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        set_up_channel_model(cls, "np_classes", "np_prob")
        cls.mapset_dir = os.path.join(*[gs.gisenv()[k] for k in
                                        ("GISDBASE", "LOCATION_NAME", "MAPSET")])

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def same_for_every_nprocs(self, make):
        """make(nprocs) for each of NPROCS: all as nprocs=1 gives."""
        want = make("1")
        self.assertTrue(want)
        for nprocs in NPROCS[1:]:
            self.assertEqual(make(nprocs), want, f"nprocs={nprocs}")

    def test_convert_writes_the_same_sbrt(self):
        def convert(nprocs):
            name = "np_out_" + nprocs.replace("-", "m")
            run("r3.sbrt.convert", "input=np_classes", "properties=np_prob",
                f"output={name}", f"nprocs={nprocs}", "--overwrite", "--quiet")
            # every member but the history (its date and command line)
            directory = os.path.join(self.mapset_dir, "sbrt", name)
            members = sorted(m for m in os.listdir(directory) if m != "hist")
            return {m: open(os.path.join(directory, m), "rb").read() for m in members}

        self.same_for_every_nprocs(convert)

    def test_convert_expands_and_describes_the_same(self):
        def expand(nprocs):
            name = "np_vox_" + nprocs.replace("-", "m")
            run("r3.sbrt.convert", "-r", "sbrt=np_classes", f"output={name}",
                f"nprocs={nprocs}", "--overwrite", "--quiet")
            return (ascii_of("r3.out.ascii", name) +
                    run("r3.sbrt.convert", "-p", "sbrt=np_classes", "format=json",
                        f"nprocs={nprocs}"))

        self.same_for_every_nprocs(expand)

    def test_what_logs_the_same(self):
        self.same_for_every_nprocs(lambda nprocs: run(
            "r3.sbrt.what", "input=np_classes", "coordinates=150,150,850,450,1150,950",
            "format=json", "-v", f"nprocs={nprocs}"))

    def test_profile_the_same(self):
        self.same_for_every_nprocs(lambda nprocs: run(
            "r3.sbrt.profile", "input=np_classes", "coordinates=50,50,1150,950",
            "format=json", f"nprocs={nprocs}"))

    def test_surface_maps_the_same(self):
        def surface(nprocs):
            name = "np_thick_" + nprocs.replace("-", "m")
            run("r3.sbrt.surface", "input=np_classes", "classes=2", f"thickness={name}",
                f"nprocs={nprocs}", "--overwrite", "--quiet")
            return ascii_of("r.out.ascii", name)

        self.same_for_every_nprocs(surface)

    def test_volume_reports_the_same(self):
        self.same_for_every_nprocs(lambda nprocs: run(
            "r3.sbrt.volume", "input=np_classes", "format=json", f"nprocs={nprocs}"))


if __name__ == "__main__":
    test()
