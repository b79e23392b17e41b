/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Byte sinks: memory and files
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/byte_sink.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

#include "util/error.hpp"

namespace sbrt {

void MemorySink::append(const void *data, size_t size)
{
    const uint8_t *p = static_cast<const uint8_t *>(data);
    bytes_.insert(bytes_.end(), p, p + size);
}

void MemorySink::overwrite(uint64_t offset, const void *data, size_t size)
{
    if (offset > bytes_.size() || size > bytes_.size() - offset)
        fail("MemorySink: overwrite past the end");
    std::memcpy(bytes_.data() + offset, data, size);
}

FileSink::FileSink(std::string path) : path_(std::move(path))
{
    fd_ = open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0)
        fail("cannot create ", path_, ": ", std::strerror(errno));
}

FileSink::~FileSink()
{
    if (fd_ >= 0)
        close(fd_);
}

void FileSink::write_at(uint64_t offset, const void *data, size_t size)
{
    const uint8_t *p = static_cast<const uint8_t *>(data);
    while (size > 0) {
        const ssize_t n = pwrite(fd_, p, size, off_t(offset));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            fail("cannot write ", path_, " at byte ", offset, ": ",
                 n < 0 ? std::strerror(errno) : "nothing written");
        p += n;
        size -= size_t(n);
        offset += uint64_t(n);
    }
}

void FileSink::append(const void *data, size_t size)
{
    if (fd_ < 0)
        fail(path_, ": written after finish()");
    write_at(size_, data, size);
    size_ += size;
}

void FileSink::overwrite(uint64_t offset, const void *data, size_t size)
{
    if (fd_ < 0 || offset > size_ || size > size_ - offset)
        fail(path_, ": overwrite past the end");
    write_at(offset, data, size);
}

void FileSink::finish()
{
    if (fd_ < 0)
        return;
    const bool synced = fsync(fd_) == 0;
    const int error = errno;
    const bool closed = close(fd_) == 0;
    fd_ = -1;
    if (!synced || !closed)
        fail("cannot write ", path_, ": ", std::strerror(synced ? errno : error));
}

} // namespace sbrt
