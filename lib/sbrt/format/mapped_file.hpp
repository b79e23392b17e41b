/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A regular file mapped read-only into memory (RAII): the SBRT
 *            reader decodes from the page cache, with no buffer of the
 *            whole file filled first
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MAPPED_FILE_HPP
#define SBRT_MAPPED_FILE_HPP

#include <cstddef>
#include <cstdint>
#include <string>

namespace sbrt {

class FileDescriptor;

/// \brief The bytes of a regular file; throws sbrt::Error where it cannot
/// be opened or mapped, or is no regular file (a FIFO is refused, not
/// waited on).
class MappedFile {
public:
    /// Whether every page is read in when mapped (one call instead of a
    /// page fault per 4 KiB: for a file read whole) or as it is touched
    /// (for a file read in part: a paged model's blocks, a summary).
    enum class Pages { populated, on_demand };
    explicit MappedFile(const std::string &path, Pages pages = Pages::populated);
    /// Maps the regular file open as `file` (which may be closed after);
    /// `what` names it in errors.
    MappedFile(const FileDescriptor &file, const std::string &what,
               Pages pages = Pages::populated);
    ~MappedFile();
    MappedFile(const MappedFile &) = delete;
    MappedFile &operator=(const MappedFile &) = delete;

    const uint8_t *data() const { return static_cast<const uint8_t *>(data_); }
    size_t size() const { return size_; }
    /// Drops the pages holding [data, data + size) of this mapping, and
    /// those Linux mapped around them (fault-around: the aligned 64 KiB),
    /// from the process's resident memory (madvise MADV_DONTNEED), never
    /// past the mapping: bytes read once, whose next read faults them in
    /// again from the page cache.
    void release(const uint8_t *data, size_t size) const;

private:
    void *data_ = nullptr;
    size_t size_ = 0;
};


} // namespace sbrt

#endif
