/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The lock a writer of an SBRT holds while it reads, changes and
 *            rewrites it, so that two changes at once are made one after
 *            the other instead of one losing the other; readers never take
 *            it and never wait
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_SBRT_LOCK_HPP
#define SBRT_SBRT_LOCK_HPP

#include <chrono>
#include <string>

#include "format/member_dir.hpp"

namespace sbrt {

/// \brief An exclusive flock(2) on `.name.lock`, the hidden sibling of SBRT
/// directory `dir/name`, held for the object's life (move-only).
///
/// The lock file lies beside the directory, not in it: a rewrite replaces
/// the directory by a rename, so a lock inside it would be a different
/// file for the next writer. The file is never removed (removing a lock
/// file lets two writers hold locks on two different files); the kernel
/// drops the lock when its holder exits or is killed, so nothing is left
/// held. flock is advisory: only writers that take this lock are ordered.
class SbrtLock {
public:
    /// Takes the lock of SBRT directory `directory`, waiting at most
    /// `wait` for another holder to let it go. Throws sbrt::Error naming
    /// the directory where the wait runs out ("another process is changing
    /// it") or the lock file cannot be opened (not a regular file, no
    /// permission).
    SbrtLock(const std::string &directory, std::chrono::milliseconds wait);
    SbrtLock(SbrtLock &&) noexcept = default;
    SbrtLock &operator=(SbrtLock &&) noexcept = default;
    SbrtLock(const SbrtLock &) = delete;
    SbrtLock &operator=(const SbrtLock &) = delete;
    ~SbrtLock() = default; // closing the descriptor drops the lock

    /// `dir/.name.lock` for SBRT directory `dir/name`.
    static std::string lock_path(const std::string &directory);

private:
    FileDescriptor file_;
};

} // namespace sbrt

#endif
