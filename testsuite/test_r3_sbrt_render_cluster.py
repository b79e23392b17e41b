"""
MODULE:    testsuite/test_r3_sbrt_render_cluster.py (r3.sbrt addon)
PURPOSE:   The manual's recipes for many views on many machines, run as
           written on a one-node Slurm cluster (tools/slurm_cluster.sh): an
           orbit as a job array (a frame range per task, each task a GRASS
           session of its own in a mapset of its own), then the video from
           the frames; a 4 x 4 tile poster as a job array, then the mosaic
           (r.patch, and the PNG); a task killed halfway and run again; the
           orbit with GNU parallel. Each against the same work in one
           process: PNGs pixel for pixel, maps cell for cell. Skipped, with
           the reason, where Slurm cannot start.
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import signal
import struct
import subprocess
import tempfile
import time

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import image_region, set_up_t_model

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLUSTER = os.path.join(ROOT, "tools", "slurm_cluster.sh")
SIZE = (160, 120)
# the killed task's frames: slow enough on one thread to be killed halfway
# (on faster machines too: 1.2 M pixels a frame)
KILLED_SIZE = (1280, 960)
FRAMES = 24
TASKS = 4
# what a job's GRASS session needs of this one's environment
JOB_ENV = "PATH,HOME,GRASS_ADDON_BASE,GRASS_SKIP_MAPSET_OWNER_CHECK"


def pixels(path):
    from PIL import Image

    with Image.open(path) as image:
        return image.size, image.convert("RGB").tobytes()


class TestCluster(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = gs.tempfile(create=False)
        os.makedirs(cls.work)
        # a short path: Slurm's sockets lie in it (108 bytes at most)
        cls.slurm = tempfile.mkdtemp(prefix="sbrt_slurm.", dir="/tmp")
        cls.addClassCleanup(shutil.rmtree, cls.slurm, ignore_errors=True) # after the stop
        run = subprocess.run([CLUSTER, "start", cls.slurm], capture_output=True, text=True)
        cls.skipped = None
        if run.returncode != 0:
            # each test skipped, saying why (tools/run_tests.sh prints it)
            cls.skipped = run.stderr.strip() or "tools/slurm_cluster.sh failed"
            print(f"SKIPPED: {cls.skipped}")
            return
        cls.env = dict(os.environ, SLURM_CONF=os.path.join(cls.slurm, "slurm.conf"))
        cls.addClassCleanup(subprocess.run, [CLUSTER, "stop", cls.slurm], capture_output=True)
        set_up_t_model(cls)
        image_region(cls, *SIZE)
        env = gs.gisenv()
        cls.mapset = env["MAPSET"]
        cls.location = os.path.join(env["GISDBASE"], env["LOCATION_NAME"])
        # the jobs' new mapsets start in the project's default region: the
        # image's, as the manual says to set it once (g.region -s)
        cls.runModule("g.region", save="image", overwrite=True)
        shutil.copy(os.path.join(cls.location, cls.mapset, "windows", "image"),
                    os.path.join(cls.location, "PERMANENT", "DEFAULT_WIND"))

    @classmethod
    def tearDownClass(cls):
        if not cls.skipped:
            cls.del_temp_region()

    def setUp(self):
        if self.skipped:
            self.skipTest(self.skipped)

    def render(self, *args, size=SIZE):
        run = subprocess.run(["r3.sbrt.render", "input=geo", "size=%d,%d" % size,
                              "backend=cpu", *args], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, msg=run.stderr)

    def job_script(self, name, lines):
        """A job array's script: the manual's lines, its paths made real."""
        path = os.path.join(self.work, name + ".sh")
        with open(path, "w") as script:
            script.write("#!/bin/bash\n#SBATCH --cpus-per-task=1\n")
            script.write("\n".join(lines).replace("/data/loc", self.location)
                         .replace("/data", self.work)
                         .replace("geology@PERMANENT", f"geo@{self.mapset}") + "\n")
        return path

    def sbatch(self, script, array, wait=True):
        """Submits `script` as --array=`array`; returns the job id once every
        task has ended (tools/slurm_cluster.sh wait: sbatch --wait would poll
        every 2 to 10 s), or at once (wait=False)."""
        run = subprocess.run(
            ["sbatch", "--parsable", f"--array={array}", f"--export={JOB_ENV}",
             f"--output={self.work}/%x_%a.out", script],
            capture_output=True, text=True, env=self.env)
        self.assertEqual(run.returncode, 0, msg=run.stderr)
        job = run.stdout.strip().split(";")[0]
        if not wait:
            return job
        try:
            run = subprocess.run([CLUSTER, "wait", self.slurm, job],
                                 capture_output=True, text=True, env=self.env, timeout=600)
        except subprocess.TimeoutExpired:
            queue = subprocess.run(["squeue"], capture_output=True, text=True, env=self.env)
            subprocess.run(["scancel", "--user=root"], env=self.env)
            self.fail(f"the job array did not end in 10 minutes:\n{queue.stdout}")
        logs = ""
        for name in sorted(os.listdir(self.work)):
            if name.endswith(".out"):
                with open(os.path.join(self.work, name)) as out:
                    logs += f"--- {name}\n{out.read()[-1500:]}"
        self.assertEqual(run.returncode, 0, msg=run.stderr + logs)
        return job

    def orbit_lines(self, png, size=SIZE, frames_a_task=FRAMES // TASKS):
        # the manual's job array, a quarter of the frames a task, each task
        # in a mapset of its own (made by its first run's session: a rerun
        # finds it)
        return [f"first=$((SLURM_ARRAY_TASK_ID * {frames_a_task} + 1))",
                "mapset=/data/loc/job$SLURM_ARRAY_TASK_ID",
                "new=; [ -d $mapset ] || new=-c",
                "grass $new $mapset --exec r3.sbrt.render input=geology@PERMANENT "
                "nprocs=$SLURM_CPUS_PER_TASK \\",
                f"    frames={FRAMES} range=$first-$((first + {frames_a_task - 1})) "
                f"size={size[0]},{size[1]} backend=cpu png={png}"]

    def one_process_orbit(self, size=SIZE):
        png = os.path.join(self.work, "one_%dx%d" % size, "orbit_%04d.png")
        os.makedirs(os.path.dirname(png), exist_ok=True)
        if not os.path.exists(png % FRAMES):
            self.render(f"frames={FRAMES}", f"png={png}", size=size)
        return png

    def assertSameFrames(self, got, want):
        for k in range(1, FRAMES + 1):
            self.assertEqual(pixels(got % k), pixels(want % k), f"frame {k}")

    def test_orbit_as_a_job_array_then_the_video(self):
        png = "/data/orbit/orbit_%04d.png"
        os.makedirs(os.path.join(self.work, "orbit"))
        self.sbatch(self.job_script("orbit", self.orbit_lines(png)), f"0-{TASKS - 1}")
        got = png.replace("/data", self.work)
        self.assertSameFrames(got, self.one_process_orbit())
        # each task in its own mapset
        for task in range(TASKS):
            self.assertTrue(os.path.isdir(os.path.join(self.location, f"job{task}")))
        # the video from the frames there: nothing rendered again
        video = os.path.join(self.work, "orbit.mp4")
        before = os.path.getmtime(got % 1)
        self.render(f"frames={FRAMES}", f"png={got}", f"video={video}")
        self.assertEqual(os.path.getmtime(got % 1), before)
        count = subprocess.run(
            ["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
             "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0", video],
            capture_output=True, text=True, check=True).stdout.strip()
        self.assertEqual(int(count), FRAMES)

    def test_poster_as_a_job_array_then_the_mosaic(self):
        from PIL import Image

        cols, rows = SIZE
        th, tw = rows // 4, cols // 4
        # a task a tile: row and column from the task's number
        lines = [f"row=$((SLURM_ARRAY_TASK_ID / 4 * {th})) col=$((SLURM_ARRAY_TASK_ID % 4 * {tw}))",
                 "mapset=/data/loc/poster$SLURM_ARRAY_TASK_ID",
                 "new=; [ -d $mapset ] || new=-c",
                 "grass $new $mapset --exec r3.sbrt.render input=geology@PERMANENT "
                 "nprocs=$SLURM_CPUS_PER_TASK \\",
                 f"    size={cols},{rows} tile=$row,$col,{th},{tw} backend=cpu zexag=2 "
                 "output=tile_$SLURM_ARRAY_TASK_ID material=tile_$SLURM_ARRAY_TASK_ID.class \\",
                 "    png=/data/poster/tile_$SLURM_ARRAY_TASK_ID.png"]
        os.makedirs(os.path.join(self.work, "poster"))
        self.sbatch(self.job_script("poster", lines), "0-15")
        whole = os.path.join(self.work, "whole.png")
        self.render("output=whole", "material=whole_class", f"png={whole}", "-n", "zexag=2")
        mosaic = Image.new("RGB", SIZE)
        for task in range(16):
            with Image.open(os.path.join(self.work, "poster", f"tile_{task}.png")) as tile:
                self.assertEqual(tile.size, (tw, th))
                mosaic.paste(tile, (task % 4 * tw, task // 4 * th))
        with Image.open(whole) as image:
            self.assertEqual(list(mosaic.getdata()), list(image.convert("RGB").getdata()))
        # the tiles' maps, each in its task's mapset, joined by r.patch
        self.runModule("r.patch", overwrite=True, output="patched",
                       input=[f"tile_{t}.class@poster{t}" for t in range(16)])
        self.runModule("r.mapcalc", overwrite=True,
                       expression="dif = if(isnull(patched) &&& isnull(whole_class), 0, "
                       "if(isnull(patched) ||| isnull(whole_class), 1, patched != whole_class))")
        stats = gs.parse_command("r.univar", map="dif", flags="g")
        self.assertEqual(int(stats["n"]), cols * rows)
        self.assertEqual(float(stats["sum"]), 0)
        self.assertGreater(int(gs.parse_command("r.univar", map="whole_class", flags="g")["n"]),
                           cols * rows // 5)

    @staticmethod
    def lock_holder(lock):
        """The process GRASS's mapset lock `lock` names while it runs (not
        once it is a zombie), else None. GRASS's etc/lock writes the pid as
        a native int, not as text: 2610 is b"2\\n\\0\\0", which read as text
        names pid 2 (the kernel's kthreadd, never ended)."""
        try:
            with open(lock, "rb") as f:
                (pid,) = struct.unpack("=i", f.read(struct.calcsize("=i")))
            with open(f"/proc/{pid}/stat") as f:
                state = f.read().rsplit(")", 1)[1].split()[0]
            return None if state in ("Z", "X") else pid
        except (OSError, struct.error, IndexError):
            return None

    def wait_for_lock_release(self, lock):
        """Waits until no running process holds GRASS's mapset lock `lock`:
        the killed session's GRASS may outlive the job's place in the queue
        by a moment, and one that Slurm's kill did not reach (seen in a
        chroot) is ended as scancel would have; the lock of a process that
        is gone is removed, as GRASS would take it over (a zombie's too,
        which GRASS's own check still counts as running)."""
        settle = time.time() + 60
        while self.lock_holder(lock) and time.time() < settle:
            time.sleep(0.1)
        pid = self.lock_holder(lock)
        if pid:
            os.kill(pid, signal.SIGKILL)
            settle = time.time() + 10
            while self.lock_holder(lock) and time.time() < settle:
                time.sleep(0.1)
        self.assertIsNone(self.lock_holder(lock), "the killed task's GRASS still runs")
        if os.path.exists(lock):
            os.remove(lock)

    def test_a_task_killed_halfway_is_run_again(self):
        png = "/data/killed/orbit_%04d.png"
        got = png.replace("/data", self.work)
        os.makedirs(os.path.dirname(got))
        # one task for every frame, larger ones, killed once its first
        # frames are done
        script = self.job_script("killed", self.orbit_lines(png, KILLED_SIZE, FRAMES))
        job = self.sbatch(script, "0", wait=False)
        deadline = time.time() + 120
        while not os.path.exists(got % 3) and time.time() < deadline:
            time.sleep(0.05)
        subprocess.run(["scancel", job], env=self.env, check=True)
        while subprocess.run(["squeue", "--noheader", "-j", job], capture_output=True, text=True,
                             env=self.env).stdout.strip() and time.time() < deadline:
            time.sleep(0.1)
        # GRASS refuses a mapset whose lock names a live process: the
        # killed session's lock goes first (the rerun is what is tested)
        self.wait_for_lock_release(os.path.join(self.location, "job0", ".gislock"))
        done = [k for k in range(1, FRAMES + 1) if os.path.exists(got % k)]
        self.assertGreaterEqual(len(done), 3)
        self.assertLess(len(done), FRAMES, "the task ended before it was killed")
        # the frame it was on: its claim file left, its lock gone with it
        self.assertTrue([n for n in os.listdir(os.path.dirname(got)) if n.endswith(".claim")])
        kept = {k: os.path.getmtime(got % k) for k in done}
        # the same task again: the finished frames stay, the rest are made
        self.sbatch(script, "0")
        self.assertSameFrames(got, self.one_process_orbit(KILLED_SIZE))
        for k, when in kept.items():
            self.assertEqual(os.path.getmtime(got % k), when, f"frame {k} made again")

    def test_orbit_with_gnu_parallel(self):
        if not shutil.which("parallel"):
            self.skipTest("GNU parallel is not installed")
        got = os.path.join(self.work, "parallel", "orbit_%04d.png")
        os.makedirs(os.path.dirname(got))
        step = FRAMES // TASKS
        env = {k: os.environ[k] for k in JOB_ENV.split(",") if k in os.environ}
        run = subprocess.run(
            f"seq 1 {step} {FRAMES} | parallel -j {TASKS} 'm={self.location}/par{{}}; "
            f"c=; [ -d $m ] || c=-c; grass $c $m "
            f"--exec r3.sbrt.render input=geo@{self.mapset} frames={FRAMES} "
            f"range={{}}-$(({{}}+{step - 1})) size={SIZE[0]},{SIZE[1]} backend=cpu png={got}'",
            shell=True, capture_output=True, text=True, env=env)
        self.assertEqual(run.returncode, 0, msg=run.stderr[-3000:])
        self.assertSameFrames(got, self.one_process_orbit())


if __name__ == "__main__":
    test()
