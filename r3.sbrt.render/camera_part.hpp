/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's camera: view, image size, tile, position and
 *            the vertical exaggeration (its own part: the frame's key)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_CAMERA_PART_HPP
#define R3_SBRT_CAMERA_PART_HPP

#include <array>
#include <optional>
#include <string>

#include "option_table.hpp"
#include "scene/view.hpp"

/// \brief view=, size=, tile=, position=, target=, azimuth=, elevation=,
/// distance=, fov=, ortho_height= (no key: every frame is framed anew).
struct CameraPart {
    sbrt::View view; ///< the camera as asked for (map units, degrees)
    int width = 640, height = 480; ///< size=: perspective and orthographic
    bool size_given = false;       ///< size= was given (a top view's PNG fits it)
    std::optional<std::array<int, 4>> tile; ///< row, col, rows, cols of the image

    static void define(OptionTable &table);
    void read(const Answers &answers);

private:
    void read_size(const Answers &answers);
    void read_view(const Answers &answers);
};

/// \brief zexag=: what the coordinate frame and the prepared scene depend on.
struct ExaggerationPart {
    double zexag = 1;
    bool zexag_fitted = true; ///< no zexag=: RenderSession::load fits it to the model

    static void define(OptionTable &table);
    void read(const Answers &answers);
    std::string key() const;
};

#endif
