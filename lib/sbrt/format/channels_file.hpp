/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `channels` member of an SBRT (issue 29): per-voxel
 *            property channels over each column's solid span, in blocks
 *            of cells aligned with the stack blocks, each channel's block
 *            zstd-compressed on its own (values as integers above the
 *            block's least, or as float bits; differences down the column;
 *            byte planes), written as a stream, decoded block by block on
 *            first use
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CHANNELS_FILE_HPP
#define SBRT_CHANNELS_FILE_HPP

#include <atomic>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "format/byte_sink.hpp"
#include "model/model.hpp"
#include "model/property_channel.hpp"

namespace sbrt {

/// The longest name, long name or unit of a channel the channels member
/// holds (a reader refuses longer texts as damage).
constexpr size_t MAX_CHANNEL_TEXT = 4096;

class MappedFile;

/// Version 1.1 of the `channels` member (1.0 is read: its kinds are what
/// the units say).
constexpr uint16_t CHANNELS_MAJOR = 1;
constexpr uint16_t CHANNELS_MINOR = 1;
constexpr uint32_t CHANNELS_HEADER_SIZE = 64;

/// Layout (little-endian):
///   header: magic "\x89SBCH\r\n\x1a", u16 major 1, u16 minor, u32 header
///   size, u32 rows cols block size (cells a side) channels, u64 offset of
///   the directory, u64 end of file, u32 crc32 of the directory, u32 0 0,
///   u32 crc32 of the header;
///   blocks, by rows of blocks, then channel, then block column: one zstd
///   frame each of: u8 coding (0: integers, 1: float32 bits), u8 width
///   (bytes a value: 1, 2 or 4), u16 0, i32 base (the block's least
///   integer; 0 for floats), then the values of its cells (row by row,
///   each cell's span bottom up) as integers - base, or float bits, each
///   the difference to (integers, modulo 2^(8 width); floats: XOR with)
///   the value below it in the column, as byte planes (every value's
///   byte 0, then every value's byte 1, ...);
///   directory, per channel: name, long name, unit (u32 length + bytes),
///   f64 scale offset, u8 has fill, f32 fill, u64 voxels valid, f64 min
///   max, u8 integer, u64 bytes, then per block: u64 offset, u32
///   compressed size, u32 uncompressed size, u32 crc32 of the compressed
///   bytes; after the last channel (1.1 on, where a 1.0 reader stops
///   reading), per channel: u8 kind (ChannelKind, 1 to 4).
///
/// \brief Values of one channel's block waiting for the rest of its rows,
/// held in the narrowest of int8, int16 and float32 that holds each
/// exactly (GeoTOP's percentages and fills: a byte each), widened when a
/// value needs it.
class PendingValues {
public:
    void append(const float *values, size_t n);
    size_t size() const { return size_; }
    /// The values as floats into `out` (replacing what it held).
    void floats(std::vector<float> &out) const;
    void clear();

private:
    /// Stores the values held again in `width` bytes each (2 or 4).
    void widen(unsigned width);
    std::vector<uint8_t> bytes_;
    unsigned width_ = 1; ///< 1: int8, 2: int16, 4: float32 bits
    size_t size_ = 0;
};

/// \brief Writes a channels member as rows of cells arrive (north to
/// south), holding one row of blocks at a time (its values as narrow as
/// they allow) and compressing it a few blocks at a time.
class ChannelsWriter {
public:
    ChannelsWriter(ByteSink &sink, int rows, int cols, int block_size,
                   std::vector<ChannelInfo> channels, unsigned threads = 0,
                   int zstd_level = 3);

    /// The next row: `spans` per cell (cols of them), and per channel the
    /// values of the row's spans one after another (bottom up).
    void add_row(const ColumnSpan *spans, const std::vector<const float *> &values);
    /// The same in parts: channel `channel`'s values of the next rows, one
    /// row at a time (distinct channels may come from threads at once),
    /// then end_row for each of those rows in order, at most
    /// rows_to_block_end() rows ahead.
    void add_channel_row(size_t channel, const ColumnSpan *spans, const float *values);
    void end_row(const ColumnSpan *spans);
    /// Rows that may come before the row of blocks is complete.
    int rows_to_block_end() const { return block_size_ - row_ % block_size_; }
    /// Writes the directory and the header (every row must have come).
    void finish();
    /// The channels with the figures of their values (after finish: bytes).
    const std::vector<ChannelInfo> &channels() const { return channels_; }

private:
    void flush_block_row();

    struct BlockEntry {
        uint64_t offset = 0;
        uint32_t compressed = 0, raw = 0, crc = 0;
    };
    ByteSink &sink_;
    int rows_, cols_, block_size_, block_cols_;
    std::vector<ChannelInfo> channels_;
    unsigned threads_;
    int zstd_level_;
    int row_ = 0;
    std::vector<std::vector<ColumnSpan>> block_spans_; ///< per block column
    /// per channel, per block column: the values of the pending rows
    std::vector<std::vector<PendingValues>> pending_;
    std::vector<std::vector<BlockEntry>> table_; ///< per channel
    /// per block of a group compressed together: its values, raw and
    /// compressed bytes (kept from one group to the next: no fresh pages)
    std::vector<std::vector<float>> values_;
    std::vector<std::vector<uint8_t>> raw_, compressed_;
};

/// \brief Decoded values of one channel: `size` codes of `width` bytes
/// each (1, 2 or 4, little-endian), a value base + code (integers) or the
/// code's bits (float32). A view: the codes belong to PropertyChannels.
class ChannelValues {
public:
    ChannelValues() = default;
    ChannelValues(const uint8_t *codes, unsigned width, bool float_bits, int32_t base,
                  size_t size)
        : codes_(codes), size_(size), base_(base), width_(uint8_t(width)),
          float_bits_(float_bits)
    {
    }
    size_t size() const { return size_; }
    explicit operator bool() const { return codes_ != nullptr; }
    float operator[](size_t i) const
    {
        uint32_t code;
        if (width_ == 1) {
            code = codes_[i];
        } else if (width_ == 2) {
            const uint8_t *p = codes_ + 2 * i;
            code = uint32_t(p[0]) | uint32_t(p[1]) << 8;
        } else {
            const uint8_t *p = codes_ + 4 * i;
            code = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 |
                   uint32_t(p[3]) << 24;
        }
        if (float_bits_) {
            float v;
            std::memcpy(&v, &code, 4);
            return v;
        }
        return float(int64_t(base_) + int64_t(code));
    }
    /// Whether every value is a whole number held as a 1- or 2-byte code
    /// and small enough (below 2^24) that float holds it exactly: whole()
    /// then gives value i as operator[] does, as an integer.
    bool whole_codes() const
    {
        return !float_bits_ && width_ <= 2 && base_ > -(1 << 24) + 65536 &&
               base_ < (1 << 24) - 65536;
    }
    int64_t whole(size_t i) const
    {
        const uint32_t code = width_ == 1 ? uint32_t(codes_[i])
                                          : uint32_t(codes_[2 * i]) |
                                                uint32_t(codes_[2 * i + 1]) << 8;
        return int64_t(base_) + int64_t(code);
    }
    /// Values [0, size()) as whole() gives them, into `out` (whole_codes()
    /// must hold; `out` is not the codes): in a loop the compiler
    /// vectorises.
    void whole_into(int32_t *out) const;
    /// `count` values from the `first` on (a cell's span in its block).
    ChannelValues part(size_t first, size_t count) const
    {
        return {codes_ + first * width_, width_, float_bits_, base_, count};
    }

private:
    const uint8_t *codes_ = nullptr;
    size_t size_ = 0;
    int32_t base_ = 0;
    uint8_t width_ = 1;
    bool float_bits_ = false;
};

/// The number of channels in the untrusted channels file `file` (named
/// `what`), checked to be made for stacks of `frame` in blocks of
/// `block_size` cells: its header, size and directory checksum (the
/// spans of each block are checked when a reader first decodes it).
/// Throws sbrt::Error where it does not fit.
size_t channels_for_stacks(const MappedFile &file, const Frame &frame, int block_size,
                           const std::string &what);

/// \brief Where a cell's span lies in its block's decoded values.
struct CellSlot {
    uint32_t lo = 0, hi = 0; ///< the span
    uint32_t at = 0;         ///< its first value in the block
};

/// \brief The channels of an SBRT, read from untrusted bytes: the header,
/// directory and block table are checked when opened, a block when it is
/// first needed (its checksum, sizes and codes against the model's spans).
/// Blocks are decoded once, by whichever thread needs one first.
class PropertyChannels {
public:
    /// `model` is the SBRT's model as read (spans are taken from it); a
    /// model read for an area decodes only the blocks it has stacks in.
    PropertyChannels(std::shared_ptr<const MappedFile> file, std::string what,
                     const Model &model);
    ~PropertyChannels();
    PropertyChannels(const PropertyChannels &) = delete;
    PropertyChannels &operator=(const PropertyChannels &) = delete;

    size_t size() const { return channels_.size(); }
    const ChannelInfo &info(size_t channel) const { return channels_[channel]; }
    const std::vector<ChannelInfo> &infos() const { return channels_; }
    /// Index of the channel called `name`, or -1.
    int find(const std::string &name) const;
    int block_size() const { return block_size_; }

    ColumnSpan span(uint64_t cell) const
    {
        return {slots_[cell].lo, slots_[cell].hi};
    }
    /// The values of `cell`'s span, bottom up (span(cell).size() of them),
    /// its block decoded where it is not yet; empty (false) for an empty
    /// span. Throws sbrt::Error for a corrupt block.
    ChannelValues column(size_t channel, uint64_t cell) const;
    /// The value at voxel `level` (0 bottom) of `cell`; false outside its span.
    bool value(size_t channel, uint64_t cell, uint32_t level, float &out) const
    {
        const CellSlot &s = slots_[cell];
        if (level < s.lo || level >= s.hi)
            return false;
        out = column(channel, cell)[level - s.lo];
        return true;
    }
    /// Where `cell`'s values lie: its span and first value in its block.
    const CellSlot &slot(uint64_t cell) const { return slots_[cell]; }
    /// The cells of the model the channels belong to, and the values each
    /// channel holds (every cell's span).
    uint64_t cells() const { return slots_.size(); }
    uint64_t values() const { return values_; }
    /// The block holding `cell`'s values (of every channel), of blocks().
    size_t block_of(uint64_t cell) const;
    size_t blocks() const { return blocks_; }
    /// The decoded values of `channel` in `block`, every cell's span after
    /// another (decoded now where they are not yet, kept in the width they
    /// are stored in; throws sbrt::Error for a corrupt block).
    ChannelValues block_values(size_t channel, size_t block) const;
    /// Blocks decoded so far (all channels) and in the file.
    uint64_t blocks_decoded() const { return decoded_; }
    uint64_t block_count() const { return uint64_t(blocks_) * channels_.size(); }

    /// Writes this channels file again (in the current version) into the
    /// empty `sink` with the long names, units and kinds of `infos`, one
    /// for each channel in order under the same name; the blocks are
    /// copied as they are. Throws sbrt::Error where `infos` does not match.
    void write_with(const std::vector<ChannelInfo> &infos, ByteSink &sink) const;

private:
    struct Block;

    std::shared_ptr<const MappedFile> file_;
    std::string what_;
    uint64_t blocks_begin_ = 0, blocks_end_ = 0; ///< the blocks' bytes in the file
    int rows_ = 0, cols_ = 0, block_size_ = 0, block_cols_ = 0;
    size_t blocks_ = 0;
    std::vector<ChannelInfo> channels_;
    std::vector<CellSlot> slots_;
    std::vector<uint32_t> block_values_; ///< values a block holds (all spans)
    uint64_t values_ = 0;
    std::unique_ptr<Block[]> blocks_data_; ///< channel-major
    mutable std::atomic<uint64_t> decoded_{0};
};

} // namespace sbrt

#endif
