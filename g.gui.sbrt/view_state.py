"""
MODULE:    g.gui.sbrt
PURPOSE:   What the viewer shows, as r3.sbrt.render's options: the camera
           (orbit, pan, zoom), vertical exaggeration, hidden and
           translucent strata, the section, boreholes and the drape
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""

import math
import shlex

DEGREES_PER_PIXEL = 0.4
NO_CLASS = -2147483648  # the empty material (air), not a stratum
# the light turns with the camera, from 45 degrees to its left, so that
# walls and cut faces the camera sees are lit
LIGHT_FROM_CAMERA = 45.0
LIGHT_ELEVATION = 45.0
ZOOM_PER_STEP = 0.85


def number(value):
    """A number as the options take it (the same text on screen and in
    the saved command: both render the same image)."""
    return "%.10g" % value


class ZexagScale:
    """A logarithmic slider's positions 0..STEPS as exaggerations 1..`top`,
    two significant digits (the fitted one of a national model is in the
    thousands, a thick one's 1)."""

    STEPS = 200

    def __init__(self, top):
        self.top = max(top, 1.0 + 1e-9)

    def value(self, position):
        z = self.top ** (min(max(position, 0), self.STEPS) / self.STEPS)
        return float("%.2g" % z)

    def position(self, zexag):
        share = math.log(max(zexag, 1.0)) / math.log(self.top)
        return int(round(min(share, 1.0) * self.STEPS))


class ViewState:
    """The view of one SBRT; `extent` and `strata` come from the server."""

    def __init__(self, sbrt, extent, strata):
        self.sbrt = sbrt
        self.extent = extent
        # by class id, as -p and the PNG legend list them
        self.strata = sorted((s for s in strata if s.id != NO_CLASS), key=lambda s: s.id)
        self.azimuth, self.elevation, self.fov = 225.0, 30.0, 40.0
        self.distance = None  # None: framed by r3.sbrt.render
        self.target = None  # (x, y, z), real map units
        self.zexag = extent.zexag  # fitted to the model by r3.sbrt.render
        # kernel normals: smooth light on a voxel model's stairs (frames
        # until the view rests keep face normals: a kernel costs more)
        self.smooth_shading = extent.voxels
        self.hidden = set()  # class ids
        self.opacity = {}  # class id: share of light absorbed (< 1)
        self.section = None  # (direction in degrees from east, offset -1..1)
        self.boreholes = ""
        self.log_columns = ("", "", "")  # top, bottom, class
        self.log_depths = False  # log_reference=depth
        self.borehole_radius = 0.0  # map units; 0: r3.sbrt.render's default
        self.texture = ""
        self.drape = False
        self.backend = "auto"
        self.memory = ""  # MB; empty: the view server's default
        # property channels: the property (a channel or a sum a+b), shown
        # as colours or not, its selection threshold (only voxels with the
        # property >= it are solid), the uncertainty channel that greys
        # the colours
        self.property = ""
        self.color_by_property = True
        self.threshold = None
        self.fade = ""

    # the camera ---------------------------------------------------------
    def adopt_camera(self, frame):
        """Takes the camera a framed view resolved to (the first frame)."""
        self.azimuth, self.elevation = frame.azimuth, frame.elevation
        self.distance, self.target = frame.distance, frame.target

    def reset_camera(self):
        self.azimuth, self.elevation = 225.0, 30.0
        self.distance = self.target = None

    def orbit(self, dx, dy):
        """A drag of dx, dy pixels turns the model with the mouse."""
        self.azimuth = (self.azimuth - dx * DEGREES_PER_PIXEL) % 360.0
        self.elevation = min(89.0, max(-89.0, self.elevation + dy * DEGREES_PER_PIXEL))

    def _screen_axes(self):
        """The camera's right and up (unit, exaggerated space)."""
        az, el = math.radians(self.azimuth), math.radians(self.elevation)
        forward = (-math.sin(az) * math.cos(el), -math.cos(az) * math.cos(el), -math.sin(el))
        right = (-math.cos(az), math.sin(az), 0.0)
        up = (
            right[1] * forward[2] - right[2] * forward[1],
            right[2] * forward[0] - right[0] * forward[2],
            right[0] * forward[1] - right[1] * forward[0],
        )
        return right, up

    def pan(self, dx, dy, height):
        """A drag of dx, dy pixels of an image `height` pixels high moves
        the model with the mouse."""
        if self.distance is None or self.target is None:
            return
        per_pixel = 2 * self.distance * math.tan(math.radians(self.fov) / 2) / height
        right, up = self._screen_axes()
        x, y, z = self.target
        move = [(-dx * r + dy * u) * per_pixel for r, u in zip(right, up)]
        self.target = (x + move[0], y + move[1], z + move[2] / self.zexag)

    def zoom(self, steps):
        """Wheel steps (positive: closer)."""
        if self.distance is not None:
            self.distance *= ZOOM_PER_STEP**steps

    # the section --------------------------------------------------------
    def section_points(self):
        """x1,y1,x2,y2 of the vertical section, or None."""
        if self.section is None:
            return None
        direction, offset = self.section
        e = self.extent
        a = math.radians(direction)
        along, normal = (math.cos(a), math.sin(a)), (-math.sin(a), math.cos(a))
        width, depth = e.east - e.west, e.north - e.south
        reach = 0.5 * (abs(width * normal[0]) + abs(depth * normal[1]))
        cx = (e.east + e.west) / 2 + normal[0] * offset * reach
        cy = (e.north + e.south) / 2 + normal[1] * offset * reach
        half = math.hypot(width, depth)
        return (
            cx - along[0] * half,
            cy - along[1] * half,
            cx + along[0] * half,
            cy + along[1] * half,
        )

    def section_chord(self):
        """x1,y1,x2,y2 of the section's line within the model's extent
        (west or south end first), or None without a section."""
        points = self.section_points()
        if points is None:
            return None
        x1, y1, x2, y2 = points
        e = self.extent
        # Liang-Barsky: the part of the line inside the rectangle
        low, high = 0.0, 1.0
        for p, q in ((x1 - x2, x1 - e.west), (x2 - x1, e.east - x1),
                     (y1 - y2, y1 - e.south), (y2 - y1, e.north - y1)):
            if p == 0:
                continue
            t = q / p
            if p < 0:
                low = max(low, t)
            else:
                high = min(high, t)
        return (x1 + low * (x2 - x1), y1 + low * (y2 - y1),
                x1 + high * (x2 - x1), y1 + high * (y2 - y1))

    def profile_command(self, png, output=""):
        """The r3.sbrt.profile command line of the section's line across
        the model (a figure `png`, and a map `output` where given)."""
        words = ["input=" + self.sbrt,
                 "coordinates=" + ",".join(number(v) for v in self.section_chord())]
        if output:
            words.append("output=" + output)
        words.append("png=" + png)
        return "r3.sbrt.profile " + " ".join(shlex.quote(w) for w in words)

    def move_section(self, share):
        """Moves the section by `share` of the model across (-2..2)."""
        if self.section is not None:
            direction, offset = self.section
            self.section = (direction, min(0.98, max(-0.98, offset + share)))

    # the options --------------------------------------------------------
    def words(self, width, height, moving=False, reduced=False):
        """r3.sbrt.render's options of this view in a width x height image
        (`moving`: a frame while the user moves something or before the
        view rests, lit with face normals: kernel normals cost more;
        `reduced`: the reduced frame drawn while the user moves, from the
        SBRT's coarse level of detail where it has one, never exact)."""
        words = [
            "input=" + self.sbrt,
            "size=%d,%d" % (width, height),
            "azimuth=" + number(self.azimuth),
            "elevation=" + number(self.elevation),
            "fov=" + number(self.fov),
        ]
        if self.distance is not None:
            words.append("distance=" + number(self.distance))
        if self.target is not None:
            words.append("target=" + ",".join(number(v) for v in self.target))
        light = (self.azimuth + LIGHT_FROM_CAMERA) % 360.0
        if light != 315.0:  # r3.sbrt.render's default
            words.append("light=%s,%s" % (number(light), number(LIGHT_ELEVATION)))
        words.append("zexag=" + number(self.zexag))  # the command says it
        if self.smooth_shading and not moving:
            words.append("normals=kernel")
        if reduced:
            words.append("detail=coarse")
        if self.hidden:
            words.append("hide=" + ",".join(str(i) for i in sorted(self.hidden)))
        translucent = sorted(i for i in self.opacity if i not in self.hidden)
        if translucent:
            words.append(
                "opacity="
                + ",".join("%d:%s" % (i, number(self.opacity[i])) for i in translucent)
            )
        points = self.section_points()
        if points:
            words.append("section=" + ",".join(number(v) for v in points))
        if self.boreholes:
            words.append("boreholes=" + self.boreholes)
            if self.borehole_radius > 0:
                words.append("borehole_radius=" + number(self.borehole_radius))
            if all(self.log_columns):
                words += [
                    "log_top=" + self.log_columns[0],
                    "log_bottom=" + self.log_columns[1],
                    "log_class=" + self.log_columns[2],
                ]
                if self.log_depths:
                    words.append("log_reference=depth")
        if self.drape and self.texture:
            words.append("texture=" + self.texture)
        if self.property and self.color_by_property:
            words.append("property=" + self.property)
        if self.property and self.threshold is not None:
            words.append("select=%s>=%s" % (self.property, number(self.threshold)))
        if self.fade:
            words.append("fade=" + self.fade)
        if self.backend != "auto":
            words.append("backend=" + self.backend)
        if self.memory:
            words.append("memory=" + self.memory)
        return words

    def command(self, width, height, output="", png="", extra=()):
        """The r3.sbrt.render command line that renders this view."""
        words = self.words(width, height)
        if output:
            words.append("output=" + output)
        if png:
            words.append("png=" + png)
        return "r3.sbrt.render " + " ".join(shlex.quote(w) for w in words + list(extra))
