"""
MODULE:    g.gui.sbrt
PURPOSE:   The client of the view server (r3.sbrt.render --serve): one
           process that keeps the SBRT loaded and answers each request
           line (r3.sbrt.render's own options) with a frame of RGB bytes
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

import collections
import shlex
import subprocess
import threading


class ServerError(Exception):
    """The server stopped (its last messages) or refused a request."""


# legend: a property view's PropertyLegend (None for a view of the classes)
Frame = collections.namedtuple(
    "Frame", "width height ms azimuth elevation distance target rgb words legend",
    defaults=(None,)
)
# the colour ramp's ends and the unit of a property view, as its legend
# shows them (0 to 100 % for a sum of probabilities)
PropertyLegend = collections.namedtuple("PropertyLegend", "low high unit")
Stratum = collections.namedtuple("Stratum", "id rgb label")
# a property channel: its name, unit, long name and range (as meant)
Channel = collections.namedtuple("Channel", "name unit long_name low high")
# what a pixel of a view hits: map coordinates, class id, shown property
Pick = collections.namedtuple("Pick", "x y z class_id value")
# zexag: the exaggeration r3.sbrt.render fits to the model (no zexag= given);
# voxels: every top on a voxel boundary (stairs that kernel normals smooth)
Extent = collections.namedtuple("Extent", "north south east west bottom top zexag voxels",
                                defaults=(1.0, False))


class ViewServer:
    """r3.sbrt.render --serve, started at the first request and again
    after it stopped on an error (the message is in the ServerError)."""

    def __init__(self, command=("r3.sbrt.render", "--serve")):
        self._command = list(command)
        self._process = None
        self._messages = collections.deque(maxlen=20)

    def start(self):
        """Starts the server's process now (else the first request does):
        it sets GRASS up while the caller does something else."""
        self._start()

    def _start(self):
        if self._process and self._process.poll() is None:
            return
        self._messages.clear()
        self._process = subprocess.Popen(
            self._command,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
        )
        self._reader = threading.Thread(
            target=self._read_messages, args=(self._process.stderr,), daemon=True
        )
        self._reader.start()

    def _read_messages(self, stream):
        for line in stream:
            text = line.decode(errors="replace").strip()
            if text:
                self._messages.append(text)

    def _stopped(self):
        self._process.wait()
        self._reader.join(timeout=5)  # it ends at the end of the messages
        messages = [m for m in self._messages if "ERROR" in m] or list(self._messages)
        self._process = None
        return ServerError(
            messages[-1] if messages else "the view server stopped unexpectedly"
        )

    def _ask(self, verb, words):
        if any("\n" in w or "\r" in w for w in words):
            raise ServerError("an option value holds a line break: %r" % words)
        self._start()
        line = " ".join([verb] + [shlex.quote(w) for w in words]) + "\n"
        try:
            self._process.stdin.write(line.encode())
            self._process.stdin.flush()
        except BrokenPipeError:
            raise self._stopped() from None
        return self._line()

    def _line(self):
        line = self._process.stdout.readline()
        if not line:
            raise self._stopped()
        head = line.decode(errors="replace").rstrip("\n")
        if head.startswith("error "):
            raise ServerError(head[len("error ") :])
        return head.split()

    def _lines(self, count):
        """The next `count` lines of a reply, as text."""
        lines = []
        for _number in range(count):
            line = self._process.stdout.readline()
            if not line:
                raise self._stopped()
            lines.append(line.decode(errors="replace").rstrip("\n"))
        return lines

    def _read(self, count):
        data = self._process.stdout.read(count)
        if len(data) != count:
            raise self._stopped()
        return data

    def render(self, words):
        """The frame of r3.sbrt.render's options `words` (a list)."""
        head = self._ask("render", words)
        width, height = int(head[1]), int(head[2])
        values = [float(v) for v in head[3:10]]
        legend = None
        if len(head) >= 13 and head[10] == "property":  # the unit last, maybe with spaces
            legend = PropertyLegend(float(head[11]), float(head[12]), " ".join(head[13:]))
        return Frame(
            width,
            height,
            values[0],
            values[1],
            values[2],
            values[3],
            tuple(values[4:7]),
            self._read(width * height * 3),
            list(words),
            legend,
        )

    def strata(self, sbrt):
        """The extent and strata (id, colour, label) of SBRT `sbrt`."""
        extent, strata, _channels = self.model(sbrt)
        return extent, strata

    def model(self, sbrt, memory=""):
        """The extent, strata (id, colour, label) and property channels of
        SBRT `sbrt`, read within `memory` MB (the server's default where
        empty; the frames' requests give the same, so that it is read
        once)."""
        head = self._ask("classes", ["input=" + sbrt] + (["memory=" + memory] if memory else []))
        extent = Extent(*[float(v) for v in head[1:8]], voxels=head[8:9] == ["1"])
        strata = []
        for text in self._lines(int(self._line()[1])):
            fields = text.split(" ", 4)
            label = fields[4] if len(fields) > 4 else ""
            strata.append(
                Stratum(int(fields[0]), tuple(int(v) for v in fields[1:4]), label)
            )
        channels = []
        for line in self._lines(int(self._line()[1])):
            low, high, text = line.split(" ", 2)
            name, unit, long_name = (text.split("|", 2) + ["", ""])[:3]
            channels.append(Channel(name, unit, long_name, float(low), float(high)))
        return extent, strata, channels

    def pick(self, words, row, col):
        """What pixel (row, col) of the view of options `words` hits: a
        Pick, or None where it hits nothing."""
        head = self._ask("pick", [str(row), str(col)] + list(words))
        if head[1] == "none":
            return None
        x, y, z = (float(v) for v in head[1:4])
        return Pick(x, y, z, int(head[4]), float(head[5]))

    def close(self):
        if self._process and self._process.poll() is None:
            try:
                self._process.stdin.write(b"quit\n")
                self._process.stdin.close()
            except BrokenPipeError:
                pass
            try:
                self._process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self._process.kill()
                self._process.wait()
        self._process = None
