/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Read-only memory mapping of a file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/mapped_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <sys/mman.h>
#include <unistd.h>

#include "format/member_dir.hpp"
#include "util/error.hpp"

namespace sbrt {

MappedFile::MappedFile(const std::string &path, Pages pages)
    : MappedFile(open_regular_file(path), path, pages)
{
}

MappedFile::MappedFile(const FileDescriptor &file, const std::string &what, Pages pages)
{
    size_ = size_t(regular_file_size(file, what));
    if (size_ > 0) {
        const int populate = pages == Pages::populated ? MAP_POPULATE : 0;
        data_ = mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | populate, file.get(), 0);
        if (data_ == MAP_FAILED) {
            const int error = errno;
            data_ = nullptr;
            fail(what, ": cannot map ", size_, " bytes: ", std::strerror(error));
        }
    }
}

void MappedFile::release(const uint8_t *data, size_t size) const
{
    // Linux maps the cached pages of the aligned 64 KiB around a page
    // read (fault-around): those go too, else a view of small blocks keeps
    // most of the file resident
    const uintptr_t window = std::max<uintptr_t>(uintptr_t(sysconf(_SC_PAGESIZE)), 64 << 10);
    const uintptr_t begin = uintptr_t(data_), end = begin + size_;
    const uintptr_t first = std::max(begin, uintptr_t(data) / window * window);
    const uintptr_t last =
        std::min(end, (uintptr_t(data) + size + window - 1) / window * window);
    if (data_ && last > first) // only a hint: failing, it changes nothing
        madvise(reinterpret_cast<void *>(first), last - first, MADV_DONTNEED);
}

MappedFile::~MappedFile()
{
    if (data_)
        munmap(data_, size_);
}

} // namespace sbrt
