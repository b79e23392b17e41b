/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   property= and property_color=: the channels a render shows
 *            (checked against the SBRT's) and their colour ramp from a
 *            GRASS colour table or rules file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_PROPERTY_COLORS_HPP
#define R3_SBRT_PROPERTY_COLORS_HPP

#include <string>
#include <vector>

#include "format/channels_file.hpp"
#include "render_options.hpp"
#include "shading/color_ramp.hpp"

/// The indices of the channels property= names; throws (bad_request) for
/// an SBRT without channels, an unknown name, a channel named twice, or
/// channels of different units.
std::vector<size_t> property_channels(const RenderRequest &request,
                                      const sbrt::PropertyChannels *channels);

/// Whether the channels summed are a family of probabilities (issue 51):
/// each a probability in % (its kind, or where a file has none its unit
/// "%"), so that the probabilities of one voxel sum to 100 at most.
bool probability_family(const sbrt::PropertyChannels &channels,
                        const std::vector<size_t> &summed);

/// The range of the shown property (the colour ramp's, the legend's ends):
/// 0 to 100 for a family of probabilities, whatever values are present;
/// else the least and greatest value the property takes (as meant: a sum's
/// per voxel, not the sum of the channels' ranges).
std::pair<double, double> property_range(const sbrt::PropertyChannels &channels,
                                         const std::vector<size_t> &summed);

/// The unit of the shown property: "%" for a family of probabilities
/// (whatever unit the file gives), else the channels' (one unit).
std::string property_unit(const sbrt::PropertyChannels &channels,
                          const std::vector<size_t> &summed);

/// The ramp of property_color= over [low, high] (GRASS's colour tables
/// stretch over the range; a rules file's % values are of the range).
sbrt::ColorRamp property_ramp(const std::string &table, double low, double high);

#endif
