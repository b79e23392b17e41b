"""
MODULE:    benchmarks/server_frames.py (r3.sbrt addon)
PURPOSE:   The view server's figures of issue 49 (r3.sbrt.render --serve,
           driven through g.gui.sbrt's own client), in a GRASS session,
           one new server process: the first frame (process start, model
           read, scene), frames of an orbit at a reduced size (the camera
           moved: the viewer's frames while dragging), a stratum hidden
           (hide= changed) + frame; after each step the server's peak RSS
           (VmHWM). Prints one JSON object (with "error" where a step
           failed: the figures before it kept). Figures only: never part of
           pass/fail.
USAGE:     server_frames.py SBRT [WIDTH HEIGHT [ORBIT_WIDTH ORBIT_HEIGHT [FRAMES]]]
           (800 600 400 300 12); SBRT_MEMORY=MB adds memory=MB to every
           request, SBRT_SERVER_WORDS="word..." those words (backend=egl)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import json
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "g.gui.sbrt"))
from view_client import ViewServer  # noqa: E402

NO_CLASS = -2147483648  # the strata list's entry for cells of no class


def peak_rss_kb(pid):
    """VmHWM of process `pid` in kB (0 where /proc does not say)."""
    try:
        with open("/proc/%d/status" % pid) as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0


def main():
    sbrt = sys.argv[1]
    numbers = [int(v) for v in sys.argv[2:]]
    width, height, orbit_width, orbit_height, frames = (
        numbers + [800, 600, 400, 300, 12][len(numbers):])
    budget = ["memory=" + os.environ["SBRT_MEMORY"]] if os.environ.get("SBRT_MEMORY") else []
    # e.g. SBRT_SERVER_WORDS="backend=egl": the GPU's frames
    budget += os.environ.get("SBRT_SERVER_WORDS", "").split()
    server = ViewServer()
    figures = {"sbrt": sbrt, "size": [width, height], "orbit_size": [orbit_width, orbit_height]}
    try:
        start = time.perf_counter()
        server.render(["input=" + sbrt, "size=%d,%d" % (width, height)] + budget)
        figures["first_s"] = time.perf_counter() - start
        pid = server._process.pid  # the client keeps it private; a benchmark may look
        figures["first_rss_kb"] = peak_rss_kb(pid)
        times, served = [], []
        for k in range(1, frames + 1):
            start = time.perf_counter()
            # as the viewer orbits: the camera and its light turn together
            frame = server.render(["input=" + sbrt, "size=%d,%d" % (orbit_width, orbit_height),
                                   "azimuth=%d" % ((225 + k * 10) % 360),
                                   "light=%d,45" % ((270 + k * 10) % 360)] + budget)
            times.append((time.perf_counter() - start) * 1000)
            served.append(frame.ms)
        figures["orbit_ms"] = statistics.median(times)
        figures["orbit_server_ms"] = statistics.median(served)
        figures["orbit_rss_kb"] = peak_rss_kb(pid)
        # a stratum of the model: the demo models' 13, else the first
        ids = [s.id for s in server.strata(sbrt)[1] if s.id != NO_CLASS]
        hidden = 13 if 13 in ids else ids[0]
        start = time.perf_counter()
        server.render(["input=" + sbrt, "size=%d,%d" % (width, height), "hide=%d" % hidden]
                      + budget)
        figures["hide_s"] = time.perf_counter() - start
        figures["hide_id"] = hidden
        figures["hide_rss_kb"] = peak_rss_kb(pid)
    except Exception as error:  # the figures so far, and why the rest are missing
        figures["error"] = "%s: %s" % (type(error).__name__, error)
    finally:
        server.close()
    print(json.dumps(figures))
    return 1 if "error" in figures else 0


if __name__ == "__main__":
    sys.exit(main())
