/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The outputs of an animation's frames: their names, whether a
 *            frame is finished, and what the whole sequence makes (a
 *            space-time raster dataset, a video)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_FRAMES_HPP
#define R3_SBRT_FRAMES_HPP

#include <string>

#include "render_options.hpp"

/// The request of frame k (from 1): maps named <name>_NNNN and the PNG
/// from png= (a printf pattern such as orbit_%04d.png, else _NNNN before
/// the extension); the request itself when there is one frame.
RenderRequest frame_request(const RenderRequest &request, int frame);

/// Throws the request's error (bad_request), which run_reporting_errors
/// turns into a GRASS error, unless png= names each frame's file: one %d
/// (flags and width allowed) or none.
void check_png_pattern(const std::string &png);

/// Whether every output of this frame's request exists (the PNG last,
/// after its maps): a rerun skips it unless --overwrite.
bool frame_finished(const RenderRequest &frame);

/// Throws the request's error (bad_request), which run_reporting_errors
/// turns into a GRASS error before any frame is rendered, where video=
/// cannot be made (no ffmpeg on the PATH, an unknown extension).
void check_video(const RenderRequest &request);

/// Registers <output>_NNNN of frames first..last in the space-time raster
/// dataset strds= (relative time, one second a frame; created if new).
void register_frames(const RenderRequest &request);

/// Assembles the PNG files of all frames into video= at fps= with ffmpeg.
void assemble_video(const RenderRequest &request);

/// \brief The frames of a video= given without png=: PNG files in a
/// temporary folder of the mapset, removed with it when the run ends
/// (made or not). All frames must be rendered in this run (no range=).
class TemporaryFrames {
public:
    explicit TemporaryFrames(const RenderRequest &request);
    ~TemporaryFrames();
    TemporaryFrames(const TemporaryFrames &) = delete;
    TemporaryFrames &operator=(const TemporaryFrames &) = delete;
    /// png= for the frames: a pattern in the folder.
    const std::string &png() const { return png_; }

private:
    std::string folder_, png_;
    int frames_;
};

#endif
