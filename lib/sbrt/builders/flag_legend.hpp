/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Class labels of a file variable from its CF `flag_values`
 *            and `flag_meanings`
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_FLAG_LEGEND_HPP
#define SBRT_FLAG_LEGEND_HPP

#include <string>
#include <vector>

#include "model/model.hpp"

namespace sbrt {

/// \brief The label of each flag value: the word of `meanings` (blank
/// separated, '_' -> ' ') at its position. Nothing when both are empty.
/// Throws sbrt::Error naming both counts when they differ (CF wants one
/// meaning per value; pairing them otherwise would mislabel classes), and
/// for a value that is no 32-bit integer class.
std::vector<Material> flag_legend(const std::vector<double> &values,
                                  const std::string &meanings);

} // namespace sbrt

#endif
