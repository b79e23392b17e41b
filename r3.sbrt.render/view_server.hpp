/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The view server of g.gui.sbrt: one process, one loaded model,
 *            a frame per request line (r3.sbrt.render's own options), the
 *            prepared scene kept while only the camera moves
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_VIEW_SERVER_HPP
#define R3_SBRT_VIEW_SERVER_HPP

#include <cstdio>

#include "render_options.hpp"

/// Serves requests from `in` until "quit" or its end, answering on `out`
/// (r3.sbrt.render --serve; the protocol is in g.gui.sbrt's manual):
///
///     render key=value... -flags  ->  "frame W H MS AZ EL DIST TX TY TZ\n"
///                                     (property=: "... TZ property LOW HIGH
///                                     UNIT\n", the legend's ramp and unit)
///                                     and W*H*3 bytes of RGB, rows from the top
///     classes input=NAME          ->  "model N S E W BOTTOM TOP ZEXAG
///                                     VOXELS\n", "classes COUNT\n" and
///                                     per class "ID R G B LABEL\n", then
///                                     "channels COUNT\n" and per channel
///                                     "LOW HIGH NAME|UNIT|LONG NAME\n"
///                                     (from the block summaries where the
///                                     SBRT has them: no block decoded)
///     anything wrong              ->  "error MESSAGE\n"
///
/// A request's words are those of the command line and are read by the
/// same code (parse_render_request) into the same render session, so a
/// frame is the image the same command renders; output=, png= and the other
/// outputs, frames=, tile= and rules=- are refused, as are an option given
/// twice, an empty line, a NUL byte and a line over 64 KiB. A camera,
/// light, ambient, background or normals change keeps the prepared scene;
/// any other option prepares it again. AZ, EL, DIST and TX,TY,TZ are the
/// camera as azimuth=, elevation=, distance= and target= (the defaults
/// resolved). Every line gets a reply: a frame, the classes or an error,
/// after which the server goes on.
void serve_views(const OptionTable &options, FILE *in, FILE *out);

#endif
