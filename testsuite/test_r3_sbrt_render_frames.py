"""
MODULE:    testsuite/test_r3_sbrt_render_frames.py (r3.sbrt addon)
PURPOSE:   Animations of r3.sbrt.render: an orbit's frame k against a single
           render from the turned camera, a range= run against the full
           run, a sweep's first frame against the uncut model, reruns that
           keep finished frames, the space-time raster dataset, the video
           (ffprobe), and clear errors for bad sequences
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import math
import os
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test
import grass.script as gs

from geomodel_fixture import image_region, set_up_t_model

SIZE = (48, 36)
POSITION = (-900.0, -700.0, 1400.0)
TARGET = (1000.0, 1250.0, 300.0)


def turned(p, axis, degrees):
    """p turned about the vertical through axis, counter-clockwise from above
    (the module's arithmetic, so that the camera is the same to the bit)."""
    a = degrees * math.pi / 180
    c, s = math.cos(a), math.sin(a)
    dx, dy = p[0] - axis[0], p[1] - axis[1]
    return (axis[0] + c * dx - s * dy, axis[1] + s * dx + c * dy, p[2])


def said(run):
    """A run's messages with GRASS's line wrapping undone."""
    return " ".join(run.stderr.split())


def point(p):
    return ",".join(repr(v) for v in p)


class TestFrames(TestCase):
    @classmethod
    def setUpClass(cls):
        set_up_t_model(cls)

    @classmethod
    def tearDownClass(cls):
        cls.del_temp_region()

    def setUp(self):
        image_region(self, *SIZE)
        self.dir = gs.tempfile(create=False)
        os.makedirs(self.dir)

    def render(self, *args, check=True):
        run = subprocess.run(
            ["r3.sbrt.render", "input=geo", "size=%d,%d" % SIZE, "backend=cpu", *args],
            capture_output=True, text=True)
        if check:
            self.assertEqual(run.returncode, 0, msg=run.stderr)
        return run

    def differing(self, a, b):
        self.runModule("r.mapcalc", overwrite=True,
                       expression=f"dif = if(isnull({a}) &&& isnull({b}), 0, "
                       f"if(isnull({a}) ||| isnull({b}), 1, {a} != {b}))")
        return int(float(gs.parse_command("r.univar", map="dif", flags="g")["sum"]))

    def hits(self, name):
        return int(gs.parse_command("r.univar", map=name, flags="g")["n"])

    def test_orbit_frame_is_the_turned_camera(self):
        frames = 6
        self.render("output=orb", "material=orb_m", f"frames={frames}", "zexag=2",
                    f"position={point(POSITION)}", f"target={point(TARGET)}")
        for k in (1, 3, 6):
            single = turned(POSITION, TARGET, (k - 1) * 360 / frames)
            self.render("output=one", "material=one_m", "zexag=2", "--overwrite",
                        f"position={point(single)}", f"target={point(TARGET)}")
            self.assertGreater(self.hits("one_m"), SIZE[0] * SIZE[1] // 5)
            self.assertEqual(self.differing(f"orb_m_{k:04d}", "one_m"), 0, msg=k)
        # the frames differ (the camera turns); angle= sets the arc: frame 2
        # of 2 over 240 degrees is 120 degrees on, as frame 3 of 6 over 360
        self.assertGreater(self.differing("orb_m_0001", "orb_m_0004"), 100)
        self.render("output=arc", "material=arc_m", "frames=2", "angle=240",
                    "zexag=2", f"position={point(POSITION)}", f"target={point(TARGET)}")
        self.assertEqual(self.differing("arc_m_0002", "orb_m_0003"), 0)

    def test_default_orbit_keeps_the_whole_model_in_every_frame(self):
        self.render("output=dfl", "material=dfl_m", "frames=8", "zexag=2")
        for k in range(1, 9):
            name = f"dfl_m_{k:04d}"
            # the border rows and columns see background only
            self.runModule("r.mapcalc", overwrite=True,
                           expression=f"edge = if((row() == 1 || row() == {SIZE[1]} || "
                           f"col() == 1 || col() == {SIZE[0]}) && !isnull({name}), 1, 0)")
            edge = gs.parse_command("r.univar", map="edge", flags="g")
            self.assertEqual(int(float(edge["sum"])), 0, msg=name)
            self.assertGreater(self.hits(name), SIZE[0] * SIZE[1] // 5, msg=name)

    def test_range_equals_the_same_frames_of_the_full_run(self):
        self.render("output=full", "material=full_m", "frames=5", "depth=full_d")
        self.render("output=part", "material=part_m", "frames=5", "depth=part_d",
                    "range=2-3")
        for k in (2, 3):
            self.assertEqual(self.differing(f"full_m_{k:04d}", f"part_m_{k:04d}"), 0)
            self.assertRastersNoDifference(f"full_d_{k:04d}", f"part_d_{k:04d}",
                                           precision=0)
            self.assertRastersNoDifference(f"full_{k:04d}.red", f"part_{k:04d}.red",
                                           precision=0)
        for k in (1, 4, 5):
            self.assertRasterDoesNotExist(f"part_m_{k:04d}")
        self.render("output=one1", "material=one1_m", "frames=5", "range=4")
        self.assertEqual(self.differing("full_m_0004", "one1_m_0004"), 0)

    def test_rerun_keeps_finished_frames(self):
        png = os.path.join(self.dir, "re_%02d.png")
        self.render("output=re", f"png={png}", "frames=3")
        files = [png % k for k in (1, 2, 3)]
        times = [os.stat(f).st_mtime_ns for f in files]
        run = self.render("output=re", f"png={png}", "frames=3")
        self.assertIn("3 frames were there already", said(run))
        self.assertEqual([os.stat(f).st_mtime_ns for f in files], times)
        # a frame whose PNG is missing (a killed job) is rendered again
        os.remove(files[1])
        run = self.render("output=re", f"png={png}", "frames=3")
        self.assertIn("2 frames were there already", said(run))
        self.assertTrue(os.path.exists(files[1]))
        self.assertEqual(os.stat(files[0]).st_mtime_ns, times[0])
        # --overwrite renders them all again
        self.render("output=re", f"png={png}", "frames=3", "--overwrite")
        self.assertNotEqual(os.stat(files[2]).st_mtime_ns, times[2])
        # without a pattern, _NNNN goes before the extension
        self.render("output=nn", f"png={os.path.join(self.dir, 'nn.png')}", "frames=2")
        self.assertTrue(os.path.exists(os.path.join(self.dir, "nn_0002.png")))

    def test_two_jobs_at_one_frame_are_refused(self):
        import fcntl

        png = os.path.join(self.dir, "cl_%02d.png")
        claim = png % 2 + ".claim"
        # another job holds frame 2 (its claim locked): this one stops
        # there, naming it
        with open(claim, "w") as held:
            held.write("node7 process 4242\n")
            held.flush()
            fcntl.flock(held, fcntl.LOCK_EX)
            run = self.render(f"png={png}", "frames=3", check=False)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("Frame 2", said(run))
        self.assertIn("being rendered by another job (node7 process 4242", said(run))
        self.assertTrue(os.path.exists(png % 1))
        self.assertFalse(os.path.exists(png % 2))
        # that job was killed: its file holds no lock and is taken over;
        # the frames are made and no claim is left
        self.assertTrue(os.path.exists(claim))
        self.render(f"png={png}", "frames=3")
        self.assertTrue(all(os.path.exists(png % k) for k in (1, 2, 3)))
        self.assertEqual([n for n in os.listdir(self.dir) if n.endswith(".claim")], [])

    def test_sweep_moves_the_plane_across_the_model(self):
        frames = 4
        self.render("output=sw", "material=sw_m", f"frames={frames}", "path=sweep",
                    "plane=0,0,300,1,1,0")
        self.render("output=whole", "material=whole_m")
        # frame 1 cuts nothing; each next one cuts more
        self.assertEqual(self.differing("sw_m_0001", "whole_m"), 0)
        counts = [self.hits(f"sw_m_{k:04d}") for k in range(1, frames + 1)]
        self.assertEqual(sorted(counts, reverse=True), counts)
        self.assertLess(counts[-1], counts[0])
        self.assertGreater(counts[-1], 0)

    def test_frames_form_a_space_time_dataset(self):
        self.render("output=ts", "frames=4", "strds=ts_frames", "range=1-2")
        self.render("output=ts", "frames=4", "strds=ts_frames", "range=3-4")
        rows = gs.read_command("t.rast.list", input="ts_frames", columns="name,start_time",
                               flags="u").split()
        self.assertEqual(rows, [f"ts_{k:04d}|{k - 1}" for k in range(1, 5)])
        info = gs.parse_command("t.info", input="ts_frames", flags="g")
        self.assertEqual(info["temporal_type"], "relative")

    def test_video_has_every_frame(self):
        if not shutil.which("ffprobe"):
            self.skipTest("no ffmpeg (tools/setup.sh installs it)")
        png = os.path.join(self.dir, "v_%03d.png")
        video = os.path.join(self.dir, "orbit.mp4")
        self.render("output=v", f"png={png}", "frames=6", f"video={video}", "fps=6")
        count = subprocess.run(
            ["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
             "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0", video],
            capture_output=True, text=True, check=True).stdout.strip()
        self.assertEqual(count, "6")
        # a range= job that leaves frames missing makes no video yet
        os.remove(video)
        run = self.render("output=v2", f"png={os.path.join(self.dir, 'w_%03d.png')}",
                          "frames=6", f"video={video}", "range=1-2")
        self.assertIn("frame 3 is not rendered", said(run))
        self.assertFalse(os.path.exists(video))

    def test_video_without_png(self):
        """Issue 31, item 6: video= alone makes the video from frames in a
        temporary folder, removed after."""
        if not shutil.which("ffprobe"):
            self.skipTest("no ffmpeg (tools/setup.sh installs it)")
        video = os.path.join(self.dir, "alone.mp4")
        env = gs.gisenv()
        tmp = os.path.join(env["GISDBASE"], env["LOCATION_NAME"], env["MAPSET"], ".tmp")
        before = set(os.listdir(tmp)) if os.path.isdir(tmp) else set()
        self.render("output=va", "frames=4", f"video={video}", "fps=4")
        count = subprocess.run(
            ["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
             "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0", video],
            capture_output=True, text=True, check=True).stdout.strip()
        self.assertEqual(count, "4")
        after = set(os.listdir(tmp)) if os.path.isdir(tmp) else set()
        self.assertEqual(after - before, set(), "frames left behind")

    def test_keys_pass_through_every_keyframe(self):
        keys = [(-800, -800, 1500, 1000, 1250, 300, 40),
                (1000, -1500, 1200, 1000, 1250, 300, 35),
                (2800, -800, 1500, 1000, 1250, 300, 40)]
        path = os.path.join(self.dir, "keys.txt")
        with open(path, "w") as f:
            f.write("# x y z tx ty tz fov\n")
            for key in keys:
                f.write(" ".join(str(v) for v in key) + "\n")
        self.render("output=ky", "material=ky_m", "frames=5", "path=keys", f"keys={path}")
        for k, key in ((1, keys[0]), (3, keys[1]), (5, keys[2])):
            self.render("output=one", "material=one_m", "--overwrite",
                        f"position={point(key[:3])}", f"target={point(key[3:6])}",
                        f"fov={key[6]}")
            self.assertEqual(self.differing(f"ky_m_{k:04d}", "one_m"), 0, msg=k)
        # in between, a view of its own
        self.assertGreater(self.differing("ky_m_0002", "ky_m_0001"), 50)
        with open(path, "w") as f:
            f.write("0 0 1500 1000 1250 300\n")
        run = self.render("output=bad", "frames=3", "path=keys", f"keys={path}",
                          check=False)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("at least two", said(run))

    def test_line_frames_stand_on_the_line(self):
        # a 3D line west of the model, towards it, 300 m up
        self.runModule("v.in.ascii", input="-", output="flight", format="standard",
                       flags="zn", overwrite=True,
                       stdin_="L 2\n -1500 1250 300\n -500 1250 300\n")
        self.render("output=ln", "material=ln_m", "frames=3", "path=line",
                    "path_map=flight")
        # frame 2: the middle of the line, looking a step (500 m) east, level
        self.render("output=one", "material=one_m", "--overwrite",
                    "position=-1000,1250,300", "target=-500,1250,300")
        self.assertGreater(self.hits("one_m"), SIZE[0] * SIZE[1] // 10)
        self.assertEqual(self.differing("ln_m_0002", "one_m"), 0)
        self.assertGreater(self.differing("ln_m_0001", "ln_m_0003"), 20)
        # height= over a 2D line: the camera that high above the model's top
        self.runModule("v.in.ascii", input="-", output="flat", format="standard",
                       flags="n", overwrite=True, stdin_="L 2\n 100 100\n 1900 2400\n")
        self.render("output=lh", "material=lh_m", "frames=3", "path=line",
                    "path_map=flat", "height=300")
        self.assertGreater(self.hits("lh_m_0001"), SIZE[0] * SIZE[1] // 4)
        run = self.render("output=bad", "frames=3", "path=line", "path_map=flat",
                          check=False)
        self.assertIn("is 2D: give height=", said(run))
        self.runModule("v.in.ascii", input="-", output="spot", format="point",
                       separator=",", overwrite=True, stdin_="1000,1000\n")
        run = self.render("output=bad", "frames=3", "path=line", "path_map=spot",
                          check=False)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("has no lines", said(run))

    def test_tiles_mosaic_to_the_whole_image(self):
        from PIL import Image

        cols, rows = SIZE
        whole = os.path.join(self.dir, "whole.png")
        self.render("output=wh", "material=wh_m", f"png={whole}", "-n", "zexag=2")
        mosaic = Image.new("RGB", SIZE)
        tiles = []
        for row, height in ((0, 20), (20, rows - 20)):
            for col, width in ((0, 30), (30, cols - 30)):
                name = f"ti_{row}_{col}"
                png = os.path.join(self.dir, name + ".png")
                self.render(f"output={name}", f"material={name}_m", f"png={png}",
                            f"tile={row},{col},{height},{width}", "zexag=2")
                with Image.open(png) as tile:
                    self.assertEqual(tile.size, (width, height))
                    mosaic.paste(tile, (col, row))
                tiles.append(f"{name}_m")
        with Image.open(whole) as image:
            self.assertEqual(list(mosaic.getdata()), list(image.getdata()))
        # the tiles' maps lie in the whole image's window: r.patch joins them
        self.runModule("r.patch", input=tiles, output="patched", overwrite=True)
        self.assertEqual(self.differing("patched", "wh_m"), 0)
        self.assertGreater(self.hits("wh_m"), cols * rows // 5)
        for bad, words in (("0,0,40,10", "within the"), ("0,0,0,10", "within the")):
            run = self.render("output=bad", f"tile={bad}", check=False)
            self.assertNotEqual(run.returncode, 0)
            self.assertIn(words, said(run))
        run = self.render("output=bad", "tile=0,0,10,10", "normals=kernel", check=False)
        self.assertIn("would not mosaic", said(run))

    def test_gpu_frames_upload_once_and_match_the_cpu(self):
        # EGL (llvmpipe here): the model goes to the GPU once for all frames
        run = subprocess.run(
            ["r3.sbrt.render", "input=geo", "size=%d,%d" % SIZE, "backend=egl",
             "output=gf", "material=gf_m", "frames=3", "zexag=2", "--verbose"],
            capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, msg=run.stderr)
        self.assertEqual(run.stderr.count("Model upload:"), 1)
        self.assertEqual(run.stderr.count("Bands back:"), 3)
        # shaded on the GPU: the bytes asked for read, nothing else (RGB
        # and the class id: 3 + 4)
        self.assertEqual(run.stderr.count("(7.00 bytes a pixel)"), 3, msg=run.stderr)
        self.render("output=cf", "material=cf_m", "frames=3", "zexag=2")
        for k in (1, 2, 3):
            # float32 on the GPU: a few edge pixels may differ
            self.assertLessEqual(self.differing(f"gf_m_{k:04d}", f"cf_m_{k:04d}"),
                                 SIZE[0] * SIZE[1] // 100, msg=k)
            self.assertGreater(self.hits(f"gf_m_{k:04d}"), SIZE[0] * SIZE[1] // 5)

    def test_bad_sequences_fail_clearly(self):
        # file names in a folder of its own: a file left in /tmp by
        # something else is not what the checks meet first
        folder = tempfile.mkdtemp(prefix="r3sbrt_bad_frames_")
        self.addCleanup(shutil.rmtree, folder, ignore_errors=True)
        a = os.path.join(folder, "a")
        for args, words in (
            (["frames=0"], "frames=0"),
            (["frames=4", "range=3-5"], "range=3-5"),
            (["frames=4", "range=3-2"], "range=3-2"),
            (["frames=4", "path=sweep"], "plane= or section="),
            (["frames=4", "path=line"], "give path_map="),
            (["frames=4", "path=keys"], "give keys="),
            (["frames=4", "view=top"], "top view does not turn"),
            (["frames=2", "png=%s_%%d_%%d.png" % a], "one %d"),
            (["frames=2", "png=%s.png" % a, "video=%s.avi" % a], ".mp4, .webm or .gif"),
            (["frames=4", "video=%s.mp4" % a, "range=1-2"], "without png="),
            (["strds=x"], "give frames="),
        ):
            run = self.render("output=bad", *args, check=False)
            self.assertNotEqual(run.returncode, 0, msg=args)
            self.assertIn(words, said(run), msg=args)
            self.assertRasterDoesNotExist("bad_0001")
        # video= without ffmpeg on the PATH: said before any frame is made
        env = dict(os.environ, PATH=os.path.dirname(shutil.which("r3.sbrt.render")))
        run = subprocess.run(
            [shutil.which("r3.sbrt.render"), "input=geo", "output=bad", "frames=2",
             "png=/tmp/b_%d.png", "video=/tmp/b.mp4"],
            capture_output=True, text=True, env=env)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("needs ffmpeg", said(run))
        self.assertRasterDoesNotExist("bad_0001")


if __name__ == "__main__":
    test()
