/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   property= and property_color=: the channels a render shows
 *            (checked against the SBRT's) and their colour ramp from a
 *            GRASS colour table or rules file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_PROPERTY_COLORS_HPP
#define R3_SBRT_PROPERTY_COLORS_HPP

#include <vector>

#include "format/channels_file.hpp"
#include "render_options.hpp"
#include "shading/color_ramp.hpp"

/// The indices of the channels property= names; throws (bad_request) for
/// an SBRT without channels, an unknown name, a channel named twice, or
/// channels of different units.
std::vector<size_t> property_channels(const RenderRequest &request,
                                      const sbrt::PropertyChannels *channels);

/// The range of the shown property: the sum of the channels' least and
/// greatest values (as meant), at most 100 where all are in %.
std::pair<double, double> property_range(const sbrt::PropertyChannels &channels,
                                         const std::vector<size_t> &summed);

/// The ramp of property_color= over [low, high] (GRASS's colour tables
/// stretch over the range; a rules file's % values are of the range).
sbrt::ColorRamp property_ramp(const std::string &table, double low, double high);

#endif
