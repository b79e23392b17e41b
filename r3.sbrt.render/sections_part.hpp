/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's sections: clip planes, a cross section and a
 *            fence diagram (part of the prepared scene's key; a section
 *            faces the camera, so its key is the camera's too)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SECTIONS_PART_HPP
#define R3_SBRT_SECTIONS_PART_HPP

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "option_table.hpp"
#include "scene/camera.hpp"
#include "scene/scene.hpp"

/// \brief plane=, section=, fence=.
struct SectionsPart {
    std::vector<std::array<double, 6>> planes;    ///< x,y,z,nx,ny,nz each
    std::optional<std::array<double, 4>> section; ///< x1,y1,x2,y2
    std::string fence;                            ///< vector line map

    static void define(OptionTable &table);
    void read(const Answers &answers);
    /// plane= as given, and section= with its normal turned towards the
    /// camera (the side facing the camera is removed, so the cut shows).
    std::vector<sbrt::ClipPlane> clip_planes(const sbrt::Camera &camera) const;
    std::string key(const sbrt::Camera &camera) const;
};

#endif
