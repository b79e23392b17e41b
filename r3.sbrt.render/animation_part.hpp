/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's animation: frames, path, range, the dataset and
 *            the video of the sequence (no key: each frame's camera is made
 *            anew; a sweep moves its plane itself)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_ANIMATION_PART_HPP
#define R3_SBRT_ANIMATION_PART_HPP

#include <optional>
#include <string>

#include "camera_part.hpp"
#include "option_table.hpp"
#include "scene/camera_path.hpp"
#include "sections_part.hpp"

/// \brief frames=, path=, angle=, path_map=, height=, keys=, range=,
/// strds=, video=, fps= (GUI section Animation) and --overwrite.
struct AnimationPart {
    int frames = 1;
    sbrt::PathKind path = sbrt::PathKind::orbit;
    std::string path_map, keys;          ///< path=line's lines, path=keys' file
    std::optional<double> line_height;   ///< path=line: above the model's top
    double angle = 360;                  ///< the orbit's arc, degrees
    int first_frame = 1, last_frame = 1; ///< range=
    std::string strds, video;            ///< outputs of the whole sequence
    double fps = 12;
    bool overwrite = false; ///< --overwrite: redo finished frames

    static void define(OptionTable &table);
    void read(const Answers &answers);
    /// What the animation refuses of the camera and the sections.
    void check(const CameraPart &camera, const SectionsPart &sections) const;

private:
    void read_range(const Answers &answers);
};

#endif
