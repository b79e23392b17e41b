"""
MODULE:    g.gui.sbrt
PURPOSE:   Renders on a thread of its own, always the latest request: the
           window stays responsive and frames never queue up behind a drag
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

import threading

from view_client import ServerError


class RenderThread(threading.Thread):
    """Takes requests (r3.sbrt.render options and a tag), renders the
    latest one through `server` and hands each frame, or the error, to
    `deliver(tag, frame, error)` (which must pass it to the GUI thread)."""

    def __init__(self, server, deliver):
        super().__init__(daemon=True)
        self._server = server
        self._deliver = deliver
        self._wake = threading.Condition()
        self._pending = None
        self._pick = None
        self._stop = False

    def request(self, words, tag):
        """Replaces any request not yet started."""
        with self._wake:
            self._pending = (list(words), tag)
            self._wake.notify()

    def pick(self, words, row, col, answer):
        """Asks what pixel (row, col) of the view of `words` hits, before
        the next frame; `answer(pick, error)` gets it (on this thread)."""
        with self._wake:
            self._pick = (list(words), row, col, answer)
            self._wake.notify()

    def stop(self):
        with self._wake:
            self._stop = True
            self._wake.notify()
        self.join(timeout=5)
        self._server.close()

    def run(self):
        while True:
            with self._wake:
                while self._pending is None and self._pick is None and not self._stop:
                    self._wake.wait()
                if self._stop:
                    return
                pick, self._pick = self._pick, None
                if pick is None:
                    words, tag = self._pending
                    self._pending = None
            if pick is not None:
                words, row, col, answer = pick
                answer(*self._ask(self._server.pick, words, row, col))
            else:
                self._deliver(tag, *self._ask(self._server.render, words))

    @staticmethod
    def _ask(request, *args):
        """(the answer of request(*args), None), or (None, what went wrong):
        the thread goes on whatever broke."""
        try:
            return request(*args), None
        except ServerError as error:
            return None, str(error)
        except Exception as error:
            return None, "%s: %s" % (type(error).__name__, error)
