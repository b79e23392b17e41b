/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A small file a user names (a rules file, a label list) read
 *            whole: regular files only, of bounded size, never waiting on a
 *            FIFO nor reading a device without end
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_UTIL_USER_FILE_HPP
#define SBRT_UTIL_USER_FILE_HPP

#include <cstdint>
#include <string>

namespace sbrt {

/// What a file of type `mode` (stat's st_mode) is, for "... is a FIFO
/// (named pipe), not a regular file".
const char *file_kind(unsigned mode);

/// \brief All of file `path` (named `what` in errors), at most `max_bytes`.
/// A symbolic link is followed, as for any file named on a command line;
/// what it opens must be a regular file: a FIFO (opened without waiting for
/// a writer), a device such as /dev/zero, a directory or a socket is
/// refused at once, as is a file over `max_bytes`. Throws sbrt::Error
/// naming `what` and what the file is.
std::string read_user_file(const std::string &path, uint64_t max_bytes,
                           const std::string &what);

/// \brief All that descriptor `fd` (e.g. standard input) gives up to its
/// end, at most `max_bytes` (more throws sbrt::Error naming `what`).
std::string read_to_end(int fd, uint64_t max_bytes, const std::string &what);

} // namespace sbrt

#endif
