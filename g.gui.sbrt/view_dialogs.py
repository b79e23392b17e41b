"""
MODULE:    g.gui.sbrt
PURPOSE:   The dialogs of "Save view" (raster maps and PNG) and "Record
           orbit" (frames and video)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

import os

import wx


class _FormDialog(wx.Dialog):
    """Labelled fields in a grid, OK (the default: Enter) and Cancel."""

    def __init__(self, parent, title):
        super().__init__(parent, title=title)
        self._grid = wx.FlexGridSizer(cols=2, vgap=6, hgap=8)
        self._grid.AddGrowableCol(1)

    def _field(self, label, control):
        self._grid.Add(wx.StaticText(self, label=label), flag=wx.ALIGN_CENTER_VERTICAL)
        self._grid.Add(control, flag=wx.EXPAND)
        return control

    def _finish(self):
        """The overwrite check box last, then the buttons."""
        self.overwrite = self._field(
            "", wx.CheckBox(self, label=_("Allow output files to overwrite existing files"))
        )
        sizer = wx.BoxSizer(wx.VERTICAL)
        sizer.Add(self._grid, flag=wx.EXPAND | wx.ALL, border=10)
        buttons = self.CreateStdDialogButtonSizer(wx.OK | wx.CANCEL)
        sizer.Add(buttons, flag=wx.EXPAND | wx.ALL, border=8)
        self.SetSizerAndFit(sizer)
        self.SetSize((max(self.GetSize()[0], 460), -1))
        self.FindWindowById(wx.ID_OK).SetDefault()


class SaveViewDialog(_FormDialog):
    """Names of the raster maps and of the PNG of "Save view"."""

    def __init__(self, parent, name):
        super().__init__(parent, _("Save view"))
        self.output = self._field(
            _("Raster maps (<name>, <name>.red, .green, .blue):"),
            wx.TextCtrl(self, value=name),
        )
        self.png = self._field(
            _("PNG file:"),
            wx.TextCtrl(self, value=os.path.join(os.getcwd(), name + ".png")),
        )
        self._finish()
        # typing names the maps at once, and the PNG after them until the
        # PNG is named otherwise
        self.output.SetFocus()
        self.output.SelectAll()
        self._png_follows = True
        self.output.Bind(wx.EVT_TEXT, self._on_output)
        self.png.Bind(wx.EVT_KEY_DOWN, self._on_png_key)

    def _on_output(self, event):
        if self._png_follows:
            folder = os.path.dirname(self.png.GetValue()) or os.getcwd()
            self.png.ChangeValue(os.path.join(folder, self.output.GetValue().strip() + ".png"))

    def _on_png_key(self, event):
        self._png_follows = False
        event.Skip()


class RecordOrbitDialog(_FormDialog):
    """Frames and files of "Record orbit" (r3.sbrt.render frames= path=orbit)."""

    def __init__(self, parent, name):
        super().__init__(parent, _("Record orbit"))
        self.frames = self._field(
            _("Frames (a full turn):"), wx.SpinCtrl(self, min=2, max=3600, initial=36)
        )
        self.png = self._field(
            _("PNG of each frame (%04d: its number):"),
            wx.TextCtrl(self, value=os.path.join(os.getcwd(), name + "_orbit_%04d.png")),
        )
        self.video = self._field(
            _("Video (.mp4, .webm or .gif; empty: none):"),
            wx.TextCtrl(self, value=os.path.join(os.getcwd(), name + "_orbit.mp4")),
        )
        self._finish()
        # typing sets the number of frames at once
        self.frames.SetFocus()
        self.frames.SetSelection(-1, -1)
