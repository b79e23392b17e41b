"""
MODULE:    testsuite/test_g_gui_sbrt_gui.py (r3.sbrt addon)
PURPOSE:   g.gui.sbrt driven as a person would, under Xvfb: xdotool drags
           and clicks, screenshots (ImageMagick's import). A drag turns the
           view; hiding a stratum in the list removes its colour from the
           screen; "Save view" writes maps equal to the screen pixel for
           pixel (the command it shows renders them); "Record orbit" writes
           the frames and the video; "Section profile" opens the profile
           r3.sbrt.profile draws along the section's line
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os

from grass.gunittest.case import TestCase
from grass.gunittest.main import test

from geomodel_fixture import set_up_t_model
from viewer_fixture import ViewerSession, read_rgb_maps

SIZE = (480, 560)  # asked for; the window may make the view larger
MEMORY = 400


def shade_family(pixel, color):
    """Whether `pixel` is `color` lit by some share of light (the
    shading: colour x (ambient + (1 - ambient) x lambert))."""
    dot = sum(c * c for c in color)
    if dot == 0:
        return False
    k = sum(p * c for p, c in zip(pixel, color)) / dot
    return 0.3 < k < 1.05 and all(abs(p - k * c) <= 3 for p, c in zip(pixel, color))


class TestViewerGui(TestCase, ViewerSession):
    @classmethod
    def setUpClass(cls):
        set_up_t_model(cls)
        # memory= as r3.sbrt.render's: every request carries it
        cls.start_viewer(["input=geo", "size=%d,%d" % SIZE, "memory=%d" % MEMORY])

    @classmethod
    def tearDownClass(cls):
        # the viewer and Xvfb end in the class cleanups (also after a
        # failed set-up)
        cls.del_temp_region()

    @staticmethod
    def own_pixels(rgb, strata):
        """Per stratum id, the pixels of its colour family and of no other
        stratum's (shaded colours of similar strata are left out)."""
        counts = {s.id: 0 for s in strata}
        for i in range(0, len(rgb), 3):
            pixel = tuple(rgb[i:i + 3])
            owners = [s.id for s in strata if shade_family(pixel, s.rgb)]
            if len(owners) == 1:
                counts[owners[0]] += 1
        return counts

    def test_drag_hide_and_save(self):
        # the legend off: the canvas shows the frame alone
        self.click("legend")
        start = self.screenshot()
        x, y, width, height = self.widgets["canvas"]
        self.assertGreaterEqual(width, SIZE[0])
        self.assertGreaterEqual(height, SIZE[1])
        self.assertEqual(len(start), width * height * 3)

        # a drag across the view turns it
        count = len(self.events())
        moves = ["mousemove", x + width // 3, y + height // 2, "mousedown", 1]
        for _ in range(12):
            moves += ["mousemove_relative", "--", 8, 0, "sleep", 0.03]
        self.xdotool(*(moves + ["mouseup", 1]))
        still = self.wait_for(lambda e: e["event"] == "still", after=count)
        frame = self.wait_for(lambda e: e["event"] == "frame" and e["full"] and
                              e["t"] > still["t"], after=count)
        azimuth = [w for w in frame["words"] if w.startswith("azimuth=")][0]
        self.assertNotEqual(azimuth, "azimuth=225")
        self.assertIn("memory=%d" % MEMORY, frame["words"])
        turned = self.screenshot()
        differing = sum(1 for i in range(0, len(turned), 3)
                        if turned[i:i + 3] != start[i:i + 3])
        self.assertGreater(differing, 0.1 * width * height)

        # hiding the stratum that covers most of the screen removes its colour
        from view_client import ViewServer
        server = ViewServer()
        _, all_strata = server.strata("geo")
        server.close()
        all_strata = [s for s in all_strata if s.id >= 0]
        # the rows in sight in the list (a person would scroll for the others)
        _, list_y, _, list_height = self.widgets["strata"]
        _, side_y, _, side_height = self.widgets["controls"]
        list_height = min(list_y + list_height, side_y + side_height) - list_y
        strata = [s for s in all_strata if "stratum %d" % s.id in self.widgets and
                  list_y + 25 <= self.widgets["stratum %d" % s.id][1] and
                  sum(self.widgets["stratum %d" % s.id][1::2]) <= list_y + list_height]
        counts = self.own_pixels(turned, all_strata)
        biggest = max(strata, key=lambda s: counts[s.id])
        self.assertGreater(counts[biggest.id], 500)
        count = len(self.events())
        self.click("stratum %d" % biggest.id)
        self.full_frame_after(count, "hide=%d" % biggest.id)
        # a voxel model: the smooth frame (the one Save view renders)
        # replaces the face frame once the view rests
        self.full_frame_after(count, "hide=%d" % biggest.id, smooth=True)
        hidden = self.screenshot()
        self.assertLess(self.own_pixels(hidden, all_strata)[biggest.id],
                        0.01 * counts[biggest.id])

        # Save view: the maps (its command line's) are the screen, pixel for pixel
        count = len(self.events())
        tx, ty, tw, th = self.widgets["toolbar"]
        self.xdotool("mousemove", tx + 30, ty + th // 2, "click", 1)
        self.xdotool("search", "--sync", "--name", "^Save view$", "windowfocus", "--sync")
        self.xdotool("type", "gui_saved")
        self.xdotool("key", "Return")
        saved = self.wait_for(lambda e: e["event"] == "saved", after=count)
        self.assertEqual(saved["returncode"], 0, saved["messages"])
        self.assertIn("hide=%d" % biggest.id, saved["command"])
        self.assertIn("output=gui_saved", saved["command"])
        self.assertIn("memory=%d" % MEMORY, saved["command"])
        self.assertTrue(os.path.exists(os.path.join(self.work, "gui_saved.png")))
        self.use_temp_region()
        self.runModule("g.region", raster="gui_saved.red")
        cols, rows, rgb = read_rgb_maps("gui_saved")
        self.assertEqual((cols, rows), (width, height))
        differing = sum(1 for i in range(0, len(rgb), 3) if rgb[i:i + 3] != hidden[i:i + 3])
        self.assertEqual(differing, 0)

        # Record orbit: 4 frames typed, the PNGs and the video of the turn
        count = len(self.events())
        self.xdotool("mousemove", tx + 130, ty + th // 2, "click", 1)
        self.xdotool("search", "--sync", "--name", "^Record orbit$", "windowfocus", "--sync")
        self.xdotool("type", "4")
        self.xdotool("key", "Tab")
        self.xdotool("key", "Return")
        recorded = self.wait_for(lambda e: e["event"] == "recorded", after=count)
        self.assertEqual(recorded["returncode"], 0, recorded["messages"])
        self.assertIn("frames=4", recorded["command"])
        self.assertIn("path=orbit", recorded["command"])
        pngs = sorted(f for f in os.listdir(self.work) if f.startswith("geo_orbit_"))
        self.assertEqual(pngs, ["geo_orbit_%04d.png" % k for k in range(1, 5)])
        self.assertGreater(os.path.getsize(os.path.join(self.work, "geo_orbit.mp4")), 0)

    def test_section_profile(self):
        # the section on: its line is the profile's
        count = len(self.events())
        self.click("section")
        self.wait_for(lambda e: e["event"] == "frame" and e["full"] and
                      any(w.startswith("section=") for w in e["words"]), after=count)
        count = len(self.events())
        tx, ty, tw, th = self.widgets["toolbar"]
        self.xdotool("mousemove", tx + 268, ty + th // 2, "click", 1)
        profiled = self.wait_for(lambda e: e["event"] == "profiled", after=count)
        self.assertEqual(profiled["returncode"], 0, profiled["messages"])
        self.assertIn("r3.sbrt.profile input=geo coordinates=", profiled["command"])
        shown = self.wait_for(lambda e: e["event"] == "section_profile", after=count)
        self.assertTrue(os.path.exists(shown["png"]))
        width, height = shown["size"]
        self.assertGreater(width, 600)
        self.assertGreater(height, 300)
        self.xdotool("search", "--sync", "--name", "^Profile of the section of geo",
                     "windowfocus", "--sync")


if __name__ == "__main__":
    test()
