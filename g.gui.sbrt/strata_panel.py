"""
MODULE:    g.gui.sbrt
PURPOSE:   The strata list: colour swatch, id and label of each class, a
           check box that shows or hides it, and the opacity of the one
           selected
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

import wx


class StrataPanel(wx.Panel):
    """Calls `on_change()` after the user hides, shows or fades a stratum;
    reads and writes `state.hidden` and `state.opacity`."""

    def __init__(self, parent, state, on_change):
        super().__init__(parent)
        self.state = state
        self._on_change = on_change
        self.list = wx.ListCtrl(self, style=wx.LC_REPORT | wx.LC_SINGLE_SEL)
        self.list.EnableCheckBoxes(True)
        self.list.InsertColumn(0, _("Class"), width=95)
        self.list.InsertColumn(1, _("Label"), width=140)
        self.list.InsertColumn(2, _("Opacity"), width=60)
        images = wx.ImageList(16, 12)
        for stratum in state.strata:
            images.Add(self._swatch(stratum.rgb))
        self.list.AssignImageList(images, wx.IMAGE_LIST_SMALL)
        for row, stratum in enumerate(state.strata):
            self.list.InsertItem(row, str(stratum.id), row)
            self.list.SetItem(row, 1, stratum.label)
            self.list.SetItem(row, 2, "100 %")
            self.list.CheckItem(row, True)
        self.opacity = wx.Slider(self, value=100, minValue=0, maxValue=100)
        self.opacity.SetToolTip(_("Opacity of the selected stratum (100: opaque)"))
        self.opacity.Disable()

        sizer = wx.BoxSizer(wx.VERTICAL)
        sizer.Add(self.list, proportion=1, flag=wx.EXPAND)
        row = wx.BoxSizer(wx.HORIZONTAL)
        row.Add(wx.StaticText(self, label=_("Opacity:")), flag=wx.ALIGN_CENTER_VERTICAL)
        row.Add(self.opacity, proportion=1, flag=wx.EXPAND)
        sizer.Add(row, flag=wx.EXPAND | wx.TOP, border=4)
        self.SetSizer(sizer)

        self.list.Bind(wx.EVT_LIST_ITEM_CHECKED, self._on_checked)
        self.list.Bind(wx.EVT_LIST_ITEM_UNCHECKED, self._on_checked)
        self.list.Bind(wx.EVT_LIST_ITEM_SELECTED, self._on_selected)
        self.opacity.Bind(wx.EVT_SCROLL_CHANGED, self._on_opacity)
        self.opacity.Bind(wx.EVT_SCROLL_THUMBRELEASE, self._on_opacity)

    @staticmethod
    def _swatch(rgb):
        bitmap = wx.Bitmap(16, 12)
        dc = wx.MemoryDC(bitmap)
        dc.SetBackground(wx.Brush(wx.Colour(*rgb)))
        dc.Clear()
        dc.SetPen(wx.Pen(wx.Colour(60, 60, 60)))
        dc.SetBrush(wx.TRANSPARENT_BRUSH)
        dc.DrawRectangle(0, 0, 16, 12)
        dc.SelectObject(wx.NullBitmap)
        return bitmap

    def _on_checked(self, event):
        stratum = self.state.strata[event.GetIndex()]
        if self.list.IsItemChecked(event.GetIndex()):
            self.state.hidden.discard(stratum.id)
        else:
            self.state.hidden.add(stratum.id)
        self._on_change()

    def _selected(self):
        row = self.list.GetFirstSelected()
        return None if row < 0 else row

    def _on_selected(self, event):
        stratum = self.state.strata[event.GetIndex()]
        alpha = self.state.opacity.get(stratum.id, 1.0)
        self.opacity.SetValue(int(round(alpha * 100)))
        self.opacity.Enable()

    def _on_opacity(self, event):
        row = self._selected()
        if row is None:
            return
        stratum = self.state.strata[row]
        value = self.opacity.GetValue()
        if value >= 100:
            self.state.opacity.pop(stratum.id, None)
        else:
            self.state.opacity[stratum.id] = value / 100.0
        self.list.SetItem(row, 2, "%d %%" % value)
        self._on_change()

    def checkbox_rect(self, row):
        """Screen rectangle of the check box of `row` (for tests' clicks)."""
        rect = self.list.GetItemRect(row)
        x, y = self.list.ClientToScreen(wx.Point(rect.x, rect.y))
        return (x, y, rect.height, rect.height)
