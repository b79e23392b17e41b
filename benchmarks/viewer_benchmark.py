"""
MODULE:    benchmarks/viewer_benchmark.py (r3.sbrt addon)
PURPOSE:   Figures of g.gui.sbrt (issue 19), in a GRASS session, one run:
           1. the renderer alone through the view server: frames of an
              orbit at full size and reduced (1/2 each way), a scene
              change (a stratum hidden), the first frame (model read);
           2. the viewer end to end under Xvfb: orbiting drags at 60 mouse
              events a second (xdotool), frames shown per second while
              dragging and the time from the last mouse move to the refined
              frame on screen, from the viewer's event log.
           Figures only: never part of pass/fail.
USAGE:     viewer_benchmark.py SBRT [WIDTH HEIGHT [r3.sbrt.render options...]]
           VIEWER_FIGURES=path also writes the figures as one JSON object
           (national_views.sh reads them)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "g.gui.sbrt"))
from view_client import ViewServer  # noqa: E402

# what VIEWER_FIGURES gets: ms, frames a second, kB
FIGURES = {}


def child_pids(pid):
    """The processes whose parent is `pid` (from /proc)."""
    children = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open("/proc/%s/stat" % entry) as stat:
                    # the parent follows the command's closing parenthesis
                    if int(stat.read().rsplit(")", 1)[1].split()[1]) == pid:
                        children.append(int(entry))
            except (OSError, IndexError, ValueError):
                pass
    return children


def process_name(pid):
    """The command name of process `pid` ("" where it is gone)."""
    try:
        with open("/proc/%d/comm" % pid) as comm:
            return comm.read().strip()
    except OSError:
        return ""


def peak_rss_kb(pid):
    """VmHWM of process `pid` in kB (0 where /proc does not say)."""
    try:
        with open("/proc/%d/status" % pid) as status:
            match = re.search(r"^VmHWM:\s+(\d+)", status.read(), re.M)
            return int(match.group(1)) if match else 0
    except OSError:
        return 0


def renderer_alone(sbrt, width, height, extra=()):
    server = ViewServer()
    extra = list(extra)
    start = time.perf_counter()
    server.render(["input=" + sbrt, "size=%d,%d" % (width, height)] + extra)
    first = (time.perf_counter() - start) * 1000
    FIGURES["renderer_first_ms"] = first
    for label, size in (("full", (width, height)),
                        ("reduced", (width // 2, height // 2))):
        times, served = [], []
        for k in range(36):
            start = time.perf_counter()
            # the viewer's light turns with the camera
            frame = server.render(["input=" + sbrt, "size=%d,%d" % size,
                                   "azimuth=%d" % (k * 10),
                                   "light=%d,45" % ((k * 10 + 45) % 360)] + extra)
            times.append((time.perf_counter() - start) * 1000)
            served.append(frame.ms)
        median = statistics.median(times)
        FIGURES["renderer_%s_ms" % label] = median
        print("renderer %-7s %4d x %-4d: median %.1f ms a frame (server %.1f ms, "
              "pipe and client the rest), %.1f frames/s" %
              (label, size[0], size[1], median, statistics.median(served), 1000 / median))
    # a stratum of the model (the demo models' 13, else the first)
    ids = [s.id for s in server.strata(sbrt)[1] if s.id != -2147483648]
    hidden = 13 if 13 in ids else ids[0]
    start = time.perf_counter()
    server.render(["input=" + sbrt, "size=%d,%d" % (width, height),
                   "hide=%d" % hidden] + extra)
    FIGURES["renderer_hide_ms"] = (time.perf_counter() - start) * 1000
    FIGURES["renderer_hide_id"] = hidden
    print("renderer scene change (hide=%d, prepared again) + frame: %.1f ms"
          % (hidden, FIGURES["renderer_hide_ms"]))
    # a click on another stratum's check box, as the viewer answers it:
    # the reduced frame (the coarse level where the SBRT has one), then
    # the exact frame
    reduced = ["input=" + sbrt, "size=%d,%d" % (width // 2, height // 2), "detail=coarse"]
    server.render(reduced + ["hide=%d" % hidden] + extra)  # the coarse level read
    other = next((i for i in ids if i != hidden), hidden)
    start = time.perf_counter()
    server.render(reduced + ["hide=%d,%d" % (hidden, other)] + extra)
    FIGURES["renderer_hide_reduced_ms"] = (time.perf_counter() - start) * 1000
    server.render(["input=" + sbrt, "size=%d,%d" % (width, height),
                   "hide=%d,%d" % (hidden, other)] + extra)
    FIGURES["renderer_hide_exact_ms"] = (time.perf_counter() - start) * 1000
    print("renderer a stratum hidden as the viewer asks: reduced frame %.1f ms, exact "
          "frame %.1f ms after the request" % (FIGURES["renderer_hide_reduced_ms"],
                                              FIGURES["renderer_hide_exact_ms"]))
    print("renderer first frame (process start, model read, scene): %.1f ms" % first)
    FIGURES["renderer_rss_kb"] = peak_rss_kb(server._process.pid)
    print("renderer peak RSS: %.0f MB" % (FIGURES["renderer_rss_kb"] / 1024))
    server.close()


def viewer(sbrt, width, height, extra=()):
    work = tempfile.mkdtemp(prefix="viewer_bench_")
    log = os.path.join(work, "viewer.log")
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", "1", "-screen", "0", "1600x1000x24", "-noreset"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    display = ":" + xvfb.stdout.readline().decode().strip()
    env = dict(os.environ, DISPLAY=display, GRASS_SBRT_VIEWER_LOG=log, NO_AT_BRIDGE="1")
    # of the extra words, the viewer takes property= (it colours by it)
    # and memory= (every request it sends carries it)
    options = [w for w in extra if w.startswith(("property=", "memory="))]
    started = time.monotonic()  # the viewer's log times are the same clock
    gui = subprocess.Popen(["g.gui.sbrt", "input=" + sbrt, "size=%d,%d" % (width, height)]
                           + options,
                           cwd=work, env=env, stderr=subprocess.DEVNULL)

    def events():
        with open(log) as f:
            return [json.loads(line) for line in f if line.endswith("\n")]

    try:
        deadline = time.time() + 120
        while not (os.path.exists(log) and
                   any(e["event"] == "widget" for e in events())):
            if time.time() > deadline or gui.poll() is not None:
                raise RuntimeError("g.gui.sbrt did not start")
            time.sleep(0.2)
        canvas = [e["rect"] for e in events() if e.get("name") == "canvas"][0]
        first = [e for e in events() if e["event"] == "frame"][0]
        FIGURES["viewer_first_s"] = first["t"] - started
        print("viewer first frame shown: %.2f s after g.gui.sbrt started (%s)"
              % (first["t"] - started, "full" if first["full"] else "reduced"))
        # the first exact frame (widgets are logged after it)
        exact = [e["t"] for e in events() if e["event"] == "frame" and e["full"]][0]
        FIGURES["viewer_first_exact_s"] = exact - started
        print("viewer first exact frame shown: %.2f s after g.gui.sbrt started"
              % (exact - started))
        FIGURES["viewer_fps"], FIGURES["viewer_refined_ms"] = [], []
        FIGURES["viewer_refined_server_ms"], FIGURES["viewer_refined_options"] = [], []
        x, y, w, h = canvas
        for drag in range(3):
            count = len(events())
            moves = ["mousemove", x + w // 4, y + h // 2, "mousedown", 1]
            for _step in range(120):  # 2 s at 60 events a second
                moves += ["mousemove_relative", "--", 3, 0, "sleep", 1 / 60]
            subprocess.run(["xdotool"] + [str(m) for m in moves], env=env, check=True)
            time.sleep(1.0)  # the mouse rests, the button still down
            subprocess.run(["xdotool", "mouseup", "1"], env=env, check=True)
            time.sleep(0.5)
            # a large model's exact frame may come later: wait for it (30 s)
            deadline = time.time() + 30
            while True:
                new = events()[count:]
                drags = [e["t"] for e in new if e["event"] == "drag"]
                if not drags:
                    raise RuntimeError("g.gui.sbrt logged no drag (xdotool reached no canvas)")
                frames = [e for e in new if e["event"] == "frame"]
                exact = [f for f in frames if f["full"] and f["t"] > drags[-1]]
                refined = [f["t"] for f in exact]
                if refined or time.time() > deadline:
                    break
                time.sleep(0.2)
            during = [f for f in frames if drags[0] <= f["t"] <= drags[-1]]
            reduced = [f for f in during if not f["full"]]
            FIGURES["viewer_fps"].append(len(during) / (drags[-1] - drags[0]))
            if refined:
                FIGURES["viewer_refined_ms"].append((refined[0] - drags[-1]) * 1000)
                FIGURES["viewer_refined_server_ms"].append(exact[0]["ms"])
                # the options that set the exact frame apart (normals=kernel
                # on a model of voxel steps)
                FIGURES["viewer_refined_options"] = sorted(
                    w for w in exact[0]["words"] if w.startswith(("normals=", "smooth=", "kernel=")))
            print("viewer drag %d: %d mouse moves in %.2f s; %d frames shown while "
                  "dragging (%d reduced %d x %d): %.1f frames/s; refined %.0f ms "
                  "after the last move%s" % (
                      drag + 1, len(drags), drags[-1] - drags[0], len(during),
                      len(reduced), reduced[0]["width"] if reduced else 0,
                      reduced[0]["height"] if reduced else 0,
                      len(during) / (drags[-1] - drags[0]),
                      (refined[0] - drags[-1]) * 1000 if refined else float("nan"),
                      " (server %.0f ms%s)" % (exact[0]["ms"], "".join(
                          " " + w for w in FIGURES["viewer_refined_options"])) if exact else ""))
    finally:
        # the peak of the viewer's view server (its child r3.sbrt.render)
        servers = [pid for pid in child_pids(gui.pid) if process_name(pid) == "r3.sbrt.render"]
        if servers:
            FIGURES["viewer_server_rss_kb"] = peak_rss_kb(servers[0])
            print("viewer's view server peak RSS: %.0f MB"
                  % (FIGURES["viewer_server_rss_kb"] / 1024))
        gui.terminate()
        gui.wait(timeout=10)
        xvfb.terminate()
        # VIEWER_LOG=path keeps the viewer's event log (what it asked, when)
        if os.environ.get("VIEWER_LOG") and os.path.exists(log):
            shutil.copyfile(log, os.environ["VIEWER_LOG"])
        shutil.rmtree(work, ignore_errors=True)


def main():
    """SBRT [WIDTH HEIGHT [r3.sbrt.render options...]]: the options (e.g.
    property=kans_5+kans_6+kans_7 zexag=20) go with every frame."""
    sbrt = sys.argv[1]
    width, height = (int(sys.argv[2]), int(sys.argv[3])) if len(sys.argv) > 3 else (800, 600)
    extra = sys.argv[4:]
    print("g.gui.sbrt on <%s>, %d x %d, %d cores%s" % (
        sbrt, width, height, os.cpu_count(), (" with " + " ".join(extra)) if extra else ""))
    FIGURES.update(sbrt=sbrt, size=[width, height])
    try:
        renderer_alone(sbrt, width, height, extra)
        viewer(sbrt, width, height, extra)
    except Exception as error:  # the figures so far, and why the rest are missing
        FIGURES["error"] = "%s: %s" % (type(error).__name__, error)
        raise
    finally:
        if os.environ.get("VIEWER_FIGURES"):
            with open(os.environ["VIEWER_FIGURES"], "w") as out:
                json.dump(FIGURES, out)


if __name__ == "__main__":
    main()
