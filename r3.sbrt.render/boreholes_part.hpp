/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's boreholes and their logs (part of the prepared
 *            scene's key; split logs face the camera)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_BOREHOLES_PART_HPP
#define R3_SBRT_BOREHOLES_PART_HPP

#include <optional>
#include <string>

#include "option_table.hpp"
#include "scene/camera.hpp"
#include "scene/scene_parts.hpp"

/// \brief boreholes=, layer=, where=, borehole_radius=, log_top=,
/// log_bottom=, log_class=, log_reference=, -b, -m.
struct BoreholesPart {
    std::string boreholes, layer = "1", where; ///< vector point map
    std::optional<double> borehole_radius;     ///< map units (default 0.4 cell)
    bool boreholes_only = false;               ///< -b
    std::string log_top, log_bottom, log_class; ///< columns of the logs
    sbrt::LogReference log_reference = sbrt::LogReference::elevation;
    bool split_logs = false; ///< -m

    static void define(OptionTable &table);
    void read(const Answers &answers);
    std::string key(const sbrt::Camera &camera) const;
};

#endif
