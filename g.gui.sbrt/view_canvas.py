"""
MODULE:    g.gui.sbrt
PURPOSE:   The image of the view and the mouse on it: left drag orbits,
           middle (or shift + left) drag pans, the wheel zooms, ctrl + left
           drag moves the section; a legend of the strata shown (bottom right)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

import wx


class ViewCanvas(wx.Window):
    """Shows frames (scaled up while reduced) and reports the mouse to
    `owner`: on_press(mode) (a button down), on_drag(mode, dx, dy),
    on_zoom(steps), on_still() (the button released after a drag),
    on_click(x, y) (a left click that moved nothing), on_resize(); mode
    is "orbit", "pan" or "section"."""

    def __init__(self, parent, owner, size):
        super().__init__(parent, size=size, style=wx.BORDER_NONE | wx.WANTS_CHARS)
        self.SetMinSize(size)
        self.SetBackgroundStyle(wx.BG_STYLE_PAINT)
        self._owner = owner
        self._bitmap = None
        self._mode = None
        self._last = None
        self._moved = False
        self.legend = []  # (rgb, text) of the strata shown
        self.show_legend = True
        self.Bind(wx.EVT_PAINT, self._on_paint)
        self.Bind(wx.EVT_SIZE, self._on_size)
        self.Bind(wx.EVT_LEFT_DOWN, self._on_down)
        self.Bind(wx.EVT_MIDDLE_DOWN, self._on_down)
        self.Bind(wx.EVT_LEFT_UP, self._on_up)
        self.Bind(wx.EVT_MIDDLE_UP, self._on_up)
        self.Bind(wx.EVT_MOTION, self._on_motion)
        self.Bind(wx.EVT_MOUSEWHEEL, self._on_wheel)
        self.Bind(wx.EVT_MOUSE_CAPTURE_LOST, self._on_capture_lost)

    def show(self, frame):
        """Shows a frame (a view_client.Frame)."""
        self._bitmap = wx.Bitmap.FromBuffer(frame.width, frame.height, frame.rgb)
        self.Refresh(eraseBackground=False)
        self.Update()

    def dragging(self):
        return self._mode is not None

    def _on_paint(self, event):
        dc = wx.AutoBufferedPaintDC(self)
        dc.SetBackground(wx.WHITE_BRUSH)
        dc.Clear()
        if self._bitmap:
            width, height = self.GetClientSize()
            bitmap = self._bitmap
            if bitmap.GetSize() != (width, height):
                image = bitmap.ConvertToImage().Scale(
                    width, height, wx.IMAGE_QUALITY_NORMAL
                )
                bitmap = wx.Bitmap(image)
            dc.DrawBitmap(bitmap, 0, 0)
        if self.show_legend and self.legend:
            self._draw_legend(dc)

    def legend_rect(self):
        """The legend's rectangle in the canvas (x, y, width, height)."""
        if not (self.show_legend and self.legend):
            return None
        dc = wx.ClientDC(self)
        dc.SetFont(wx.Font(wx.FontInfo(9)))
        text = max(dc.GetTextExtent(t)[0] for _, t in self.legend)
        line = dc.GetTextExtent("Xg")[1] + 3
        # bottom right: a perspective view leaves that corner empty most
        width, height = text + 34, line * len(self.legend) + 8
        client_width, client_height = self.GetClientSize()
        return (client_width - width - 6, client_height - height - 6, width, height)

    def _draw_legend(self, dc):
        x, y, width, height = self.legend_rect()
        dc.SetFont(wx.Font(wx.FontInfo(9)))
        line = dc.GetTextExtent("Xg")[1] + 3
        dc.SetPen(wx.Pen(wx.Colour(120, 120, 120)))
        dc.SetBrush(wx.Brush(wx.Colour(255, 255, 255)))
        dc.DrawRectangle(x, y, width, height)
        for k, (rgb, text) in enumerate(self.legend):
            top = y + 4 + k * line
            dc.SetBrush(wx.Brush(wx.Colour(*rgb)))
            dc.DrawRectangle(x + 6, top + 1, 16, line - 4)
            dc.DrawText(text, x + 28, top)

    def _on_size(self, event):
        self._owner.on_resize()
        event.Skip()

    def _on_down(self, event):
        if event.MiddleDown() or event.ShiftDown():
            self._mode = "pan"
        elif event.ControlDown():
            self._mode = "section"
        else:
            self._mode = "orbit"
        self._last = event.GetPosition()
        self._moved = False
        if not self.HasCapture():
            self.CaptureMouse()
        self.SetFocus()
        self._owner.on_press(self._mode)

    def _on_motion(self, event):
        if self._mode is None or not event.Dragging():
            return
        position = event.GetPosition()
        dx, dy = position.x - self._last.x, position.y - self._last.y
        self._last = position
        if dx or dy:
            self._moved = True
            self._owner.on_drag(self._mode, dx, dy)

    def _on_up(self, event):
        if self.HasCapture():
            self.ReleaseMouse()
        if self._mode is not None:
            clicked = self._mode == "orbit" and not self._moved
            self._mode = None
            if clicked:
                position = event.GetPosition()
                self._owner.on_click(position.x, position.y)
            else:
                self._owner.on_still()

    def _on_capture_lost(self, event):
        self._mode = None

    def _on_wheel(self, event):
        steps = event.GetWheelRotation() / max(1, event.GetWheelDelta())
        self._owner.on_zoom(steps)
