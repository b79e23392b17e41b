/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `channels` member: streamed writer, lazy checked reader
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/channels_file.hpp"

#include <zstd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include "format/byte_io.hpp"
#include "format/mapped_file.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

constexpr uint8_t CHANNELS_MAGIC[8] = {0x89, 'S', 'B', 'C', 'H', '\r', '\n', 0x1a};
constexpr uint8_t CODING_INTEGERS = 0, CODING_FLOAT_BITS = 1;
constexpr size_t BLOCK_HEAD = 8; // coding, width, 0, base
/// Integers a float32 holds exactly, and with them their differences.
constexpr double EXACT_INTEGER = 16777216.0;

uint32_t float_bits(float v)
{
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    return bits;
}

bool is_exact_integer(float v)
{
    // |v| <= 2^24 (NaN fails the test), then a round trip through int32
    return std::fabs(v) <= float(EXACT_INTEGER) && float(int32_t(v)) == v;
}

/// \brief What one block's values are (merged into a channel's figures).
struct BlockFigures {
    uint64_t valid = 0;
    double min = 0, max = 0;
    bool integer = true;
};

/// Stores `count` codes of one column (bottom up) as differences to the
/// code below into byte planes of `width` bytes at `at`.
template <unsigned WIDTH, bool INTEGERS>
void store_column(const float *values, size_t count, int64_t least, uint8_t *planes,
                  size_t n, size_t at)
{
    uint32_t below = 0;
    for (size_t k = 0; k < count; ++k) {
        uint32_t code;
        if constexpr (INTEGERS)
            code = uint32_t(int64_t(values[k]) - least);
        else
            code = float_bits(values[k]);
        const uint32_t stored = INTEGERS ? code - below : code ^ below;
        below = code;
        for (unsigned b = 0; b < WIDTH; ++b)
            planes[b * n + at + k] = uint8_t(stored >> (8 * b));
    }
}

/// A block's values (cells' spans one after another) as its raw payload;
/// `figures` gets what they are.
void encode_block(const std::vector<float> &values, const std::vector<ColumnSpan> &spans,
                  const ChannelInfo &info, BlockFigures &figures, std::vector<uint8_t> &raw)
{
    bool integers = true;
    float least = 0, most = 0;
    double valid_min = 0, valid_max = 0;
    uint64_t valid = 0;
    for (size_t i = 0; i < values.size(); ++i) {
        const float v = values[i];
        integers = integers && is_exact_integer(v);
        least = i ? std::min(least, v) : v;
        most = i ? std::max(most, v) : v;
        if (!info.is_fill(v)) {
            valid_min = valid ? std::min(valid_min, double(v)) : double(v);
            valid_max = valid ? std::max(valid_max, double(v)) : double(v);
            ++valid;
        }
    }
    figures = {valid, valid_min, valid_max, integers};
    const uint64_t range = integers ? uint64_t(int64_t(most) - int64_t(least)) : 0;
    const unsigned width = !integers ? 4 : range <= 0xff ? 1 : range <= 0xffff ? 2 : 4;
    const size_t n = values.size();
    raw.resize(BLOCK_HEAD + n * width);
    std::fill(raw.begin(), raw.begin() + BLOCK_HEAD, 0);
    raw[0] = integers ? CODING_INTEGERS : CODING_FLOAT_BITS;
    raw[1] = uint8_t(width);
    const int64_t base = integers ? int64_t(least) : 0;
    store_le(&raw[4], uint32_t(int32_t(base)), 4);
    uint8_t *planes = raw.data() + BLOCK_HEAD;
    size_t at = 0;
    for (const ColumnSpan &span : spans) {
        const float *column = values.data() + at;
        const size_t count = span.size();
        if (!integers)
            store_column<4, false>(column, count, 0, planes, n, at);
        else if (width == 1)
            store_column<1, true>(column, count, base, planes, n, at);
        else if (width == 2)
            store_column<2, true>(column, count, base, planes, n, at);
        else
            store_column<4, true>(column, count, base, planes, n, at);
        at += count;
    }
    SBRT_CHECK_EQ(at, n, "channel block");
}

/// Sums one block's differences down each column into codes of WIDTH
/// bytes (little-endian) at `codes`, which may be `planes` where WIDTH is 1.
template <unsigned WIDTH, bool INTEGERS>
void sum_columns(const uint8_t *planes, size_t n, const CellSlot *slots, size_t cells,
                 uint8_t *codes)
{
    constexpr uint32_t MASK = WIDTH == 4 ? 0xffffffffu : (1u << (8 * WIDTH)) - 1;
    for (size_t c = 0; c < cells; ++c) {
        uint32_t below = 0;
        const size_t end = size_t(slots[c].at) + (slots[c].hi - slots[c].lo);
        for (size_t i = slots[c].at; i < end; ++i) {
            uint32_t stored = 0;
            for (unsigned b = 0; b < WIDTH; ++b)
                stored |= uint32_t(planes[b * n + i]) << (8 * b);
            const uint32_t code = INTEGERS ? (below + stored) & MASK : stored ^ below;
            below = code;
            for (unsigned b = 0; b < WIDTH; ++b)
                codes[i * WIDTH + b] = uint8_t(code >> (8 * b));
        }
    }
}

/// \brief A block's values decoded: codes in their stored width.
struct DecodedCodes {
    std::unique_ptr<uint8_t[]> bytes; ///< the codes start at `at`
    size_t at = 0;
    unsigned width = 1;
    bool float_bits = false;
    int32_t base = 0;
};

/// The inverse of encode_block, on untrusted bytes (`raw`, `size` of them,
/// is taken: a block of one-byte values is decoded in place).
DecodedCodes decode_block(std::unique_ptr<uint8_t[]> raw, size_t size, const CellSlot *slots,
                          size_t cells, size_t n, const std::string &what)
{
    if (size < BLOCK_HEAD)
        fail(what, ": block of ", size, " bytes is shorter than its head");
    const uint8_t coding = raw[0], width = raw[1];
    if (coding > CODING_FLOAT_BITS || !(width == 1 || width == 2 || width == 4) ||
        (coding == CODING_FLOAT_BITS && width != 4))
        fail(what, ": block coding ", int(coding), " width ", int(width),
             " is not one this reader knows (corrupt file?)");
    if (size != BLOCK_HEAD + n * width)
        fail(what, ": block holds ", size, " bytes where its cells' spans need ",
             BLOCK_HEAD + n * width, " (the channels do not match the stacks)");
    DecodedCodes out;
    out.width = width;
    out.float_bits = coding == CODING_FLOAT_BITS;
    out.base = int32_t(uint32_t(load_le(&raw[4], 4)));
    const uint8_t *planes = raw.get() + BLOCK_HEAD;
    if (width == 1) {
        sum_columns<1, true>(planes, n, slots, cells, raw.get() + BLOCK_HEAD);
        out.bytes = std::move(raw);
        out.at = BLOCK_HEAD;
        return out;
    }
    out.bytes.reset(new uint8_t[n * width]); // every byte written below
    if (width == 2)
        sum_columns<2, true>(planes, n, slots, cells, out.bytes.get());
    else if (out.float_bits)
        sum_columns<4, false>(planes, n, slots, cells, out.bytes.get());
    else
        sum_columns<4, true>(planes, n, slots, cells, out.bytes.get());
    return out;
}

void write_string(ByteWriter &out, const std::string &s)
{
    // what read_string refuses is never written: a file nothing can read
    if (s.size() > MAX_CHANNEL_TEXT)
        fail("channels: a channel's text of ", s.size(), " bytes (at most ", MAX_CHANNEL_TEXT,
             ")");
    out.u32(uint32_t(s.size()));
    out.raw(s.data(), s.size());
}

std::string read_string(ByteReader &in, const std::string &what)
{
    const uint32_t n = in.u32();
    if (n > MAX_CHANNEL_TEXT)
        fail(what, ": a channel's text of ", n, " bytes (at most ", MAX_CHANNEL_TEXT, ")");
    std::string s(n, '\0');
    for (uint32_t i = 0; i < n; ++i)
        s[i] = char(in.u8());
    return s;
}

/// One channel's entry of the directory, up to its blocks.
void write_channel_entry(ByteWriter &dir, const ChannelInfo &c)
{
    write_string(dir, c.name);
    write_string(dir, c.long_name);
    write_string(dir, c.unit);
    dir.f64(c.scale);
    dir.f64(c.offset);
    dir.u8(c.has_fill ? 1 : 0);
    dir.f32(c.fill);
    dir.u64(c.voxels);
    dir.u64(c.valid);
    dir.f64(c.min);
    dir.f64(c.max);
    dir.u8(c.integer ? 1 : 0);
    dir.u64(c.bytes);
}

/// One channel's entry of the directory, up to its blocks, as
/// write_channel_entry writes it.
ChannelInfo read_channel_entry(ByteReader &in, const std::string &what)
{
    ChannelInfo c;
    c.name = read_string(in, what);
    c.long_name = read_string(in, what);
    c.unit = read_string(in, what);
    c.scale = in.f64();
    c.offset = in.f64();
    c.has_fill = in.u8() != 0;
    c.fill = in.f32();
    c.voxels = in.u64();
    c.valid = in.u64();
    c.min = in.f64();
    c.max = in.f64();
    c.integer = in.u8() != 0;
    c.bytes = in.u64();
    return c;
}

void write_block_entry(ByteWriter &dir, uint64_t offset, uint32_t compressed, uint32_t raw,
                       uint32_t crc)
{
    dir.u64(offset);
    dir.u32(compressed);
    dir.u32(raw);
    dir.u32(crc);
}

/// The kinds after the last channel (1.1): unset ones as the unit says.
void write_kinds(ByteWriter &dir, const std::vector<ChannelInfo> &channels)
{
    for (const ChannelInfo &c : channels)
        dir.u8(uint8_t(c.known_kind()));
}

/// The kinds of `channels`: read after the last channel (1.1), or as
/// their units say (1.0).
void read_kinds(ByteReader &in, uint16_t minor, std::vector<ChannelInfo> &channels,
                const std::string &what)
{
    for (ChannelInfo &c : channels) {
        if (minor < 1) { // 1.0: what the unit says, as it was read then
            c.kind = kind_of_unit(c.unit);
            continue;
        }
        const uint8_t kind = in.u8();
        if (kind < 1 || kind > LAST_CHANNEL_KIND)
            fail(what, ": channel ", c.name, " has kind ", int(kind),
                 ", not one this reader knows (corrupt file?)");
        c.kind = ChannelKind(kind);
    }
}

/// The header of a file whose directory (checksum `dir_crc`) lies at
/// `dir_at`, up to its `end`.
ByteWriter header_bytes(int rows, int cols, int block_size, size_t channels,
                        uint64_t dir_at, uint64_t end, uint32_t dir_crc)
{
    ByteWriter h;
    h.raw(CHANNELS_MAGIC, sizeof CHANNELS_MAGIC);
    h.u16(CHANNELS_MAJOR);
    h.u16(CHANNELS_MINOR);
    h.u32(CHANNELS_HEADER_SIZE);
    h.u32(uint32_t(rows));
    h.u32(uint32_t(cols));
    h.u32(uint32_t(block_size));
    h.u32(uint32_t(channels));
    h.u64(dir_at);
    h.u64(end);
    h.u32(dir_crc);
    h.u32(0);
    h.u32(0);
    h.u32(crc32_of(h.bytes().data(), h.size()));
    SBRT_CHECK_EQ(h.size(), size_t(CHANNELS_HEADER_SIZE), "channels header");
    return h;
}

} // namespace

// --------------------------------------------------------------- writer

namespace {
/// The width a value needs: 1 (int8), 2 (int16) or 4 (float bits: other
/// values, NaN and -0).
unsigned width_of(float v)
{
    if (v >= -128.0f && v <= 127.0f && float(int(v)) == v && !(v == 0 && std::signbit(v)))
        return 1;
    if (v >= -32768.0f && v <= 32767.0f && float(int(v)) == v && !(v == 0 && std::signbit(v)))
        return 2;
    return 4;
}
} // namespace

void PendingValues::append(const float *values, size_t n)
{
    bytes_.resize((size_ + n) * width_);
    for (size_t i = 0; i < n; ++i) {
        const float v = values[i];
        if (width_ < 4) {
            // one pass: stored while it fits, widened where it does not
            const unsigned need = width_of(v);
            if (need > width_) {
                size_ += i;
                widen(need);
                append(values + i, n - i);
                return;
            }
        }
        uint8_t *out = bytes_.data() + (size_ + i) * width_;
        if (width_ == 1) {
            *out = uint8_t(int8_t(int(v)));
        } else if (width_ == 2) {
            const int16_t k = int16_t(int(v));
            std::memcpy(out, &k, 2);
        } else {
            std::memcpy(out, &v, 4);
        }
    }
    size_ += n;
}

void PendingValues::widen(unsigned width)
{
    std::vector<float> held;
    floats(held); // the size_ values stored so far
    width_ = width;
    size_ = 0;
    bytes_.clear();
    append(held.data(), held.size());
}

void PendingValues::floats(std::vector<float> &out) const
{
    out.resize(size_);
    const uint8_t *in = bytes_.data();
    for (size_t i = 0; i < size_; ++i) {
        if (width_ == 1) {
            out[i] = float(int8_t(in[i]));
        } else if (width_ == 2) {
            int16_t v;
            std::memcpy(&v, in + 2 * i, 2);
            out[i] = float(v);
        } else {
            std::memcpy(&out[i], in + 4 * i, 4);
        }
    }
}

void PendingValues::clear()
{
    bytes_.clear(); // capacity kept for the next row of blocks
    width_ = 1;
    size_ = 0;
}

ChannelsWriter::ChannelsWriter(ByteSink &sink, int rows, int cols, int block_size,
                               std::vector<ChannelInfo> channels, unsigned threads,
                               int zstd_level)
    : sink_(sink), rows_(rows), cols_(cols), block_size_(block_size),
      block_cols_((cols + block_size - 1) / block_size), channels_(std::move(channels)),
      threads_(threads), zstd_level_(zstd_level)
{
    if (rows < 1 || cols < 1 || block_size < 1 || channels_.empty())
        fail("channels: a grid of ", rows, " x ", cols, " cells in blocks of ",
             block_size, " with ", channels_.size(), " channels");
    for (ChannelInfo &c : channels_) {
        c.voxels = c.valid = c.bytes = 0;
        c.min = c.max = 0;
        c.integer = !c.has_fill || is_exact_integer(c.fill);
    }
    block_spans_.resize(size_t(block_cols_));
    pending_.assign(channels_.size(), std::vector<PendingValues>(size_t(block_cols_)));
    table_.resize(channels_.size());
    std::vector<uint8_t> header(CHANNELS_HEADER_SIZE, 0);
    sink_.append(header.data(), header.size()); // patched by finish()
}

void ChannelsWriter::add_row(const ColumnSpan *spans, const std::vector<const float *> &values)
{
    SBRT_CHECK_EQ(values.size(), channels_.size(), "ChannelsWriter::add_row");
    for (size_t ch = 0; ch < channels_.size(); ++ch)
        add_channel_row(ch, spans, values[ch]);
    end_row(spans);
}

void ChannelsWriter::add_channel_row(size_t channel, const ColumnSpan *spans,
                                     const float *values)
{
    if (row_ >= rows_)
        fail("channels: more rows than the grid's ", rows_);
    const float *v = values;
    for (int bc = 0; bc < block_cols_; ++bc) {
        const int c0 = bc * block_size_, c1 = std::min(cols_, c0 + block_size_);
        size_t n = 0;
        for (int c = c0; c < c1; ++c)
            n += spans[c].size();
        pending_[channel][size_t(bc)].append(v, n);
        channels_[channel].voxels += n;
        v += n;
    }
}

void ChannelsWriter::end_row(const ColumnSpan *spans)
{
    if (row_ >= rows_)
        fail("channels: more rows than the grid's ", rows_);
    for (int bc = 0; bc < block_cols_; ++bc) {
        const int c0 = bc * block_size_, c1 = std::min(cols_, c0 + block_size_);
        block_spans_[size_t(bc)].insert(block_spans_[size_t(bc)].end(), spans + c0,
                                        spans + c1);
    }
    ++row_;
    if (row_ % block_size_ == 0 || row_ == rows_)
        flush_block_row();
}

void ChannelsWriter::flush_block_row()
{
    const size_t jobs = channels_.size() * size_t(block_cols_);
    // a few blocks at a time (twice the threads), appended in order: the
    // buffers are a group's, not a whole row of blocks'
    const size_t group = 2 * size_t(thread_count(threads_));
    values_.resize(group);
    raw_.resize(group);
    compressed_.resize(group);
    std::vector<uint32_t> raw_sizes(group);
    std::vector<BlockFigures> figures(group);
    for (size_t first = 0; first < jobs; first += group) {
        const size_t count = std::min(group, jobs - first);
        for_each_row(int(count), threads_, [&](int k) {
            const size_t job = first + size_t(k);
            const size_t ch = job / size_t(block_cols_), bc = job % size_t(block_cols_);
            std::vector<float> &values = values_[size_t(k)];
            pending_[ch][bc].floats(values);
            std::vector<uint8_t> &raw = raw_[size_t(k)];
            encode_block(values, block_spans_[bc], channels_[ch], figures[size_t(k)], raw);
            if (raw.size() > UINT32_MAX)
                fail("channels: a block of ", raw.size(), " bytes (give a smaller block size)");
            std::vector<uint8_t> &out = compressed_[size_t(k)];
            out.resize(ZSTD_compressBound(raw.size()));
            // one context a thread, kept: no tables allocated per block
            thread_local const std::unique_ptr<ZSTD_CCtx, size_t (*)(ZSTD_CCtx *)> context(
                ZSTD_createCCtx(), ZSTD_freeCCtx);
            const size_t n = ZSTD_compressCCtx(context.get(), out.data(), out.size(),
                                               raw.data(), raw.size(), zstd_level_);
            if (ZSTD_isError(n))
                fail("channels: zstd: ", ZSTD_getErrorName(n));
            out.resize(n);
            raw_sizes[size_t(k)] = uint32_t(raw.size());
        });
        for (size_t k = 0; k < count; ++k) {
            const size_t ch = (first + k) / size_t(block_cols_);
            ChannelInfo &info = channels_[ch];
            const BlockFigures &f = figures[k];
            if (f.valid) {
                info.min = info.valid ? std::min(info.min, f.min) : f.min;
                info.max = info.valid ? std::max(info.max, f.max) : f.max;
                info.valid += f.valid;
            }
            info.integer = info.integer && f.integer;
            const std::vector<uint8_t> &out = compressed_[k];
            table_[ch].push_back({sink_.size(), uint32_t(out.size()), raw_sizes[k],
                                  crc32_of(out.data(), out.size())});
            channels_[ch].bytes += out.size() + 20;
            sink_.append(out.data(), out.size());
        }
    }
    for (auto &per_channel : pending_)
        for (PendingValues &values : per_channel)
            values.clear();
    for (std::vector<ColumnSpan> &spans : block_spans_)
        spans.clear();
}

void ChannelsWriter::finish()
{
    if (row_ != rows_)
        fail("channels: ", row_, " rows of ", rows_, " came");
    ByteWriter dir;
    for (size_t ch = 0; ch < channels_.size(); ++ch) {
        write_channel_entry(dir, channels_[ch]);
        for (const BlockEntry &e : table_[ch])
            write_block_entry(dir, e.offset, e.compressed, e.raw, e.crc);
    }
    write_kinds(dir, channels_);
    const uint64_t dir_at = sink_.size();
    sink_.append(dir.bytes().data(), dir.size());
    ByteWriter h = header_bytes(rows_, cols_, block_size_, channels_.size(), dir_at,
                                sink_.size(), crc32_of(dir.bytes().data(), dir.size()));
    sink_.overwrite(0, h.bytes().data(), h.size());
}

// --------------------------------------------------------------- reader

struct PropertyChannels::Block {
    uint64_t offset = 0;
    uint32_t compressed = 0, raw = 0, crc = 0;
    std::once_flag once;
    DecodedCodes codes;
};

namespace {

/// The header's fields after the magic number and major version.
struct ChannelsHeader {
    uint16_t minor = 0;
    uint32_t header_size = 0;
    int rows = 0, cols = 0, block_size = 0;
    uint32_t count = 0; ///< channels
    uint64_t dir_at = 0, end = 0;
    uint32_t dir_crc = 0;
};

/// The header of the `size` bytes at `data`, its magic number, major
/// version, size and checksum checked.
ChannelsHeader read_header(const uint8_t *data, size_t size, const std::string &what)
{
    if (size < CHANNELS_HEADER_SIZE || std::memcmp(data, CHANNELS_MAGIC, 8) != 0)
        fail(what, ": not an SBRT channels file (bad magic number or truncated)");
    ByteReader in(data, CHANNELS_HEADER_SIZE, what);
    in.seek(8);
    ChannelsHeader h;
    const uint16_t major = in.u16();
    // minor: later fields come before the header checksum, or after the
    // directory's channels (1.1: the kinds)
    h.minor = in.u16();
    if (major != CHANNELS_MAJOR)
        fail(what, ": channels format ", major, ".x needs a newer r3.sbrt");
    h.header_size = in.u32();
    if (h.header_size < CHANNELS_HEADER_SIZE || h.header_size > size)
        fail(what, ": header size ", h.header_size, " is wrong");
    if (crc32_of(data, h.header_size - 4) != uint32_t(load_le(data + h.header_size - 4, 4)))
        fail(what, ": header checksum mismatch (corrupt file)");
    h.rows = int(in.u32());
    h.cols = int(in.u32());
    h.block_size = int(in.u32());
    h.count = in.u32();
    h.dir_at = in.u64();
    h.end = in.u64();
    h.dir_crc = in.u32();
    return h;
}

/// Checks header `h` against the model's frame `f` and the file of
/// `size` bytes at `data`, with the directory's checksum.
void check_header(const ChannelsHeader &h, const Frame &f, const uint8_t *data, size_t size,
                  const std::string &what)
{
    if (h.rows != f.rows || h.cols != f.cols)
        fail(what, ": channels of ", h.rows, " x ", h.cols, " cells for a model of ",
             f.rows, " x ", f.cols);
    if (h.block_size < 1 || h.block_size > 4096 || h.count < 1 || h.count > 65536)
        fail(what, ": block size ", h.block_size, ", ", h.count, " channels (corrupt file?)");
    if (h.end != size || h.dir_at < h.header_size || h.dir_at > size)
        fail(what, ": file of ", size, " bytes says it ends at ", h.end,
             " with its directory at ", h.dir_at, " (truncated or corrupt)");
    if (crc32_of(data + h.dir_at, size - h.dir_at) != h.dir_crc)
        fail(what, ": directory checksum mismatch (corrupt file)");
}

} // namespace

size_t channels_for_stacks(const MappedFile &file, const Frame &frame, int block_size,
                           const std::string &what)
{
    const ChannelsHeader h = read_header(file.data(), file.size(), what);
    check_header(h, frame, file.data(), file.size(), what);
    if (h.block_size != block_size)
        fail(what, ": channels in blocks of ", h.block_size, " cells for stacks in blocks of ",
             block_size);
    return h.count;
}

PropertyChannels::PropertyChannels(std::shared_ptr<const MappedFile> file, std::string what,
                                   const Model &model)
    : file_(std::move(file)), what_(std::move(what))
{
    const uint8_t *data = file_->data();
    const size_t size = file_->size();
    const ChannelsHeader h = read_header(data, size, what_);
    const Frame &f = model.frame();
    check_header(h, f, data, size, what_);
    rows_ = h.rows;
    cols_ = h.cols;
    block_size_ = h.block_size;
    block_cols_ = (cols_ + block_size_ - 1) / block_size_;
    const int block_rows = (rows_ + block_size_ - 1) / block_size_;
    blocks_ = size_t(block_rows) * size_t(block_cols_);
    if (uint64_t(blocks_) * h.count * 20 > size - h.dir_at)
        fail(what_, ": directory too short for ", h.count, " channels of ", blocks_,
             " blocks");
    blocks_data_ = std::make_unique<Block[]>(blocks_ * h.count);

    ByteReader in(data + h.dir_at, size - h.dir_at, what_);
    for (uint32_t ch = 0; ch < h.count; ++ch) {
        ChannelInfo c = read_channel_entry(in, what_);
        if (c.name.empty() || find(c.name) >= 0)
            fail(what_, ": channel ", ch + 1, " has no name or a name taken before");
        for (size_t b = 0; b < blocks_; ++b) {
            Block &block = blocks_data_[ch * blocks_ + b];
            block.offset = in.u64();
            block.compressed = in.u32();
            block.raw = in.u32();
            block.crc = in.u32();
            if (block.offset < h.header_size || block.offset > h.dir_at ||
                block.compressed > h.dir_at - block.offset)
                fail(what_, ": block ", b, " of channel ", c.name,
                     " lies outside the file's blocks (corrupt file)");
        }
        channels_.push_back(std::move(c));
    }
    read_kinds(in, h.minor, channels_, what_);
    blocks_begin_ = h.header_size;
    blocks_end_ = h.dir_at;

    // where each cell's span lies in its block
    slots_.resize(size_t(f.cells()));
    block_values_.assign(blocks_, 0);
    for (int row = 0; row < rows_; ++row)
        for (int col = 0; col < cols_; ++col) {
            const uint64_t cell = model.cell_index(row, col);
            const ColumnSpan span = solid_span(model, cell);
            uint32_t &filled = block_values_[block_of(cell)];
            if (uint64_t(filled) + span.size() > UINT32_MAX)
                fail(what_, ": a block of more than 2^32 values");
            slots_[cell] = {span.lo, span.hi, filled};
            filled += span.size();
            values_ += span.size();
        }
}

PropertyChannels::~PropertyChannels() = default;

int PropertyChannels::find(const std::string &name) const
{
    for (size_t i = 0; i < channels_.size(); ++i)
        if (channels_[i].name == name)
            return int(i);
    return -1;
}

size_t PropertyChannels::block_of(uint64_t cell) const
{
    const size_t row = size_t(cell / uint64_t(cols_)), col = size_t(cell % uint64_t(cols_));
    return (row / size_t(block_size_)) * size_t(block_cols_) + col / size_t(block_size_);
}

namespace {

/// base + each 1-byte code: the first 16 * runs in a loop the compiler
/// vectorises (GCC 12 at -O2: a count it knows is a multiple of 16, over
/// pointers that alias nothing), then the rest.
void widen_bytes(const uint8_t *__restrict codes, int32_t base, size_t size,
                 int32_t *__restrict out)
{
    const size_t runs = size / 16;
    for (size_t i = 0; i < runs << 4; ++i)
        out[i] = base + int32_t(codes[i]);
    for (size_t i = runs << 4; i < size; ++i)
        out[i] = base + int32_t(codes[i]);
}

} // namespace

void ChannelValues::whole_into(int32_t *out) const
{
    if (width_ == 1) {
        widen_bytes(codes_, base_, size_, out);
        return;
    }
    for (size_t i = 0; i < size_; ++i) // (2-byte codes: no cheap vector form)
        out[i] = int32_t(whole(i));
}

ChannelValues PropertyChannels::block_values(size_t channel, size_t b) const
{
    Block &block = blocks_data_[channel * blocks_ + b];
    std::call_once(block.once, [&] {
        const std::string where = what_ + ", channel " + channels_[channel].name +
                                  ", block " + std::to_string(b);
        const uint8_t *src = file_->data() + block.offset;
        if (crc32_of(src, block.compressed) != block.crc)
            fail(where, ": checksum mismatch (corrupt file)");
        const size_t expected = BLOCK_HEAD + size_t(block_values_[b]) * 4;
        if (block.raw > expected)
            fail(where, ": says it holds ", block.raw, " bytes, more than its cells can");
        // not zeroed first: decompression writes every byte or fails
        std::unique_ptr<uint8_t[]> raw(new uint8_t[std::max<size_t>(block.raw, 1)]);
        const size_t n = ZSTD_decompress(raw.get(), block.raw, src, block.compressed);
        if (ZSTD_isError(n) || n != block.raw)
            fail(where, ": does not decompress to its stated size (corrupt file)");
        // the block's cells, row by row, in the order they were written
        const size_t brow = b / size_t(block_cols_), bcol = b % size_t(block_cols_);
        std::vector<CellSlot> cells;
        for (int r = int(brow) * block_size_; r < std::min(rows_, int(brow + 1) * block_size_); ++r)
            for (int c = int(bcol) * block_size_; c < std::min(cols_, int(bcol + 1) * block_size_); ++c)
                cells.push_back(slots_[uint64_t(r) * uint64_t(cols_) + uint64_t(c)]);
        block.codes = decode_block(std::move(raw), block.raw, cells.data(), cells.size(),
                                   block_values_[b], where);
        ++decoded_;
    });
    const DecodedCodes &d = block.codes;
    return {d.bytes.get() + d.at, d.width, d.float_bits, d.base, block_values_[b]};
}

ChannelValues PropertyChannels::column(size_t channel, uint64_t cell) const
{
    const CellSlot &s = slots_[cell];
    if (s.hi == s.lo)
        return {};
    return block_values(channel, block_of(cell)).part(s.at, s.hi - s.lo);
}

void PropertyChannels::write_with(const std::vector<ChannelInfo> &infos,
                                  ByteSink &sink) const
{
    if (infos.size() != channels_.size())
        fail(what_, ": ", infos.size(), " channels given for the file's ",
             channels_.size());
    for (size_t ch = 0; ch < infos.size(); ++ch)
        if (infos[ch].name != channels_[ch].name)
            fail(what_, ": channel ", ch + 1, " is ", channels_[ch].name, ", not ",
                 infos[ch].name);
    if (sink.size() != 0)
        fail(what_, ": channels written again into a sink that is not empty");
    // the header last (as the writer does), the blocks as they are, moved
    // by the difference in header sizes
    const std::vector<uint8_t> zeros(CHANNELS_HEADER_SIZE, 0);
    sink.append(zeros.data(), zeros.size());
    const int64_t shift = int64_t(CHANNELS_HEADER_SIZE) - int64_t(blocks_begin_);
    const uint8_t *data = file_->data();
    constexpr uint64_t PIECE = uint64_t(1) << 24;
    for (uint64_t at = blocks_begin_; at < blocks_end_; at += PIECE)
        sink.append(data + at, size_t(std::min(PIECE, blocks_end_ - at)));
    ByteWriter dir;
    for (size_t ch = 0; ch < channels_.size(); ++ch) {
        ChannelInfo c = channels_[ch]; // the figures as they are
        c.long_name = infos[ch].long_name;
        c.unit = infos[ch].unit;
        c.kind = infos[ch].known_kind();
        write_channel_entry(dir, c);
        for (size_t b = 0; b < blocks_; ++b) {
            const Block &block = blocks_data_[ch * blocks_ + b];
            write_block_entry(dir, uint64_t(int64_t(block.offset) + shift),
                              block.compressed, block.raw, block.crc);
        }
    }
    write_kinds(dir, infos);
    const uint64_t dir_at = sink.size();
    sink.append(dir.bytes().data(), dir.size());
    ByteWriter h = header_bytes(rows_, cols_, block_size_, channels_.size(), dir_at,
                                sink.size(), crc32_of(dir.bytes().data(), dir.size()));
    sink.overwrite(0, h.bytes().data(), h.size());
}

} // namespace sbrt
