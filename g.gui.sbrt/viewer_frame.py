"""
MODULE:    g.gui.sbrt
PURPOSE:   The viewer's window: the view, the strata list and the controls
           of exaggeration, section, boreholes and drape; "Save view" and
           "Record orbit" run the equivalent r3.sbrt.render command
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

import json
import shlex
import subprocess
import threading
import time

import grass.script as gs
import wx
from grass.exceptions import CalledModuleError

from gui_core.gselect import ColumnSelect, Select

from column_profile import ProfileError, read_column, show_profile
from render_thread import RenderThread
from section_profile import SectionProfileFrame, profile_png_path
from view_client import PropertyLegend, ServerError
from strata_panel import StrataPanel
from view_canvas import ViewCanvas
from view_dialogs import RecordOrbitDialog, SaveViewDialog
from view_state import ViewState, ZexagScale, number

REDUCTION = 2  # while the camera moves: 1/REDUCTION of the size each way
REFINE_MS = 40  # the full frame (face normals) once the mouse rests this long
# the same while a button is held: a hand dragging leaves gaps of 40-100 ms
# between mouse moves, and a full exact frame of a national model (0.3-0.4
# s on 2 cores) asked for in each gap stalled the drag at 2-5 frames a
# second; so twice the last full frame's time, at most this (a small
# model's frame of 50 ms is asked for after 100 ms)
REFINE_HELD_MS = 250
# the smooth frame (kernel normals) once nothing has changed this long and
# no mouse button is held: longer than the pauses within a gesture (wheel
# steps, slider moves, a hand resting on a drag: tens of ms to a couple
# hundred), so that the kernel frame, which keeps the server busy for
# seconds on the CPU (it cannot be interrupted), is asked for only once
# the user has let go, never mid-gesture; short enough to feel immediate
SMOOTH_MS = 300


class EventLog:
    """JSON lines of what the viewer did (frames, drags, saves), for
    benchmarks and tests; nothing without a path."""

    def __init__(self, path):
        self._file = open(path, "a", buffering=1) if path else None

    def write(self, event, **fields):
        if self._file:
            fields.update(event=event, t=time.monotonic())
            self._file.write(json.dumps(fields) + "\n")


class ViewerFrame(wx.Frame):
    def __init__(self, server, sbrt, size, boreholes="", texture="", backend="auto",
                 log_path=None, property="", memory=""):
        super().__init__(None, title="g.gui.sbrt: " + sbrt)
        self.log = EventLog(log_path)
        extent, strata, self.channels = server.model(sbrt, memory)
        self.state = ViewState(sbrt, extent, strata)
        self.state.memory = memory
        self.state.boreholes, self.state.texture = boreholes, texture
        self.state.drape = bool(texture)
        self.state.backend = backend
        self._sent = 0
        self._smooth_ms = 0.0  # the last smooth frame's server time
        self._full_ms = REFINE_HELD_MS  # the last full frame's server time
        self._shown = 0
        self._times = []
        self._logged_widgets = False
        self._closing = False
        # the legend the server sent with the last property frame:
        # (property, view_client.PropertyLegend)
        self._frame_legend = None

        self._make_toolbar()
        body = wx.BoxSizer(wx.HORIZONTAL)
        self.canvas = ViewCanvas(self, self, size)
        body.Add(self.canvas, proportion=1, flag=wx.EXPAND)
        self.side = wx.ScrolledWindow(self, style=wx.VSCROLL)
        self.side.SetScrollRate(0, 10)
        self._make_controls(self.side)
        # as high as the view; the controls scroll
        self.side.SetMinSize((self.side.GetSizer().CalcMin()[0] + 20, size[1]))
        body.Add(self.side, flag=wx.EXPAND)
        sizer = wx.BoxSizer(wx.VERTICAL)
        sizer.Add(body, proportion=1, flag=wx.EXPAND)
        self.command = wx.TextCtrl(self, style=wx.TE_READONLY)
        self.command.SetToolTip(_("The r3.sbrt.render command of this view"))
        sizer.Add(self.command, flag=wx.EXPAND | wx.ALL, border=2)
        self.SetSizerAndFit(sizer)
        self.CreateStatusBar(2)
        self.SetStatusWidths([-1, 260])
        if property:
            self._start_with_property(property)  # before any frame is asked for

        self.refine = wx.Timer(self)
        self.Bind(wx.EVT_TIMER, lambda event: self.request_frame(True), self.refine)
        self.rest = wx.Timer(self)  # SMOOTH_MS without a change: the smooth frame
        self.Bind(wx.EVT_TIMER, self._on_rest, self.rest)
        self.Bind(wx.EVT_CLOSE, self._on_close)
        self.thread = RenderThread(
            server, lambda tag, frame, error: wx.CallAfter(self._on_frame, tag, frame, error)
        )
        self.thread.start()
        self._update_legend()
        self._first_frames()

    def _first_frames(self):
        """A reduced frame first, from the SBRT's coarse level of detail
        where it has one (a national model shows in a fraction of a second,
        not after the decode of every block), then the exact one: asked
        for once the reduced one has started (the thread keeps only the
        latest request not yet started)."""
        self.request_frame(False)
        self.refine.StartOnce(REFINE_MS)

    def _start_with_property(self, expression):
        """property= of the command line: coloured by it from the first
        frame; refused where the model has no such channels."""
        if not self.channels or not self.property_range(expression):
            names = ", ".join(c.name for c in self.channels) or _("none")
            raise ServerError(_("property=%s: not a channel of <%s> nor a sum of its "
                                "channels (channels: %s)") % (expression, self.state.sbrt,
                                                               names))
        self.property.ChangeValue(expression)
        self.state.property = expression
        self._fit_threshold(self.property_range(expression))

    # the layout ---------------------------------------------------------
    def _make_toolbar(self):
        toolbar = self.CreateToolBar(wx.TB_HORIZONTAL | wx.TB_TEXT)
        art = wx.ArtProvider.GetBitmap
        tools = [
            (_("Save view"), wx.ART_FILE_SAVE,
             _("Write the raster maps and the PNG of this view"), self.on_save),
            (_("Record orbit"), wx.ART_EXECUTABLE_FILE,
             _("Render a turn about the target into PNGs and a video"), self.on_record),
            (_("Section profile"), wx.ART_REPORT_VIEW,
             _("Draw the cross section as a geological profile with axes, legend and "
               "location map (r3.sbrt.profile)"), self.on_section_profile),
            (_("Reset view"), wx.ART_GO_HOME, _("Frame the whole model again"),
             self.on_reset),
        ]
        for label, icon, help_text, handler in tools:
            tool = toolbar.AddTool(wx.ID_ANY, label, art(icon, wx.ART_TOOLBAR), help_text)
            self.Bind(wx.EVT_TOOL, handler, tool)
        toolbar.Realize()

    def _box(self, parent, sizer, title):
        box = wx.StaticBoxSizer(wx.VERTICAL, parent, title)
        sizer.Add(box, flag=wx.EXPAND | wx.ALL, border=4)
        return box

    def _make_controls(self, parent):
        sizer = wx.BoxSizer(wx.VERTICAL)
        view = self._box(parent, sizer, _("View"))
        self.zexag_label = wx.StaticText(parent)
        view.Add(self.zexag_label)
        # logarithmic, 1 to ten times the fitted exaggeration (at least 20)
        self.zexag_scale = ZexagScale(max(20.0, 10 * self.state.zexag))
        self.zexag = wx.Slider(parent, value=self.zexag_scale.position(self.state.zexag),
                               minValue=0, maxValue=ZexagScale.STEPS)
        view.Add(self.zexag, flag=wx.EXPAND)
        self._show_zexag()
        self.smooth = wx.CheckBox(parent, label=_("Smooth shading (kernel normals)"))
        self.smooth.SetValue(self.state.smooth_shading)
        self.smooth.SetToolTip(_("Light voxel stairs as the slopes they make (on by "
                                 "default for voxel models; frames use face normals "
                                 "until the view rests, then the smooth one follows)"))
        view.Add(self.smooth)
        self.legend = wx.CheckBox(parent, label=_("Legend"))
        self.legend.SetValue(True)
        view.Add(self.legend)

        if self.channels:  # survey models: what they carry beside the classes
            self._make_property_controls(parent, sizer)

        strata = self._box(parent, sizer, _("Strata"))
        self.strata = StrataPanel(parent, self.state, self.on_scene)
        self.strata.SetMinSize((300, min(360, 60 + 22 * len(self.state.strata))))
        strata.Add(self.strata, proportion=1, flag=wx.EXPAND)

        section = self._box(parent, sizer, _("Cross section"))
        self.section_on = wx.CheckBox(parent, label=_("Cut the model (ctrl + drag moves it)"))
        section.Add(self.section_on)
        section.Add(wx.StaticText(parent, label=_("Direction (degrees from east):")))
        self.section_direction = wx.Slider(parent, value=0, minValue=0, maxValue=179,
                                           style=wx.SL_HORIZONTAL | wx.SL_VALUE_LABEL)
        section.Add(self.section_direction, flag=wx.EXPAND)
        section.Add(wx.StaticText(parent, label=_("Position across the model (%):")))
        self.section_offset = wx.Slider(parent, value=0, minValue=-98, maxValue=98,
                                        style=wx.SL_HORIZONTAL | wx.SL_VALUE_LABEL)
        section.Add(self.section_offset, flag=wx.EXPAND)

        wells = self._box(parent, sizer, _("Boreholes"))
        self.boreholes = Select(parent, type="vector", size=(280, -1))
        self.boreholes.SetValue(self.state.boreholes)
        wells.Add(self.boreholes, flag=wx.EXPAND)
        columns = wx.FlexGridSizer(cols=2, vgap=2, hgap=4)
        self.log_columns = []
        for label in (_("Log top:"), _("Log bottom:"), _("Log class:")):
            columns.Add(wx.StaticText(parent, label=label), flag=wx.ALIGN_CENTER_VERTICAL)
            column = ColumnSelect(parent, size=(180, -1))
            columns.Add(column)
            self.log_columns.append(column)
        wells.Add(columns)
        self.log_depths = wx.CheckBox(parent, label=_("Logs in depths below the surface"))
        wells.Add(self.log_depths)
        radius = wx.BoxSizer(wx.HORIZONTAL)
        radius.Add(wx.StaticText(parent, label=_("Radius (map units, 0: 0.4 cell):")),
                   flag=wx.ALIGN_CENTER_VERTICAL)
        self.borehole_radius = wx.SpinCtrlDouble(parent, min=0, max=1e6, initial=0, inc=5)
        radius.Add(self.borehole_radius)
        wells.Add(radius)

        drape = self._box(parent, sizer, _("Drape"))
        self.texture = Select(parent, type="raster", size=(280, -1))
        self.texture.SetValue(self.state.texture)
        drape.Add(self.texture, flag=wx.EXPAND)
        self.drape = wx.CheckBox(parent, label=_("Drape the map on the terrain"))
        self.drape.SetValue(self.state.drape)
        drape.Add(self.drape)
        parent.SetSizer(sizer)
        parent.SetMinSize((320, -1))

        self.zexag.Bind(wx.EVT_SLIDER, self._on_zexag)
        self.smooth.Bind(wx.EVT_CHECKBOX, self._on_smooth)
        self.legend.Bind(wx.EVT_CHECKBOX, self._on_legend)
        self.section_on.Bind(wx.EVT_CHECKBOX, self._on_section)
        self.section_direction.Bind(wx.EVT_SLIDER, self._on_section)
        self.section_offset.Bind(wx.EVT_SLIDER, self._on_section)
        self.boreholes.Bind(wx.EVT_TEXT, self._on_boreholes)
        for column in self.log_columns:
            column.Bind(wx.EVT_TEXT, self._on_boreholes)
        self.log_depths.Bind(wx.EVT_CHECKBOX, self._on_boreholes)
        self.borehole_radius.Bind(wx.EVT_SPINCTRLDOUBLE, self._on_boreholes)
        self.texture.Bind(wx.EVT_TEXT, self._on_drape)
        self.drape.Bind(wx.EVT_CHECKBOX, self._on_drape)
        if self.state.boreholes:
            self._fill_columns()

    def _make_property_controls(self, parent, sizer):
        """Colour by a property channel (or a sum, typed a+b), keep only the
        voxels where it reaches a threshold (live), fade the colours by an
        uncertainty channel; a click shows the column's profile."""
        box = self._box(parent, sizer, _("Properties"))
        names = [c.name for c in self.channels]
        box.Add(wx.StaticText(parent, label=_("Property (a channel, or a sum a+b):")))
        self.property = wx.ComboBox(parent, choices=[""] + names, size=(280, -1))
        box.Add(self.property, flag=wx.EXPAND)
        self.color_by = wx.CheckBox(parent, label=_("Colour by the property"))
        self.color_by.SetValue(True)
        box.Add(self.color_by)
        self.select_on = wx.CheckBox(parent, label=_("Only the voxels where it is at least:"))
        box.Add(self.select_on)
        self.threshold = wx.Slider(parent, value=50, minValue=0, maxValue=100,
                                   style=wx.SL_HORIZONTAL | wx.SL_VALUE_LABEL)
        box.Add(self.threshold, flag=wx.EXPAND)
        box.Add(wx.StaticText(parent, label=_("Fade the colours by uncertainty:")))
        self.fade = wx.Choice(parent, choices=[_("(none)")] + names)
        self.fade.SetSelection(0)
        box.Add(self.fade, flag=wx.EXPAND)
        box.Add(wx.StaticText(parent, label=_("Click the model: the column's profile")))
        self.property.Bind(wx.EVT_TEXT, self._on_property)
        self.color_by.Bind(wx.EVT_CHECKBOX, self._on_property)
        self.select_on.Bind(wx.EVT_CHECKBOX, self._on_property)
        self.threshold.Bind(wx.EVT_SLIDER, self._on_property)
        self.fade.Bind(wx.EVT_CHOICE, self._on_property)

    def property_range(self, expression):
        """The range of a property: 0..100 where all its channels are in %
        (probabilities: those of a voxel sum to 100 at most), else the sum
        of its channels' ranges (a bound; the legend takes the range the
        server sends with a frame); None for an unknown channel."""
        by_name = {c.name: c for c in self.channels}
        parts = [p.strip() for p in expression.split("+")]
        if not all(p in by_name for p in parts):
            return None
        if all(by_name[p].unit == "%" for p in parts):
            return 0.0, 100.0
        low = sum(by_name[p].low for p in parts)
        high = sum(by_name[p].high for p in parts)
        return low, max(high, low)

    def property_legend(self, expression):
        """The ends and unit of the legend of a property: those the server
        sent with its last frame (the ramp it drew with), else what the
        channels say; None for an unknown channel."""
        if self._frame_legend and self._frame_legend[0] == expression:
            return self._frame_legend[1]
        limits = self.property_range(expression)
        if not limits:
            return None
        first = expression.split("+")[0].strip()
        unit = next(c.unit for c in self.channels if c.name == first)
        return PropertyLegend(limits[0], limits[1], unit)

    def _fit_threshold(self, limits):
        """The threshold slider over a property's range (whole numbers)."""
        self.threshold.SetRange(int(limits[0]), max(int(limits[0]) + 1, int(round(limits[1]))))

    def _on_property(self, event):
        expression = self.property.GetValue().strip()
        limits = self.property_range(expression) if expression else None
        self.state.property = expression if limits else ""
        self.state.color_by_property = self.color_by.GetValue()
        if limits and event.GetEventObject() is self.property:
            self._fit_threshold(limits)
        self.state.threshold = (float(self.threshold.GetValue())
                                if limits and self.select_on.GetValue() else None)
        choice = self.fade.GetSelection()
        self.state.fade = self.channels[choice - 1].name if choice > 0 else ""
        self.log.write("property", property=self.state.property,
                       threshold=self.state.threshold, fade=self.state.fade)
        self._update_legend()
        if isinstance(event.GetEventObject(), wx.Slider):
            self._moving()
        else:
            self.request_frame(True)

    def on_click(self, x, y):
        """A click on the view: what lies under that pixel, then the
        profile of its column (r3.sbrt.what on a thread)."""
        self.on_still()
        width, height = self.canvas.GetClientSize()
        words = self.state.words(width, height)
        self.SetStatusText(_("Looking under the pointer..."), 0)
        self.thread.pick(words, y, x, lambda pick, error: wx.CallAfter(
            self._on_pick, pick, error))

    def _on_pick(self, pick, error):
        if self._closing:
            return
        if error or pick is None:
            self.log.write("pick", hit=False, error=error)
            self.SetStatusText(error or _("Nothing under the pointer"), 0)
            return
        self.log.write("pick", hit=True, x=pick.x, y=pick.y, z=pick.z,
                       class_id=pick.class_id)
        self.SetStatusText(_("Column at %.2f, %.2f (class %d at %.2f)")
                           % (pick.x, pick.y, pick.class_id, pick.z), 0)

        def work():
            try:
                column, failure = read_column(self.state.sbrt, pick.x, pick.y), None
            except ProfileError as error:
                column, failure = None, str(error)
            wx.CallAfter(self._show_profile, column, failure)

        threading.Thread(target=work, daemon=True).start()

    def _show_profile(self, column, failure):
        if self._closing:
            return
        if failure:
            wx.MessageBox(failure, _("Column profile failed"), wx.OK | wx.ICON_ERROR, self)
            return
        self.profile = show_profile(self, column, self.state.strata, self.channels,
                                    self.state.sbrt)
        self.log.write("profile", x=column["x"], y=column["y"],
                       voxels=len(column.get("voxels", [])))

    # requests -----------------------------------------------------------
    def request_frame(self, full, smooth=False):
        """Asks for a frame: reduced (not `full`), full size with face
        normals, or (`smooth`) full size as r3.sbrt.render draws it, kernel
        normals where smooth shading is on. Every request but a smooth one
        is a change: it restarts the wait for the smooth frame."""
        width, height = self.canvas.GetClientSize()
        if width < 2 or height < 2:
            return
        if not full:
            width, height = max(1, width // REDUCTION), max(1, height // REDUCTION)
        self._sent += 1
        kind = "smooth" if smooth else "full" if full else "reduced"
        words = self.state.words(width, height, moving=not smooth, reduced=not full)
        self.thread.request(words, (self._sent, kind))
        self.log.write("request", number=self._sent, kind=kind, held=self._held())
        self.command.SetValue(self.state.command(*self.canvas.GetClientSize()))
        if not smooth:
            self._wait_for_rest()

    def _held(self):
        """Whether a mouse button is held: a drag on the view or a slider's
        thumb (a gesture going on)."""
        mouse = wx.GetMouseState()
        return self.canvas.dragging() or mouse.LeftIsDown() or mouse.MiddleIsDown()

    def _rest_ms(self):
        """How long the view must rest before the smooth frame: SMOOTH_MS, or
        as long as the last smooth frame took where that is longer (the
        server cannot be interrupted: a national model's smooth frame keeps
        it busy about 2 s, and a drag begun meanwhile waited for it, so a
        frame is risked only after a rest as long as it blocks)."""
        return max(SMOOTH_MS, int(self._smooth_ms))

    def _refine_held_ms(self):
        """How long the view must rest, a button held, before the full
        frame: twice what the last one took, REFINE_MS to REFINE_HELD_MS."""
        return int(min(REFINE_HELD_MS, max(REFINE_MS, 2 * self._full_ms)))

    def _wait_for_rest(self):
        """The smooth frame _rest_ms() from now, where smooth shading is on
        (a pending one is cancelled: something changed)."""
        self.rest.Stop()
        if self.state.smooth_shading and not self.canvas.dragging():
            self.rest.StartOnce(self._rest_ms())

    def _on_rest(self, event):
        if not self.state.smooth_shading or self._closing:
            return
        if self._held():  # a slider's thumb held still: wait for its release
            self.rest.StartOnce(self._rest_ms())
            return
        self.request_frame(True, smooth=True)

    def _moving(self):
        """A change while the user moves something: a reduced frame now,
        the full one when the moving stops."""
        self.request_frame(False)
        self.refine.StartOnce(self._refine_held_ms() if self._held() else REFINE_MS)

    def on_drag(self, mode, dx, dy):
        self.log.write("drag", mode=mode, dx=dx, dy=dy)
        if mode == "orbit":
            self.state.orbit(dx, dy)
        elif mode == "pan":
            self.state.pan(dx, dy, self.canvas.GetClientSize()[1])
        elif mode == "section":
            if self.state.section is None:
                return
            self.state.move_section(2.0 * dx / self.canvas.GetClientSize()[0])
            self.section_offset.SetValue(int(round(self.state.section[1] * 100)))
        self._moving()

    def on_zoom(self, steps):
        self.state.zoom(steps)
        self._moving()

    def on_press(self, mode):
        """A button down on the view: a gesture begins; no smooth frame
        until it ends (on_still, on_click)."""
        self.log.write("press", mode=mode)
        self.rest.Stop()

    def on_still(self):
        """The button released: the exact frame (face normals) at once, the
        smooth one after SMOOTH_MS without a change."""
        self.log.write("still")
        self.refine.Stop()
        self.request_frame(True)

    def on_resize(self):
        if hasattr(self, "thread"):
            self.refine.StartOnce(REFINE_MS)

    def on_scene(self):
        """A stratum hidden, shown or faded: a reduced frame at once (from
        the coarse level: a national model shows the change in a fraction
        of the exact frame's time), the exact one right after."""
        self._update_legend()
        self._moving()

    def _on_frame(self, tag, frame, error):
        if self._closing:
            return
        if error:
            self.SetStatusText(error, 0)
            self.log.write("error", message=error)
            return
        number, kind = tag
        full, smooth = kind != "reduced", kind == "smooth"
        if smooth:  # stale or not, what the next one will cost
            self._smooth_ms = frame.ms
        elif full:
            self._full_ms = frame.ms
        if number < self._shown:
            return
        if smooth and number < self._sent:  # the view changed since: a stale frame
            self.log.write("stale", number=number, ms=frame.ms)
            return
        self._shown = number
        framed = not any(w.startswith("distance=") for w in frame.words)
        # the camera of a full frame: a reduced one's aspect may differ
        # by a rounded pixel
        if self.state.distance is None and framed and full:
            self.state.adopt_camera(frame)
        self.canvas.show(frame)
        self._adopt_legend(frame)
        now = time.monotonic()
        self._times = [t for t in self._times if now - t < 1.0] + [now]
        if not full:
            note = _(" (reduced; the exact frame follows)")
        elif smooth:
            note = _(", smooth shading") if self.state.smooth_shading else ""
        else:
            note = _(", face normals") if self.state.smooth_shading else ""
        self.SetStatusText(_("%d x %d in %.0f ms%s") % (frame.width, frame.height,
                                                        frame.ms, note), 0)
        self.SetStatusText(_("%d frames/s") % len(self._times), 1)
        self.log.write("frame", number=number, full=full, smooth=smooth,
                       width=frame.width, height=frame.height, ms=frame.ms, words=frame.words,
                       legend=list(frame.legend) if frame.legend else None)
        if full and not self._logged_widgets:
            self._logged_widgets = True
            self._log_widgets()

    def _adopt_legend(self, frame):
        """The legend of a property frame as the server drew it (its ramp's
        ends and unit: a sum of probabilities 0 to 100 %, another sum the
        range of its values)."""
        if not frame.legend:
            return
        words = [w for w in frame.words if w.startswith("property=")]
        if not words:
            return
        legend = (words[-1][len("property="):], frame.legend)
        if legend != self._frame_legend:
            self._frame_legend = legend
            self._update_legend()

    def _log_widgets(self):
        def rect(window):
            x, y = window.GetScreenPosition()
            width, height = window.GetSize()
            return [x, y, width, height]

        self.log.write("widget", name="canvas", rect=rect(self.canvas))
        self.log.write("widget", name="legend", rect=rect(self.legend))
        self.log.write("widget", name="zexag", rect=rect(self.zexag))
        self.log.write("widget", name="smooth", rect=rect(self.smooth))
        self.log.write("widget", name="section", rect=rect(self.section_on))
        self.log.write("widget", name="strata", rect=rect(self.strata.list))
        self.log.write("widget", name="controls", rect=rect(self.side))
        for row, stratum in enumerate(self.state.strata):
            self.log.write("widget", name="stratum %d" % stratum.id,
                           rect=list(self.strata.checkbox_rect(row)))
        if self.channels:
            for name in ("property", "color_by", "select_on", "threshold", "fade"):
                self.log.write("widget", name=name, rect=rect(getattr(self, name)))
        toolbar = self.GetToolBar()  # the last widget logged
        self.log.write("widget", name="toolbar", rect=rect(toolbar))

    # controls -----------------------------------------------------------
    def _update_legend(self):
        legend = (self.property_legend(self.state.property)
                  if self.state.property and self.state.color_by_property else None)
        if legend:
            # the property's colour bar: r3.sbrt.render's default ramp
            # (viridis) over the property's range, highest first
            from matplotlib import colormaps

            ramp = colormaps["viridis"]
            self.canvas.legend = [
                (tuple(int(round(255 * c)) for c in ramp(share)[:3]),
                 ("%s %g %s" % (self.state.property if share == 1.0 else "",
                                legend.low + share * (legend.high - legend.low),
                                legend.unit)).strip())
                for share in (1.0, 0.75, 0.5, 0.25, 0.0)]
            self.canvas.Refresh(eraseBackground=False)
            return
        self.canvas.legend = [
            (s.rgb, ("%d %s" % (s.id, s.label)).strip())
            for s in self.state.strata
            if s.id not in self.state.hidden
        ]
        self.canvas.Refresh(eraseBackground=False)

    def _on_legend(self, event):
        self.canvas.show_legend = self.legend.GetValue()
        self.canvas.Refresh(eraseBackground=False)

    def _on_zexag(self, event):
        self.state.zexag = self.zexag_scale.value(self.zexag.GetValue())
        # the model grows about its bottom: framed again, from the same side
        self.state.distance = self.state.target = None
        self._show_zexag()
        self._moving()

    def _on_smooth(self, event):
        self.state.smooth_shading = self.smooth.GetValue()
        if self.state.smooth_shading:  # the face frame is on the screen
            self.command.SetValue(self.state.command(*self.canvas.GetClientSize()))
            self._wait_for_rest()
        else:
            self.request_frame(True)

    def _show_zexag(self):
        self.zexag_label.SetLabel(_("Vertical exaggeration: %s") % number(self.state.zexag))

    def _on_section(self, event):
        if self.section_on.GetValue():
            self.state.section = (float(self.section_direction.GetValue()),
                                  self.section_offset.GetValue() / 100.0)
        else:
            self.state.section = None
        if isinstance(event.GetEventObject(), wx.Slider):
            self._moving()
        else:
            self.request_frame(True)

    def _fill_columns(self):
        for column in self.log_columns:
            column.InsertColumns(vector=self.state.boreholes, layer=1)

    @staticmethod
    def _existing(name, element):
        """`name` where such a map exists, else "" (a name half typed)."""
        return name if name and gs.find_file(name, element=element)["name"] else ""

    def _on_boreholes(self, event):
        name = self._existing(self.boreholes.GetValue().strip(), "vector")
        if name != self.state.boreholes:
            self.state.boreholes = name
            if name:
                self._fill_columns()
        try:
            columns = set(gs.vector_columns(name)) if name else set()
        except CalledModuleError:  # no attribute table
            columns = set()
        self.state.log_columns = tuple(
            c.GetValue().strip() if c.GetValue().strip() in columns else ""
            for c in self.log_columns)
        self.state.log_depths = self.log_depths.GetValue()
        self.state.borehole_radius = self.borehole_radius.GetValue()
        self.request_frame(True)

    def _on_drape(self, event):
        self.state.texture = self._existing(self.texture.GetValue().strip(), "cell")
        self.state.drape = self.drape.GetValue()
        self.request_frame(True)

    # save and record ----------------------------------------------------
    def _run(self, command, event, busy, failure, finished, then=None):
        """Shows `command` and runs it on a thread (status `busy`); then logs
        `event` with its outcome and shows `finished` (and calls `then`), or
        its messages in a box titled `failure`."""
        self.command.SetValue(command)
        self.SetStatusText(busy, 0)
        self.log.write("command", command=command)

        def done(returncode, messages):
            if self._closing:
                return
            self.log.write(event, command=command, returncode=returncode,
                           messages=messages)
            if returncode:
                wx.MessageBox(messages, failure, wx.OK | wx.ICON_ERROR, self)
            else:
                self.SetStatusText(finished, 0)
                if then:
                    then()

        def work():
            result = subprocess.run(shlex.split(command), capture_output=True, text=True)
            wx.CallAfter(done, result.returncode, result.stderr.strip())

        threading.Thread(target=work, daemon=True).start()

    def on_save(self, event):
        with SaveViewDialog(self, self.state.sbrt.split("@")[0] + "_view") as dialog:
            if dialog.ShowModal() != wx.ID_OK:
                return
            output, png = dialog.output.GetValue().strip(), dialog.png.GetValue().strip()
            extra = ["--overwrite"] if dialog.overwrite.GetValue() else []
        command = self.state.command(*self.canvas.GetClientSize(), output=output, png=png,
                                     extra=extra)
        self._run(command, "saved", _("Saving the view..."), _("Save view failed"),
                  _("Saved <%s> and %s") % (output, png))

    def on_record(self, event):
        with RecordOrbitDialog(self, self.state.sbrt.split("@")[0]) as dialog:
            if dialog.ShowModal() != wx.ID_OK:
                return
            frames, png = dialog.frames.GetValue(), dialog.png.GetValue().strip()
            video = dialog.video.GetValue().strip()
            extra = ["frames=%d" % frames, "path=orbit"] + (["video=" + video] if video else [])
            if dialog.overwrite.GetValue():
                extra.append("--overwrite")
        command = self.state.command(*self.canvas.GetClientSize(), png=png, extra=extra)
        self._run(command, "recorded", _("Recording an orbit of %d frames...") % frames,
                  _("Record orbit failed"), _("Orbit written: %s") % (video or png))

    def on_section_profile(self, event):
        if self.state.section is None:
            wx.MessageBox(_("Turn the cross section on first: its line is the profile's."),
                          _("Section profile"), wx.OK | wx.ICON_INFORMATION, self)
            return
        png = profile_png_path()
        command = self.state.profile_command(png)

        def show():
            frame = SectionProfileFrame(self, png, _("Profile of the section of %s")
                                        % self.state.sbrt)
            frame.Show()
            self.log.write("section_profile", png=png, size=list(frame.GetClientSize()))

        self._run(command, "profiled", _("Drawing the section's profile..."),
                  _("Section profile failed"), _("Profile drawn"), then=show)

    def on_reset(self, event):
        self.state.reset_camera()
        self.request_frame(True)

    def _on_close(self, event):
        self._closing = True
        self.refine.Stop()
        self.rest.Stop()
        self.thread.stop()
        self.Destroy()
