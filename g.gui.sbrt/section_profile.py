"""
MODULE:    g.gui.sbrt (r3.sbrt addon)
PURPOSE:   The viewer's cross section as a geological profile: the figure
           r3.sbrt.profile draws along the section's line, in a window
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import shutil
import tempfile

import wx


class SectionProfileFrame(wx.Frame):
    """A window showing a profile figure (PNG) at its own size, scrolled
    where the screen is smaller; the file is removed with its folder when
    the window closes."""

    def __init__(self, parent, png, title):
        super().__init__(parent, title=title)
        self.folder = os.path.dirname(png)
        scrolled = wx.ScrolledWindow(self)
        bitmap = wx.Bitmap(png, wx.BITMAP_TYPE_PNG)
        wx.StaticBitmap(scrolled, bitmap=bitmap)
        scrolled.SetVirtualSize(bitmap.GetSize())
        scrolled.SetScrollRate(10, 10)
        screen = wx.GetDisplaySize()
        self.SetClientSize((min(bitmap.GetWidth(), screen.width - 80),
                            min(bitmap.GetHeight(), screen.height - 120)))
        self.Bind(wx.EVT_CLOSE, self._on_close)

    def _on_close(self, event):
        shutil.rmtree(self.folder, ignore_errors=True)
        event.Skip()


def profile_png_path():
    """A new PNG path in a folder of its own (removed with the window)."""
    return os.path.join(tempfile.mkdtemp(prefix="g_gui_sbrt_profile_"), "profile.png")
