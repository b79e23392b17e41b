"""
MODULE:    testsuite/test_g_gui_sbrt_smooth.py (r3.sbrt addon)
PURPOSE:   g.gui.sbrt's smooth shading (kernel normals) never stalls a
           gesture: under Xvfb, a drag with pauses (longer than the refine
           delay and than the rest delay) gets full frames with face normals
           while the button is held and no kernel frame is asked for; once
           released, the face frame comes first and the smooth one replaces
           it; the wheel, a slider (its thumb held still) and a scene change
           likewise
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import time

from grass.gunittest.case import TestCase
from grass.gunittest.main import test

from viewer_fixture import ViewerSession

SIZE = (320, 240)
# a button held still this long, well past the viewer's rest delay
# (viewer_frame.SMOOTH_MS, 300 ms): a smooth frame asked for because the
# mouse rested would be asked for within it
HOLD_S = 1.0
KERNEL = "normals=kernel"


def kernel(event):
    return event["event"] == "frame" and KERNEL in event["words"]


class TestViewerSmoothShading(TestCase, ViewerSession):
    @classmethod
    def setUpClass(cls):
        cls.use_temp_region()
        # a voxel model (its tops on voxel boundaries: smooth shading on)
        cls.runModule("g.region", n=1000, s=0, e=1200, w=0, t=24, b=0, res=100,
                      res3=100, tbres=2)
        cls.runModule("r3.mapcalc", overwrite=True,
                      expression="smo = if(depth() > 6 + (row() * 3 + col() * 2) % 5, "
                                 "null(), 1 + (depth() / 3 + col() / 4) % 3)")
        cls.runModule("r3.sbrt.convert", input="smo", output="smo")
        cls.start_viewer(["input=smo", "size=%d,%d" % SIZE])

    @classmethod
    def tearDownClass(cls):
        cls.runModule("r3.sbrt.manage", flags="f", remove="smo")
        cls.runModule("g.remove", flags="f", type="raster_3d", name="smo")
        cls.del_temp_region()

    def smooth_after(self, count):
        """The smooth frame after event `count`, and the full frames before
        it (face normals: each comes first)."""
        smooth = self.wait_for(kernel, after=count)
        self.assertTrue(smooth["smooth"], smooth)
        faces = [e for e in self.events()[count:] if e["event"] == "frame" and
                 e["full"] and e["t"] < smooth["t"]]
        self.assertTrue(faces, "no face frame before the smooth one")
        self.assertTrue(all(KERNEL not in e["words"] for e in faces), faces)
        return smooth, faces

    def test_1_start_face_then_smooth(self):
        smooth, faces = self.smooth_after(0)
        self.assertIn("zexag=", " ".join(smooth["words"]))

    def test_2_drag_with_pauses(self):
        self.smooth_after(0)  # the start settled
        count = len(self.events())
        x, y, width, height = self.widgets["canvas"]
        self.xdotool("mousemove", x + width // 3, y + height // 2, "mousedown", 1)
        press = self.wait_for(lambda e: e["event"] == "press", after=count)
        for _ in range(3):  # moves, then a pause past the refine delay
            self.xdotool("mousemove_relative", "--", 6, 0, "sleep", 0.02,
                         "mousemove_relative", "--", 6, 0)
            moved = len(self.events())
            # the pause gets the full-size frame, face normals
            face = self.wait_for(lambda e: e["event"] == "frame" and e["full"],
                                 after=moved)
            self.assertNotIn(KERNEL, face["words"])
        time.sleep(HOLD_S)  # the button held still
        held = self.events()[count:]
        self.xdotool("mouseup", 1)
        still = self.wait_for(lambda e: e["event"] == "still", after=count)
        during = [e for e in held if press["t"] <= e["t"] <= still["t"]]
        self.assertTrue([e for e in during if e["event"] == "drag"])
        self.assertTrue([e for e in during if e["event"] == "frame" and not e["full"]])
        self.assertEqual([e for e in during if kernel(e)], [])
        self.assertEqual([e for e in during if e["event"] == "request" and
                          e["kind"] == "smooth"], [])
        # released: the face frame at once, then the smooth one
        smooth, faces = self.smooth_after(len(held) + count)
        self.assertGreater(faces[0]["t"], still["t"])
        azimuth = [w for w in smooth["words"] if w.startswith("azimuth=")]
        self.assertIn(azimuth[0], faces[-1]["words"])  # the same view, smoother

    def test_3_wheel_and_scene_change(self):
        self.smooth_after(0)
        x, y, width, height = self.widgets["canvas"]
        count = len(self.events())
        self.xdotool("mousemove", x + width // 2, y + height // 2, "click", 4, "click", 4)
        smooth, faces = self.smooth_after(count)
        self.assertTrue(any(w.startswith("distance=") for w in smooth["words"]))
        # smooth shading off: the face frame, no smooth one; on: it follows
        count = len(self.events())
        self.click("smooth", x_offset=8)
        off = self.full_frame_after(count)
        self.assertNotIn(KERNEL, off["words"])
        count = len(self.events())
        self.click("smooth", x_offset=8)
        self.wait_for(kernel, after=count)

    def test_4_slider_held(self):
        self.smooth_after(0)
        count = len(self.events())
        x, y, width, height = self.widgets["zexag"]
        # the thumb follows the pointer from the trough on, held still
        self.xdotool("mousemove", x + width // 4, y + height // 2, "mousedown", 1,
                     "sleep", 0.1, "mousemove_relative", "--", 10, 0, "sleep", 0.1,
                     "mousemove_relative", "--", 10, 0)
        face = self.wait_for(lambda e: e["event"] == "frame" and e["full"], after=count)
        self.assertNotIn(KERNEL, face["words"])
        time.sleep(HOLD_S)
        held = self.events()[count:]
        self.xdotool("mouseup", 1)
        self.assertEqual([e for e in held if kernel(e)], [])
        self.assertEqual([e for e in held if e["event"] == "request" and
                          e["kind"] == "smooth"], [])
        smooth, faces = self.smooth_after(count)
        self.assertIn(face["number"], [e["number"] for e in faces])


if __name__ == "__main__":
    test()
