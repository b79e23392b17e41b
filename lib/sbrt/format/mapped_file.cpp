/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Read-only memory mapping of a file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/mapped_file.hpp"

#include <cerrno>
#include <cstring>

#include <sys/mman.h>

#include "format/member_dir.hpp"
#include "util/error.hpp"

namespace sbrt {

MappedFile::MappedFile(const std::string &path)
    : MappedFile(open_regular_file(path), path)
{
}

MappedFile::MappedFile(const FileDescriptor &file, const std::string &what)
{
    size_ = size_t(regular_file_size(file, what));
    if (size_ > 0) {
        // populated at once: one call instead of a page fault per 4 KiB
        data_ = mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE,
                     file.get(), 0);
        if (data_ == MAP_FAILED) {
            const int error = errno;
            data_ = nullptr;
            fail(what, ": cannot map ", size_, " bytes: ", std::strerror(error));
        }
    }
}

MappedFile::~MappedFile()
{
    if (data_)
        munmap(data_, size_);
}

} // namespace sbrt
