"""
MODULE:    testsuite/server_fixture.py (r3.sbrt addon)
PURPOSE:   r3.sbrt.render --serve driven over its pipes, as the tests of
           its request lines and of every render option use it: each
           reply read within a time limit, a server that exits an error
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import select
import shlex
import subprocess
import time


class RawServer:
    """r3.sbrt.render --serve over pipes, never restarted: a reply line per
    request, a frame's bytes read after its line; `limit` seconds for any
    one reply; its standard error to `stderr` (a file, or none)."""

    def __init__(self, limit, stderr=subprocess.DEVNULL):
        self.limit = limit
        self.process = subprocess.Popen(
            ["r3.sbrt.render", "--serve"], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, stderr=stderr)
        self.buffer = b""

    def _fill(self, enough, deadline):
        """Reads until enough(buffer) holds, or fails at the deadline."""
        while not enough(self.buffer):
            left = deadline - time.monotonic()
            if left <= 0:
                raise TimeoutError("no whole reply within %d s" % self.limit)
            ready, _, _ = select.select([self.process.stdout], [], [], left)
            if ready:
                chunk = os.read(self.process.stdout.fileno(), 1 << 20)
                if not chunk:
                    raise EOFError("the view server exited")
                self.buffer += chunk

    def _read_line(self, deadline):
        self._fill(lambda buffer: b"\n" in buffer, deadline)
        line, self.buffer = self.buffer.split(b"\n", 1)
        return line.decode(errors="replace")

    def _read_bytes(self, count, deadline):
        self._fill(lambda buffer: len(buffer) >= count, deadline)
        data, self.buffer = self.buffer[:count], self.buffer[count:]
        return data

    def _send(self, line):
        self.process.stdin.write(line)
        self.process.stdin.flush()
        return time.monotonic() + self.limit

    def ask(self, line):
        """The reply's first line to the raw bytes `line` (a frame's and the
        classes' further lines read too)."""
        deadline = self._send(line)
        head = self._read_line(deadline)
        if head.startswith("frame "):
            width, height = (int(v) for v in head.split()[1:3])
            self._read_bytes(width * height * 3, deadline)
        elif head.startswith("model "):
            count = int(self._read_line(deadline).split()[1])
            for _ in range(count):
                self._read_line(deadline)
        return head

    def render(self, words):
        """(width, height, RGB bytes) of the frame of the options `words`;
        an AssertionError with the reply for anything but a frame."""
        deadline = self._send(("render " + shlex.join(words) + "\n").encode())
        head = self._read_line(deadline)
        if not head.startswith("frame "):
            raise AssertionError("%s: %s" % (" ".join(words), head))
        width, height = (int(v) for v in head.split()[1:3])
        return width, height, self._read_bytes(width * height * 3, deadline)

    def close(self):
        try:
            self._send(b"quit\n")
            self.process.wait(self.limit)
        except (BrokenPipeError, subprocess.TimeoutExpired):
            self.process.kill()
            self.process.wait()
