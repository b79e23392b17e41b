/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Colours by voxel on the GPU: the `buffer Paint` words
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu/gpu_paint.hpp"

#include <climits>
#include <cmath>
#include <cstring>

#include "gpu/gpu_overlays.hpp"
#include "model/material_table.hpp"
#include "shading/property_paint.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

constexpr size_t HEAD_WORDS = 4;

const PropertyChannels &painted_channels(const Shading &shading)
{
    return shading.property ? shading.property->channels() : shading.fade->channels();
}

const WholeValues &painted_whole(const Shading &shading)
{
    return shading.property ? shading.property->whole() : shading.fade->whole();
}

/// Colours in the table: a property's per value and its no-value colour;
/// a fade's per class of `model`, per value and the class's own.
uint64_t colour_count(const Model &model, const Shading &shading)
{
    const uint64_t entries = painted_whole(shading).count + 1;
    return shading.property ? entries : uint64_t(model.materials().size()) * entries;
}

/// The colours before lighting, entry by entry (GPU_PAINT_NONE's last).
std::vector<glm::dvec3> paint_colours(const Model &model, const Shading &shading)
{
    if (shading.property)
        return shading.property->entry_colors();
    std::vector<glm::dvec3> colours;
    for (size_t m = 0; m < model.materials().size(); ++m) {
        const auto rgb = material_color(model, uint32_t(m));
        const std::vector<glm::dvec3> entries =
            shading.fade->entry_colors(glm::dvec3(rgb[0], rgb[1], rgb[2]));
        colours.insert(colours.end(), entries.begin(), entries.end());
    }
    return colours;
}

/// \brief A summed channel's value in integers: raw * scale + offset, and
/// whether raw is the fill, exactly as sum_at finds them in double, for
/// codes whose values are whole (ChannelValues::whole_codes) where scale,
/// offset and fill are whole and small enough that no sum of them leaves
/// the integers double holds exactly.
struct WholeTerm {
    bool usable = false, has_fill = false;
    int64_t fill = 0, scale = 1, offset = 0;

    explicit WholeTerm(const ChannelInfo &info)
    {
        const auto whole = [](double v, double most) {
            return std::isfinite(v) && v == std::round(v) && std::abs(v) <= most;
        };
        usable = whole(info.scale, 1024) && whole(info.offset, 1 << 30) &&
                 (!info.has_fill || whole(double(info.fill), 1 << 24));
        if (!usable)
            return;
        has_fill = info.has_fill;
        fill = has_fill ? int64_t(info.fill) : 0;
        scale = int64_t(info.scale);
        offset = int64_t(info.offset);
    }
};

/// \brief The summed channels' terms in integers, usable where every
/// term is (WholeTerm) and the values' low is whole (the stated range is
/// not trusted: a low with a fraction has no whole value, every voxel
/// outside, as WholeValues::index finds).
struct WholeSum {
    std::vector<WholeTerm> terms;
    bool usable = true;
    int64_t low = 0, count = 0;
    /// Where a voxel's sum less the low starts: the terms' offsets less
    /// the low.
    int64_t start = 0;

    WholeSum(const PropertyChannels &channels, const std::vector<size_t> &summed,
             const WholeValues &whole)
    {
        for (size_t c : summed) {
            terms.emplace_back(channels.info(c));
            usable = usable && terms.back().usable;
        }
        usable = usable && std::abs(whole.low) < double(int64_t(1) << 52) &&
                 whole.low == std::floor(whole.low);
        low = usable ? int64_t(whole.low) : 0;
        count = int64_t(whole.count);
        start = -low;
        for (const WholeTerm &term : terms)
            start += term.offset;
    }
};

/// A voxel's entry: none where it has no value, else its value's index
/// (-1: outside the values, GPU_PAINT_OUTSIDE).
uint32_t paint_entry(bool has, int64_t index)
{
    return !has ? GPU_PAINT_NONE : index < 0 ? GPU_PAINT_OUTSIDE : uint32_t(index);
}

// The loops over a column's values below run over 16 * runs of them (the
// column padded): a count the compiler knows is a multiple of 16, over
// pointers that alias nothing, which it vectorises (GCC 12 at -O2, as
// Debian's builds).

/// has[i] &= raw[i] != fill over [0, 16 * runs).
void clear_fills(uint8_t *__restrict has, const int32_t *__restrict raw, int32_t fill,
                 size_t runs)
{
    for (size_t i = 0; i < runs << 4; ++i)
        has[i] &= uint8_t(raw[i] != fill);
}

/// sum[i] += raw[i] * scale over [0, 16 * runs).
void add_scaled(int64_t *__restrict sum, const int32_t *__restrict raw, int64_t scale,
                size_t runs)
{
    if (scale == 1) {
        for (size_t i = 0; i < runs << 4; ++i)
            sum[i] += raw[i];
        return;
    }
    for (size_t i = 0; i < runs << 4; ++i)
        sum[i] += int64_t(raw[i]) * scale;
}

/// Each voxel's entry from its sum less the low and whether it has a value
/// (paint_entry, in 16 bits), over [0, 16 * runs).
void entries_of(const int64_t *__restrict sum, const uint8_t *__restrict has, int64_t count,
                uint16_t *__restrict entry, size_t runs)
{
    for (size_t i = 0; i < runs << 4; ++i) {
        const bool inside = uint64_t(sum[i]) < uint64_t(count); // 0 <= sum < count
        entry[i] = uint16_t(paint_entry(has[i] != 0, inside ? sum[i] : -1));
    }
}

/// The entries of voxels [0, size) of a cell whose summed channels' values
/// are `columns`, into `out` (16 bits each, little-endian): in integers where the sum and
/// every column allow (WholeSum, ChannelValues::whole_codes), a channel at
/// a time over the whole column, else through sum_at.
void cell_entries(const PropertyChannels &channels, const std::vector<size_t> &summed,
                  const WholeSum &in_whole, const ChannelValues *columns,
                  const WholeValues &whole, uint32_t size, unsigned char *out)
{
    bool in_integers = in_whole.usable;
    for (size_t k = 0; k < summed.size(); ++k)
        in_integers = in_integers && columns[k].whole_codes();
    if (!in_integers) {
        for (uint32_t i = 0; i < size; ++i) {
            double sum;
            const bool has = sum_at(channels, summed, columns, i, sum);
            const uint16_t entry = uint16_t(paint_entry(has, has ? whole.index(sum) : -1));
            std::memcpy(out + 2 * size_t(i), &entry, 2);
        }
        return;
    }
    // a column is at most 65,535 voxels (gpu_paints); each thread's own,
    // padded to a multiple of 16 (clear_fills): the values past `size` are
    // zeroes, never copied out.
    const size_t runs = (size_t(size) + 15) / 16, padded = 16 * runs;
    thread_local std::vector<int32_t> raw;
    thread_local std::vector<int64_t> sum;
    thread_local std::vector<uint8_t> has;
    thread_local std::vector<uint16_t> entries;
    raw.assign(padded, 0);
    has.assign(padded, 1);
    sum.assign(padded, in_whole.start);
    for (size_t k = 0; k < summed.size(); ++k) {
        const WholeTerm &term = in_whole.terms[k];
        columns[k].whole_into(raw.data());
        if (term.has_fill)
            clear_fills(has.data(), raw.data(), int32_t(term.fill), runs);
        add_scaled(sum.data(), raw.data(), term.scale, runs);
    }
    entries.resize(padded);
    entries_of(sum.data(), has.data(), in_whole.count, entries.data(), runs);
    std::memcpy(out, entries.data(), 2 * size_t(size)); // (little-endian, as the words)
}

} // namespace

bool gpu_paints(const Tracer &tracer, const Shading &shading, const Outputs &outputs)
{
    if (!shading.property == !shading.fade || shading.drape ||
        shading.normals != Normals::face || outputs.value ||
        gpu_overlay_mode(tracer) != GpuOverlayMode::none)
        return false;
    const WholeValues &whole = painted_whole(shading);
    if (whole.count == 0 || whole.count >= GPU_PAINT_OUTSIDE ||
        (shading.fade && colour_count(tracer.model(), shading) > GPU_PAINT_MAX_COLOURS))
        return false;
    const Frame &f = tracer.model().frame();
    const PropertyChannels &channels = painted_channels(shading);
    return f.depths < 65536 && channels.blocks() > 0 && f.cells() == channels.cells() &&
           channels.values() <= GPU_PAINT_MAX_VOXELS;
}

uint64_t gpu_paint_bytes(const Tracer &tracer, const Shading &shading)
{
    return 4 * (HEAD_WORDS + 2 * tracer.model().frame().cells()) +
           4 * ((painted_channels(shading).values() + 1) / 2) +
           12 * colour_count(tracer.model(), shading);
}

std::string gpu_paint_key(const Shading &shading)
{
    if (!shading.property && !shading.fade)
        return {};
    std::string key = shading.property ? "property" : "fade";
    auto add = [&](const void *p, size_t n) { key.append(static_cast<const char *>(p), n); };
    const PropertyChannels *channels = &painted_channels(shading);
    add(&channels, sizeof channels);
    if (shading.property) {
        for (size_t c : shading.property->summed())
            add(&c, sizeof c);
    } else {
        const size_t c = shading.fade->channel();
        add(&c, sizeof c);
    }
    const WholeValues &whole = painted_whole(shading);
    add(&whole.low, sizeof whole.low);
    add(&whole.count, sizeof whole.count);
    // the colours follow from the ramp, the no-value colour and the fade's
    // range: the property's table and the fade's ends say them
    if (shading.property) {
        for (const glm::dvec3 &c : shading.property->table())
            add(&c, sizeof c);
        add(&shading.property->no_value(), sizeof(glm::dvec3));
    } else {
        const double ends[2] = {shading.fade->low(), shading.fade->high()};
        add(ends, sizeof ends);
    }
    return key;
}

std::vector<uint32_t> make_gpu_paint(const Tracer &tracer, const Shading &shading,
                                     unsigned threads)
{
    const Model &model = tracer.model();
    const Frame &f = model.frame();
    if (!gpu_paints(tracer, shading, Outputs{}))
        fail("a GPU paint of a shading the GPU does not colour");
    const PropertyChannels &channels = painted_channels(shading);
    const WholeValues &whole = painted_whole(shading);
    const uint64_t cells = f.cells();

    // each cell's span where the prepared model keeps its stack, and the
    // blocks that hold one
    std::vector<uint32_t> words(HEAD_WORDS + 2 * cells, 0);
    std::vector<char> block_needed(channels.blocks(), 0);
    uint64_t entries = 0;
    for (uint64_t cell = 0; cell < cells; ++cell) {
        const ColumnSpan span = model.stack(cell).size() == 0 ? ColumnSpan{} : channels.span(cell);
        if (entries + span.size() > UINT32_MAX)
            fail("a GPU paint of more than 2^32 voxels");
        words[HEAD_WORDS + 2 * cell] = uint32_t(entries);
        words[HEAD_WORDS + 2 * cell + 1] = span.lo | span.hi << 16;
        entries += span.size();
        if (span.size() > 0)
            block_needed[channels.block_of(cell)] = 1;
    }

    // the summed channels' blocks decoded first, each by one thread (a
    // model's few large blocks would leave most threads idle if the entries
    // went block by block), then each voxel's entry, a row of cells a take
    const std::vector<size_t> summed =
        shading.property ? shading.property->summed() : std::vector<size_t>{shading.fade->channel()};
    const int64_t blocks = int64_t(channels.blocks()), tasks = blocks * int64_t(summed.size());
    if (tasks <= INT_MAX) // (else each block is decoded below where first needed)
        for_each_row(int(tasks), threads, [&](int task) {
            if (block_needed[size_t(task % blocks)])
                channels.block_values(summed[size_t(task / blocks)], size_t(task % blocks));
        });
    // the entries go straight into their words, two a word (the first in
    // the low half: little-endian bytes), and the colours after them
    const std::vector<glm::dvec3> colours = paint_colours(model, shading);
    const size_t entries_at = words.size(), colours_at = entries_at + (entries + 1) / 2;
    words.resize(colours_at + 3 * colours.size()); // (zeroes: an odd count's last half)
    unsigned char *entry_bytes = reinterpret_cast<unsigned char *>(words.data() + entries_at);
    const WholeSum in_whole(channels, summed, whole);
    for_each_row(f.rows, threads, [&](int row) {
        std::vector<ChannelValues> columns(summed.size());
        for (int col = 0; col < f.cols; ++col) {
            const uint64_t cell = model.cell_index(row, col);
            const uint32_t at = words[HEAD_WORDS + 2 * cell];
            const uint32_t span = words[HEAD_WORDS + 2 * cell + 1];
            const uint32_t size = (span >> 16) - (span & 0xffff);
            if (size == 0)
                continue;
            for (size_t k = 0; k < summed.size(); ++k)
                columns[k] = channels.column(summed[k], cell);
            cell_entries(channels, summed, in_whole, columns.data(), whole, size,
                         entry_bytes + 2 * uint64_t(at));
        }
    });
    for (size_t k = 0; k < colours.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            const float v = float(colours[k][c]);
            std::memcpy(&words[colours_at + 3 * k + size_t(c)], &v, 4);
        }
    words[0] = uint32_t(entries_at);
    words[1] = uint32_t(colours_at);
    words[2] = shading.fade ? uint32_t(whole.count + 1) : 0;
    words[3] = uint32_t(whole.count); // GPU_PAINT_NONE's colour
    return words;
}

} // namespace sbrt
