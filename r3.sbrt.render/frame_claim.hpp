/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A frame's claim while it is rendered: jobs of range= that share
 *            their PNG files (a cluster's tasks) find out, with a clear
 *            message, when two of them are given the same frame
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_FRAME_CLAIM_HPP
#define R3_SBRT_FRAME_CLAIM_HPP

#include <string>

/// \brief The file `<png>.claim` beside frame `frame`'s PNG, locked
/// (flock) while the frame is rendered and removed once it is written or
/// its render fails; it names the job ("host process pid"). A claim another
/// process holds is refused (bad_request, naming that job and the file); a
/// file a killed job left holds no lock and is taken over. Without a png
/// nothing is claimed.
class FrameClaim {
public:
    FrameClaim(const std::string &png, int frame);
    ~FrameClaim();
    FrameClaim(const FrameClaim &) = delete;
    FrameClaim &operator=(const FrameClaim &) = delete;

private:
    std::string path_; ///< empty: nothing claimed
    int fd_ = -1;      ///< the locked file
};

#endif
