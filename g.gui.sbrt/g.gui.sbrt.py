#!/usr/bin/env python3
############################################################################
#
# MODULE:    g.gui.sbrt
# AUTHOR(S): r3.sbrt authors
# PURPOSE:   Explores an SBRT interactively: orbit, pan and zoom, hide and
#            fade strata, move a section, boreholes and their logs, drape;
#            frames come from r3.sbrt.render's view server
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
#
############################################################################

# %module
# % description: Explores a stack-based terrain model (SBRT) in real time: turn, hide strata, cut, boreholes.
# % keyword: general
# % keyword: GUI
# % keyword: raster3d
# % keyword: visualization
# % keyword: geology
# % keyword: SBRT
# %end
# %option
# % key: input
# % type: string
# % required: yes
# % key_desc: name
# % gisprompt: old,sbrt,sbrt
# % description: Name of the SBRT to explore (from r3.sbrt.convert)
# %end
# %option
# % key: size
# % type: integer
# % required: no
# % key_desc: width,height
# % answer: 800,600
# % description: Size of the view in pixels
# %end
# %option G_OPT_V_INPUT
# % key: boreholes
# % required: no
# % label: Vector point map of boreholes
# % description: Shown as cylinders with the classes below them (or their logs)
# %end
# %option G_OPT_R_INPUT
# % key: texture
# % required: no
# % label: Raster map draped on the terrain surface
# % description: A map with a colour table (on and off in the viewer)
# %end
# %option
# % key: property
# % type: string
# % required: no
# % key_desc: channel[+channel...]
# % label: Property channel (or a sum) to colour the model by at start
# % description: e.g. kans_5+kans_6+kans_7 (an SBRT with property channels)
# %end
# %option
# % key: memory
# % type: integer
# % required: no
# % key_desc: memory in MB
# % label: Memory for the model in MB (as r3.sbrt.render memory=)
# % description: Default: a quarter of the available memory, at least 300
# %end
# %option
# % key: backend
# % type: string
# % required: no
# % options: auto,egl,osmesa,cpu
# % answer: auto
# % description: Renderer of the frames (as r3.sbrt.render backend=)
# %end

import os
import sys

import grass.script as gs

# benchmarks and tests: a JSON line per frame, drag and save
LOG_VARIABLE = "GRASS_SBRT_VIEWER_LOG"


def main():
    options, flags = gs.parser()
    size = [int(v) for v in options["size"].split(",")]
    if len(size) != 2 or min(size) < 16 or max(size) > 8192:
        gs.fatal(_("size= takes width,height in pixels (16 to 8192 each), e.g. 800,600"))
    if options["memory"] and int(options["memory"]) < 1:
        gs.fatal(_("memory=%s is not a number of MB of at least 1") % options["memory"])

    from grass.script.utils import get_lib_path

    here = get_lib_path(modname="g.gui.sbrt")
    if here is None:
        gs.fatal(_("The files of g.gui.sbrt are missing (etc/g.gui.sbrt)"))
    sys.path.insert(0, here)
    from view_client import ServerError, ViewServer

    # the view server's process starts (GRASS set up in it) while this one
    # loads wx: a national model's first frame is shown that much sooner
    # (issue 49); its first answer says where the SBRT is not found
    server = ViewServer()
    server.start()
    # import wx only after the parser (--interface-description needs none)
    import wx
    from grass.script.setup import set_gui_path

    set_gui_path()
    from viewer_frame import ViewerFrame

    app = wx.App()
    try:
        frame = ViewerFrame(
            server,
            options["input"],
            tuple(size),
            boreholes=options["boreholes"],
            texture=options["texture"],
            backend=options["backend"],
            log_path=os.environ.get(LOG_VARIABLE),
            property=options["property"],
            memory=options["memory"],
        )
    except ServerError as error:
        server.close()
        gs.fatal(str(error))
    frame.Show()
    app.MainLoop()


if __name__ == "__main__":
    main()
