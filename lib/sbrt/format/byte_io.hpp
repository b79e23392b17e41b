/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Little-endian fields written and read one by one, bounds-checked
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BYTE_IO_HPP
#define SBRT_BYTE_IO_HPP

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "util/error.hpp"

namespace sbrt {

/// Stores the low `bytes` bytes of `v` at `p`, little-endian.
inline void store_le(uint8_t *p, uint64_t v, int bytes)
{
    for (int i = 0; i < bytes; ++i)
        p[i] = uint8_t(v >> (8 * i));
}

/// The little-endian unsigned number of `bytes` bytes at `p`.
inline uint64_t load_le(const uint8_t *p, int bytes)
{
    uint64_t v = 0;
    for (int i = 0; i < bytes; ++i)
        v |= uint64_t(p[i]) << (8 * i);
    return v;
}

/// \brief Appends little-endian fields to a byte vector.
class ByteWriter {
public:
    void u8(uint8_t v) { bytes_.push_back(v); }
    void u16(uint16_t v) { put(v, 2); }
    void u32(uint32_t v) { put(v, 4); }
    void u64(uint64_t v) { put(v, 8); }
    void i32(int32_t v) { put(uint32_t(v), 4); }
    void f32(float v)
    {
        uint32_t bits;
        std::memcpy(&bits, &v, 4);
        put(bits, 4);
    }
    void f64(double v)
    {
        uint64_t bits;
        std::memcpy(&bits, &v, 8);
        put(bits, 8);
    }
    void raw(const void *data, size_t size)
    {
        const uint8_t *p = static_cast<const uint8_t *>(data);
        bytes_.insert(bytes_.end(), p, p + size);
    }
    /// Room for `size` bytes in all, so appending does not reallocate.
    void reserve(size_t size) { bytes_.reserve(size); }
    size_t size() const { return bytes_.size(); }
    std::vector<uint8_t> &bytes() { return bytes_; }

private:
    void put(uint64_t v, int n)
    {
        for (int i = 0; i < n; ++i)
            bytes_.push_back(uint8_t(v >> (8 * i)));
    }
    std::vector<uint8_t> bytes_;
};

/// \brief Reads little-endian fields from a byte range; every read is
/// bounds-checked and throws sbrt::Error naming `what` when it runs out.
class ByteReader {
public:
    ByteReader(const uint8_t *data, size_t size, std::string what)
        : data_(data), size_(size), what_(std::move(what))
    {
    }
    uint8_t u8() { return uint8_t(get(1)); }
    uint16_t u16() { return uint16_t(get(2)); }
    uint32_t u32() { return uint32_t(get(4)); }
    uint64_t u64() { return get(8); }
    int32_t i32() { return int32_t(uint32_t(get(4))); }
    float f32()
    {
        const uint32_t bits = uint32_t(get(4));
        float v;
        std::memcpy(&v, &bits, 4);
        return v;
    }
    double f64()
    {
        const uint64_t bits = get(8);
        double v;
        std::memcpy(&v, &bits, 8);
        return v;
    }
    void seek(size_t position)
    {
        if (position > size_)
            fail(what_, ": offset ", position, " beyond the end (", size_,
                 " bytes)");
        pos_ = position;
    }
    size_t position() const { return pos_; }

private:
    uint64_t get(int n)
    {
        if (size_ - pos_ < size_t(n))
            fail(what_, ": truncated (needs ", pos_ + n, " bytes, has ", size_,
                 ")");
        uint64_t v = 0;
        for (int i = 0; i < n; ++i)
            v |= uint64_t(data_[pos_ + i]) << (8 * i);
        pos_ += n;
        return v;
    }
    const uint8_t *data_;
    size_t size_;
    size_t pos_ = 0;
    std::string what_;
};

/// CRC-32 (zlib's) of a byte range.
uint32_t crc32_of(const uint8_t *data, size_t size);

} // namespace sbrt

#endif
