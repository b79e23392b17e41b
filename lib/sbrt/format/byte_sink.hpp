/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Where a streamed writer puts its bytes: appended in order,
 *            with a header patched in place at the end; a file (RAII,
 *            synced on finish) or memory
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BYTE_SINK_HPP
#define SBRT_BYTE_SINK_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sbrt {

/// \brief Bytes written in order; earlier bytes may be overwritten.
class ByteSink {
public:
    virtual ~ByteSink() = default;
    virtual void append(const void *data, size_t size) = 0;
    /// Replaces bytes already appended at [offset, offset + size).
    virtual void overwrite(uint64_t offset, const void *data, size_t size) = 0;
    virtual uint64_t size() const = 0;
};

/// \brief A byte vector.
class MemorySink : public ByteSink {
public:
    void append(const void *data, size_t size) override;
    void overwrite(uint64_t offset, const void *data, size_t size) override;
    uint64_t size() const override { return bytes_.size(); }
    std::vector<uint8_t> &bytes() { return bytes_; }

private:
    std::vector<uint8_t> bytes_;
};

/// \brief A new file, created (truncated) on construction and closed by the
/// destructor; finish() syncs it to disk. Throws sbrt::Error naming the
/// path on any failed write.
class FileSink : public ByteSink {
public:
    explicit FileSink(std::string path);
    ~FileSink() override;
    FileSink(const FileSink &) = delete;
    FileSink &operator=(const FileSink &) = delete;

    void append(const void *data, size_t size) override;
    void overwrite(uint64_t offset, const void *data, size_t size) override;
    uint64_t size() const override { return size_; }
    /// fsync and close; throws where the data may not have reached the disk.
    void finish();

private:
    void write_at(uint64_t offset, const void *data, size_t size);
    std::string path_;
    int fd_ = -1;
    uint64_t size_ = 0;
};

} // namespace sbrt

#endif
