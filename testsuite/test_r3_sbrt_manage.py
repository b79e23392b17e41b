"""
MODULE:    testsuite/test_r3_sbrt_manage.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.manage against the rules of g.list, g.copy, g.rename and
           g.remove (GRASS 8.2): exact listings, byte-identical copies from
           the search path, overwrite, missing and illegal names, and that
           no other mapset is ever written
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.

The module runs in two mapsets of its own, WORK (current) and OTHER, with
the search path WORK,OTHER, so that every listing is known exactly. Before
each test WORK holds geo (the "layers" model) and cave ("caves"), OTHER
holds geo ("caves") and deep ("layers"): the two geo are different models.
"""
import filecmp
import os
import shutil
import subprocess

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

WORK = "sbrt_manage_work"
OTHER = "sbrt_manage_other"
SBRT_FILES = ("header", "stacks", "cats")


class ManageFixture(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        cls.runModule(
            "g.region", n=20, s=0, e=10, w=0, b=0, t=6, res=1, res3=1, tbres=1
        )
        cls.runModule(
            "r3.mapcalc",
            overwrite=True,
            expression="layers = if(depth() <= 2, 1, "
            "if(depth() == 3, null(), 2))",
        )
        cls.runModule(
            "r3.mapcalc",
            overwrite=True,
            expression="caves = if(depth() == 4 && col() > 5, null(), depth())",
        )
        for model in ("layers", "caves"):
            gs.run_command(
                "r3.sbrt.convert",
                input=model,
                output=f"manage_{model}",
                overwrite=True,
                quiet=True,
            )
        env = gs.gisenv()
        cls.location = os.path.join(env["GISDBASE"], env["LOCATION_NAME"])
        cls.models = os.path.join(cls.location, env["MAPSET"], "sbrt")
        for mapset in (WORK, OTHER):
            os.makedirs(os.path.join(cls.location, mapset), exist_ok=True)
            shutil.copy(
                os.path.join(cls.location, "PERMANENT", "DEFAULT_WIND"),
                os.path.join(cls.location, mapset, "WIND"),
            )
        cls.gisrc, cls.env = gs.create_environment(
            env["GISDBASE"], env["LOCATION_NAME"], WORK
        )
        cls.env.pop("GRASS_OVERWRITE", None)
        gs.run_command(
            "g.mapsets", mapset=f"{WORK},{OTHER}", operation="set", env=cls.env
        )

    @classmethod
    def tearDownClass(cls):
        for mapset in (WORK, OTHER):
            shutil.rmtree(os.path.join(cls.location, mapset), ignore_errors=True)
        os.remove(cls.gisrc)
        cls.del_temp_region()

    def setUp(self):
        self.fill(WORK, geo="manage_layers", cave="manage_caves")
        self.fill(OTHER, geo="manage_caves", deep="manage_layers")

    def fill(self, mapset, **sbrts):
        element = os.path.join(self.location, mapset, "sbrt")
        shutil.rmtree(element, ignore_errors=True)
        os.makedirs(element)
        for name, model in sbrts.items():
            shutil.copytree(
                os.path.join(self.models, model), os.path.join(element, name)
            )

    def path(self, mapset, name=""):
        return os.path.join(self.location, mapset, "sbrt", name)

    def manage(self, *flags, **options):
        """Runs r3.sbrt.manage in WORK: the finished process, its text output
        and its messages with GRASS's line wrapping undone (messages)."""
        args = ["r3.sbrt.manage"] + list(flags)
        args += [f"{key}={value}" for key, value in options.items()]
        run = subprocess.run(args, env=self.env, capture_output=True, text=True)
        run.messages = " ".join(run.stderr.split())
        return run

    @staticmethod
    def is_lock(name):
        """A writers' lock file, `.NAME.lock` beside SBRT NAME: empty, kept
        (a lock file removed would let two writers lock two files)."""
        return name.startswith(".") and name.endswith(".lock")

    def snapshot(self, mapset):
        """Every file of the mapset's sbrt element with its bytes (the
        writers' lock files aside)."""
        files = {}
        for top, _, names in os.walk(self.path(mapset)):
            for name in names:
                if top == self.path(mapset) and self.is_lock(name):
                    continue
                path = os.path.join(top, name)
                with open(path, "rb") as f:
                    files[os.path.relpath(path, self.path(mapset))] = f.read()
        return files

    def assertSameModel(self, directory, model):
        """The SBRT files of `directory` are those of model `model`."""
        for name in SBRT_FILES:
            self.assertTrue(
                filecmp.cmp(
                    os.path.join(directory, name),
                    os.path.join(self.models, model, name),
                    shallow=False,
                ),
                f"{directory}/{name} differs from {model}",
            )

    def assertEntries(self, mapset, names):
        """Exactly `names` in the sbrt element: no leftover, hidden or not
        (the writers' lock files aside, each empty)."""
        entries = os.listdir(self.path(mapset))
        for lock in filter(self.is_lock, entries):
            self.assertEqual(os.path.getsize(os.path.join(self.path(mapset), lock)), 0)
        self.assertEqual(sorted(e for e in entries if not self.is_lock(e)), sorted(names))


class TestManageList(ManageFixture):
    def test_list_names_the_search_path(self):
        run = self.manage("-l")
        self.assertEqual(run.returncode, 0, run.stderr)
        # geo is in both mapsets, so as g.list it says which is which
        self.assertEqual(
            run.stdout.splitlines(),
            ["cave", "deep", f"geo@{OTHER}", f"geo@{WORK}"],
        )

    def test_list_qualified(self):
        run = self.manage("-l", "-m")
        self.assertEqual(
            run.stdout.splitlines(),
            [f"cave@{WORK}", f"deep@{OTHER}", f"geo@{OTHER}", f"geo@{WORK}"],
        )

    def test_list_one_mapset(self):
        self.assertEqual(self.manage("-l", mapset=OTHER).stdout, "deep\ngeo\n")
        self.assertEqual(
            self.manage("-l", "-m", mapset=OTHER).stdout,
            f"deep@{OTHER}\ngeo@{OTHER}\n",
        )
        self.assertEqual(self.manage("-l", mapset=".").stdout, "cave\ngeo\n")

    def test_list_mapset_that_does_not_exist(self):
        run = self.manage("-l", mapset="no_such_mapset")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("Mapset <no_such_mapset> does not exist", run.messages)

    def test_list_only_mapsets_of_the_location(self):
        """Issue 28, item 3: mapset= is the name of a mapset of the
        location, never a path out of it or a directory that is no mapset."""
        location = os.path.basename(self.location)
        outside = os.path.join(os.path.dirname(self.location), "sbrt_manage_outside")
        not_a_mapset = os.path.join(self.location, "sbrt_manage_no_mapset")
        for top in (outside, not_a_mapset):
            os.makedirs(os.path.join(top, "sbrt", "secret"), exist_ok=True)
        self.addCleanup(shutil.rmtree, outside, ignore_errors=True)
        self.addCleanup(shutil.rmtree, not_a_mapset, ignore_errors=True)
        # (no subTest: GRASS 8.2's gunittest drops subtests' failures)
        for mapset in (
            f"../{location}/{OTHER}",
            "../sbrt_manage_outside",
            f"{OTHER}/../{WORK}",
            "sbrt_manage_no_mapset",
        ):
            run = self.manage("-l", "-m", mapset=mapset)
            self.assertNotEqual(run.returncode, 0, mapset)
            self.assertEqual(run.stdout, "", mapset)
            self.assertIn(
                f"Mapset <{mapset}> does not exist in location <{location}>",
                run.messages,
            )
        # nor as the mapset of a name to copy
        run = self.manage(copy="secret@sbrt_manage_no_mapset,secret")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("<secret@sbrt_manage_no_mapset> does not exist", run.messages)
        self.assertEntries(WORK, ["cave", "geo"])

    def test_list_skips_hidden_leftovers_and_empty_mapsets(self):
        # what a killed copy leaves behind is not an SBRT
        os.makedirs(self.path(WORK, ".geo.tmp.12345"))
        shutil.rmtree(self.path(OTHER))
        self.assertEqual(self.manage("-l").stdout, "cave\ngeo\n")
        run = self.manage("-l", mapset=OTHER)
        self.assertEqual((run.returncode, run.stdout), (0, ""))

    def test_one_operation_per_call(self):
        self.assertNotEqual(self.manage().returncode, 0)
        self.assertNotEqual(self.manage("-m").returncode, 0)
        self.assertNotEqual(self.manage("-l", remove="geo").returncode, 0)
        self.assertNotEqual(self.manage(copy="geo").returncode, 0)


class TestManageCopy(ManageFixture):
    def test_copy_is_identical(self):
        run = self.manage(copy="geo,geo_copy")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn(
            f"Copying SBRT model <geo@{WORK}> to current mapset as <geo_copy>",
            run.messages,
        )
        self.assertSameModel(self.path(WORK, "geo_copy"), "manage_layers")
        self.assertEntries(WORK, ["cave", "geo", "geo_copy"])
        # the copy reads as its original does
        figures = [
            gs.read_command("r3.sbrt.convert", flags="g", input=name, env=self.env)
            for name in ("geo", "geo_copy")
        ]
        self.assertEqual(
            figures[0].replace("name=geo\n", "name=geo_copy\n"), figures[1]
        )
        # its history is the original's and says where it came from
        with open(self.path(WORK, "geo/hist")) as f:
            original = f.read()
        with open(self.path(WORK, "geo_copy/hist")) as f:
            history = f.read()
        self.assertTrue(history.startswith(original))
        self.assertIn(f"copied from: geo@{WORK}\n", history[len(original):])

    def test_copy_from_another_mapset_of_the_search_path(self):
        before = self.snapshot(OTHER)
        run = self.manage(copy=f"geo@{OTHER},from_other")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertSameModel(self.path(WORK, "from_other"), "manage_caves")
        # found through the search path, kept its name, other mapset untouched
        self.assertEqual(self.manage(copy="deep,deep").returncode, 0)
        self.assertSameModel(self.path(WORK, "deep"), "manage_layers")
        self.assertEqual(self.snapshot(OTHER), before)
        self.assertEntries(WORK, ["cave", "deep", "from_other", "geo"])

    def test_copy_onto_existing_needs_overwrite(self):
        run = self.manage(copy=f"geo@{OTHER},geo")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn(
            "<geo> already exists and overwrite is not enabled. Skipping.",
            run.messages,
        )
        self.assertIn("All inputs had to be skipped. Nothing to copy.", run.messages)
        self.assertSameModel(self.path(WORK, "geo"), "manage_layers")

        run = self.manage("--overwrite", copy=f"geo@{OTHER},geo")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertSameModel(self.path(WORK, "geo"), "manage_caves")
        self.assertEntries(WORK, ["cave", "geo"])

    def test_copy_onto_itself_is_skipped(self):
        for source in ("geo", f"geo@{WORK}"):
            run = self.manage("--overwrite", copy=f"{source},GEO")
            self.assertNotEqual(run.returncode, 0)
            self.assertIn(
                f"copy={source},GEO: files are the same, no copy required. "
                "Skipping.",
                run.messages,
            )
        self.assertEntries(WORK, ["cave", "geo"])

    def test_copy_of_missing_sbrt(self):
        run = self.manage(copy="nothing,something")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("<nothing> does not exist. Skipping.", run.messages)
        run = self.manage(copy=f"cave@{OTHER},something")
        self.assertIn(f"<cave@{OTHER}> does not exist. Skipping.", run.messages)
        self.assertEntries(WORK, ["cave", "geo"])

    def test_copy_to_illegal_name(self):
        for target in (".hidden", "a@b", "a/b"):
            run = self.manage(copy=f"geo,{target}")
            self.assertNotEqual(run.returncode, 0)
            self.assertIn(
                f"<{target}> is an illegal file name. Skipping.", run.messages
            )
        self.assertEntries(WORK, ["cave", "geo"])

    def test_copy_and_rename_to_a_too_long_name(self):
        """Issue 28, item 9: a 300-character name is refused with the
        limit, not with the file system's error."""
        long_name = "n" * 300
        for option in ("copy", "rename"):
            run = self.manage(**{option: "geo," + long_name})
            self.assertNotEqual(run.returncode, 0)
            self.assertIn("at most 239", " ".join(run.messages.split()))
            self.assertNotIn("AtomicDirectory", run.messages)
        self.assertEntries(WORK, ["cave", "geo"])

    def test_several_pairs_copy_what_they_can(self):
        run = self.manage(copy="geo,g1,nothing,g2,cave,g3,deep,geo")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("<nothing> does not exist. Skipping.", run.messages)
        self.assertIn("<geo> already exists", run.messages)
        self.assertSameModel(self.path(WORK, "g1"), "manage_layers")
        self.assertSameModel(self.path(WORK, "g3"), "manage_caves")
        self.assertEntries(WORK, ["cave", "g1", "g3", "geo"])

    def test_failed_copy_leaves_nothing_behind(self):
        # a file that cannot be read breaks the copy half way
        os.symlink("/nonexistent/file", self.path(WORK, "geo/zz_missing"))
        run = self.manage("--overwrite", copy="geo,broken,geo,cave")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("Unable to copy SBRT model <geo", run.messages)
        self.assertIn("Nothing was copied.", run.messages)
        # no temporary directory left, the replaced SBRT as it was
        self.assertEntries(WORK, ["cave", "geo"])
        self.assertSameModel(self.path(WORK, "cave"), "manage_caves")


class TestManageCopyHostile(ManageFixture):
    """Issue 28, item 1: an SBRT of another mapset is untrusted input; its
    members are copied only as regular files, never through a link."""

    def copy_refused(self, member, kind):
        """copy=geo@OTHER,copied fails in time, naming `member` and what it
        is, and writes nothing: WORK and everything outside as they were."""
        work = self.snapshot(WORK)
        around = sorted(os.listdir(os.path.dirname(self.location)))
        run = subprocess.run(
            ["r3.sbrt.manage", f"copy=geo@{OTHER},copied"],
            env=self.env, capture_output=True, text=True, timeout=5,
        )
        messages = " ".join(run.stderr.split())
        self.assertNotEqual(run.returncode, 0, messages)
        self.assertIn(
            f"{self.path(OTHER, 'geo')}/{member}: {kind}, not a regular file",
            messages,
        )
        self.assertIn("Nothing was copied.", messages)
        self.assertEqual(self.snapshot(WORK), work)
        self.assertEntries(WORK, ["cave", "geo"])
        self.assertEqual(sorted(os.listdir(os.path.dirname(self.location))), around)

    def test_symlinked_stacks_is_not_followed(self):
        # a file outside the location: read through the link, it would be
        # copied (and a relative path built from it can leave the mapset)
        outside = os.path.join(os.path.dirname(self.location), "sbrt_manage_file")
        with open(outside, "w") as f:
            f.write("not an SBRT\n")
        self.addCleanup(os.remove, outside)
        os.remove(self.path(OTHER, "geo/stacks"))
        os.symlink(outside, self.path(OTHER, "geo/stacks"))
        self.copy_refused("stacks", "a symbolic link")
        with open(outside) as f:
            self.assertEqual(f.read(), "not an SBRT\n")

    def test_member_linked_to_a_directory_is_not_walked(self):
        os.symlink("/etc", self.path(OTHER, "geo/etc"))
        self.copy_refused("etc", "a symbolic link")

    def test_fifo_member_is_refused_without_waiting(self):
        for member in ("cats", "hist"):
            self.setUp()
            os.remove(self.path(OTHER, f"geo/{member}"))
            os.mkfifo(self.path(OTHER, f"geo/{member}"))
            self.copy_refused(member, "a FIFO (named pipe)")

    def test_subdirectory_is_refused(self):
        os.makedirs(self.path(OTHER, "geo/sub"))
        with open(self.path(OTHER, "geo/sub/file"), "w") as f:
            f.write("x")
        self.copy_refused("sub", "a directory")

    def test_linked_sbrt_is_refused(self):
        os.symlink(self.path(WORK, "cave"), self.path(OTHER, "linked"))
        run = self.manage(copy=f"linked@{OTHER},copied")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn(
            f"{self.path(OTHER, 'linked')}: a symbolic link, not a directory",
            run.messages,
        )
        self.assertEntries(WORK, ["cave", "geo"])


class TestManageRename(ManageFixture):
    def test_rename(self):
        run = self.manage(rename="cave,cave2")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("Rename SBRT model <cave> to <cave2>", run.messages)
        self.assertEntries(WORK, ["cave2", "geo"])
        self.assertSameModel(self.path(WORK, "cave2"), "manage_caves")

    def test_rename_onto_existing_needs_overwrite(self):
        run = self.manage(rename="cave,geo")
        # g.rename warns and still succeeds
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn(f"<geo> already exists in mapset <{WORK}>", run.messages)
        self.assertEntries(WORK, ["cave", "geo"])
        self.assertSameModel(self.path(WORK, "geo"), "manage_layers")

        run = self.manage("--overwrite", rename="cave,geo")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEntries(WORK, ["geo"])
        self.assertSameModel(self.path(WORK, "geo"), "manage_caves")

    def test_rename_stays_in_the_current_mapset(self):
        before = self.snapshot(OTHER)
        # deep is only in OTHER: not found here, and its name is free here
        run = self.manage(rename="deep,x")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("SBRT model <deep> not found", run.messages)
        self.assertEqual(self.manage(rename="cave,deep").returncode, 0)
        self.assertEntries(WORK, ["deep", "geo"])
        self.assertEqual(self.snapshot(OTHER), before)

    def test_rename_to_same_or_illegal_name(self):
        run = self.manage("--overwrite", rename="cave,CAVE")
        self.assertIn(
            "rename=cave,CAVE: files could be the same, no rename possible",
            run.messages,
        )
        for target in (".hidden", "a/b"):
            run = self.manage(rename=f"cave,{target}")
            self.assertIn(f"<{target}> is an illegal file name", run.messages)
        self.assertEntries(WORK, ["cave", "geo"])

    def test_several_pairs(self):
        run = self.manage(rename=f"cave,c1,nothing,n1,geo@{WORK},g1")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("SBRT model <nothing> not found", run.messages)
        self.assertEntries(WORK, ["c1", "g1"])
        self.assertSameModel(self.path(WORK, "g1"), "manage_layers")


class TestManageRemove(ManageFixture):
    def test_remove_without_force_only_prints(self):
        run = self.manage(remove="geo,cave,nothing")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(run.stdout, f"sbrt/cave@{WORK}\nsbrt/geo@{WORK}\n")
        self.assertIn("would be deleted", run.messages)
        self.assertIn("You must use the force flag (-f)", run.messages)
        self.assertEntries(WORK, ["cave", "geo"])

    def test_remove_with_force(self):
        before = self.snapshot(OTHER)
        run = self.manage("-f", remove=f"geo,cave@{WORK},nothing")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("Removing SBRT model <cave>", run.messages)
        self.assertIn("Removing SBRT model <geo>", run.messages)
        self.assertEntries(WORK, [])
        # geo@OTHER is now the one found, untouched
        self.assertEqual(self.snapshot(OTHER), before)
        self.assertEqual(self.manage("-l", "-m").stdout, f"deep@{OTHER}\ngeo@{OTHER}\n")

    def test_remove_finds_nothing(self):
        run = self.manage("-f", remove="deep,nothing")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("No data base element files found", run.messages)
        self.assertEntries(OTHER, ["deep", "geo"])

    def test_remove_in_another_mapset_fails(self):
        run = self.manage("-f", remove=f"geo,deep@{OTHER}")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn(
            f"deep@{OTHER}: Cannot remove or exclude files not in the current "
            "mapset.",
            run.messages,
        )
        self.assertEntries(WORK, ["cave", "geo"])
        self.assertEntries(OTHER, ["deep", "geo"])

    def test_remove_illegal_names_fails(self):
        run = self.manage("-f", remove="geo,../sbrt_manage_other/sbrt/geo")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("Illegal filenames not allowed", run.messages)
        self.assertEntries(WORK, ["cave", "geo"])
        self.assertEntries(OTHER, ["deep", "geo"])


if __name__ == "__main__":
    test()
