/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A selection by property: the voxels meeting a condition
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/voxel_selection.hpp"

#include <cmath>
#include <cstdlib>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

bool Selection::holds(double v) const
{
    switch (comparison) {
    case Comparison::greater_equal:
        return v >= threshold;
    case Comparison::greater:
        return v > threshold;
    case Comparison::less_equal:
        return v <= threshold;
    case Comparison::less:
        return v < threshold;
    case Comparison::equal:
        return v == threshold;
    case Comparison::not_equal:
        return v != threshold;
    }
    return false;
}

namespace {

std::string trimmed(const std::string &s)
{
    const size_t a = s.find_first_not_of(" \t");
    if (a == std::string::npos)
        return "";
    return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

} // namespace

Selection parse_selection(const std::string &text, const PropertyChannels &channels)
{
    static const struct {
        const char *op;
        Comparison comparison;
    } OPERATORS[] = {{">=", Comparison::greater_equal}, {"<=", Comparison::less_equal},
                     {"==", Comparison::equal},         {"!=", Comparison::not_equal},
                     {">", Comparison::greater},        {"<", Comparison::less}};
    Selection s;
    size_t at = std::string::npos, length = 0;
    for (const auto &o : OPERATORS) {
        const size_t found = text.find(o.op);
        if (found != std::string::npos) {
            at = found;
            length = std::string(o.op).size();
            s.comparison = o.comparison;
            break;
        }
    }
    if (at == std::string::npos)
        fail("'", text, "' is no condition: give channels, an operator (>=, >, <=, <, "
             "==, !=) and a number, e.g. kans_5+kans_6>=60");
    const std::string left = trimmed(text.substr(0, at));
    const std::string right = trimmed(text.substr(at + length));
    char *end = nullptr;
    s.threshold = std::strtod(right.c_str(), &end);
    if (right.empty() || *end != '\0' || !std::isfinite(s.threshold))
        fail("'", text, "': '", right, "' is not a number to compare with");
    if (left.empty())
        fail("'", text, "' names no channel: give one (or several joined by +) "
             "before the operator, e.g. kans_5>=60");
    std::string names;
    for (const ChannelInfo &c : channels.infos())
        names += (names.empty() ? "" : ", ") + c.name;
    for (size_t from = 0; from <= left.size();) {
        const size_t plus = std::min(left.find('+', from), left.size());
        const std::string name = trimmed(left.substr(from, plus - from));
        from = plus + 1;
        const int index = channels.find(name);
        if (index < 0)
            fail("'", text, "': no property channel '", name, "'; the SBRT has: ", names);
        s.channels.push_back(size_t(index));
    }
    const std::string &unit = channels.info(s.channels[0]).unit;
    for (size_t c : s.channels)
        if (channels.info(c).unit != unit)
            fail("'", text, "' adds channels of different units ('",
                 channels.info(s.channels[0]).name, "' and '", channels.info(c).name, "')");
    return s;
}

Model select_voxels(const Model &model, const PropertyChannels &channels,
                    const Selection &selection, unsigned threads)
{
    const Frame &f = model.frame();
    const uint64_t cells = f.cells();
    // per row of cells its stacks, then joined in order
    std::vector<std::vector<Interval>> rows(size_t(f.rows));
    std::vector<std::vector<uint32_t>> sizes(size_t(f.rows));
    for_each_row(f.rows, threads, [&](int row) {
        std::vector<Interval> &out = rows[size_t(row)];
        std::vector<uint32_t> &count = sizes[size_t(row)];
        std::vector<ChannelValues> columns(selection.channels.size());
        for (int col = 0; col < f.cols; ++col) {
            const uint64_t cell = model.cell_index(row, col);
            const size_t before = out.size();
            const ColumnSpan span = channels.span(cell);
            for (size_t k = 0; k < columns.size(); ++k)
                columns[k] = channels.column(selection.channels[k], cell);
            // walk the stack; voxels in the span keep their class where the
            // condition holds, all others of a solid interval go empty
            auto append = [&](uint32_t material, float top) {
                if (!out.empty() && out.size() > before && out.back().material == material)
                    out.back().top = top;
                else
                    out.push_back({material, top});
            };
            const StackRange range = model.stack(cell);
            float bottom = 0;
            for (uint64_t i = range.begin; i < range.end; ++i) {
                const Interval iv = model.intervals()[i];
                if (iv.material == EMPTY) {
                    append(EMPTY, iv.top);
                    bottom = iv.top;
                    continue;
                }
                for (uint32_t z = uint32_t(bottom); float(z) < iv.top; ++z) {
                    bool keep = span.holds(z);
                    double sum = 0;
                    for (size_t k = 0; keep && k < columns.size(); ++k) {
                        const float raw = columns[k][z - span.lo];
                        const ChannelInfo &info = channels.info(selection.channels[k]);
                        keep = !info.is_fill(raw);
                        sum += info.physical(raw);
                    }
                    append(keep && selection.holds(sum) ? iv.material : EMPTY, float(z + 1));
                }
                bottom = iv.top;
            }
            while (out.size() > before && out.back().material == EMPTY)
                out.pop_back(); // no trailing EMPTY
            count.push_back(uint32_t(out.size() - before));
        }
    });
    std::vector<uint32_t> offsets(cells + 1, 0);
    Intervals intervals;
    size_t total = 0;
    for (const auto &r : rows)
        total += r.size();
    intervals.resize(total);
    size_t at = 0;
    uint64_t cell = 0;
    for (int row = 0; row < f.rows; ++row) {
        std::copy(rows[size_t(row)].begin(), rows[size_t(row)].end(), intervals.begin() + long(at));
        at += rows[size_t(row)].size();
        for (const uint32_t n : sizes[size_t(row)]) {
            offsets[cell + 1] = offsets[cell] + n;
            ++cell;
        }
        std::vector<Interval>().swap(rows[size_t(row)]);
    }
    if (total > UINT32_MAX)
        fail("a selection of more than 2^32 intervals");
    return Model(f, model.materials(), offsets, IntervalArray::packed(std::move(intervals)));
}

} // namespace sbrt
