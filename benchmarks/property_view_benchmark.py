"""
MODULE:    benchmarks/property_view_benchmark.py (r3.sbrt addon)
PURPOSE:   What a property view costs against the class view of the same
           camera (issue 29: <= 1.3x), in process and warm: r3.sbrt.render's
           view server renders each view 14 times while the camera turns a
           degree a frame (scene kept), the first 2 left out; medians of
           the server's own frame times, three rounds in one run
USAGE:     in a GRASS session, an SBRT with GeoTOP-like channels (e.g.
           channels_benchmark.sh's or geotop_like's, imported with -a):
           python3 property_view_benchmark.py SBRT [WIDTH HEIGHT [BACKEND]]
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "g.gui.sbrt"))
from view_client import ViewServer  # noqa: E402

SAND = "kans_5+kans_6+kans_7"
VIEWS = (("class", []), ("property", ["property=" + SAND]), ("fade", ["fade=onz_lk"]),
         ("select", ["select=%s>=60" % SAND]))


def main():
    sbrt = sys.argv[1]
    width, height = (int(sys.argv[2]), int(sys.argv[3])) if len(sys.argv) > 3 else (1056, 884)
    backend = sys.argv[4] if len(sys.argv) > 4 else "cpu"
    print("property views of <%s>, %d x %d, backend=%s, %d cores" % (
        sbrt, width, height, backend, os.cpu_count()))
    server = ViewServer()
    for round_ in range(3):
        medians = {}
        for name, extra in VIEWS:
            times = []
            for k in range(14):
                frame = server.render(["input=" + sbrt, "size=%d,%d" % (width, height),
                                       "zexag=20", "azimuth=%d" % (200 + k), "elevation=35",
                                       "backend=" + backend] + extra)
                if k >= 2:
                    times.append(frame.ms)
            medians[name] = statistics.median(times)
        print("round %d: " % (round_ + 1) + ", ".join(
            "%s %.1f ms (%.2fx)" % (name, medians[name], medians[name] / medians["class"])
            for name, _ in VIEWS))
    server.close()


if __name__ == "__main__":
    main()
