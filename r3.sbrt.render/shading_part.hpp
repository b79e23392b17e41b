/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's shading: light, background and normals (no
 *            key: the session sets the shading for every frame)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SHADING_PART_HPP
#define R3_SBRT_SHADING_PART_HPP

#include <array>
#include <cstdint>

#include "camera_part.hpp"
#include "option_table.hpp"
#include "shading/shading.hpp"

/// \brief light=, ambient=, background=, normals=, kernel=, smooth=.
struct ShadingPart {
    double light_azimuth = 315, light_elevation = 45, ambient = 0.35;
    std::array<uint8_t, 3> background{255, 255, 255};
    sbrt::Normals normals = sbrt::Normals::face;
    int kernel = 5;
    double smooth = 0;

    static void define(OptionTable &table);
    void read(const Answers &answers);
    /// What the shading refuses of the camera (kernel normals of a tile).
    void check(const CameraPart &camera) const;
};

#endif
