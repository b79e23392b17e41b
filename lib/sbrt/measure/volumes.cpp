/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Volumes of class sets per zone from the intervals
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/volumes.hpp"

#include <algorithm>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

/// The sets each material of `table` belongs to.
std::vector<std::vector<uint32_t>> sets_of_materials(size_t materials,
                                                      const std::vector<ClassSet> &sets)
{
    std::vector<std::vector<uint32_t>> of(materials);
    for (uint32_t s = 0; s < sets.size(); ++s)
        for (uint32_t m : sets[s].materials())
            of.at(m).push_back(s);
    return of;
}

} // namespace

/// Adds the columns of the whole model's rows [first, last), held by
/// `band` from its row 0 = model row `band_first`, to `sums`.
template <typename Record>
void VolumeSums::add_rows(const Model &band, const Record *records, int band_first, int first,
                          int last, Sums &sums) const
{
    std::vector<double> column(sets_.size(), 0.0);
    std::vector<uint32_t> touched;
    const size_t set_count = sets_.size();
    for (int r = first; r < last; ++r)
        for (int c = 0; c < frame_.cols; ++c) {
            const int32_t zone = zones_.zone(uint64_t(r) * uint64_t(frame_.cols) + uint64_t(c));
            if (zone == CellZones::NO_ZONE)
                continue;
            // the column's thickness per set
            const StackRange stack = band.stack(band.cell_index(r - band_first, c));
            double below = 0;
            for (uint64_t i = stack.begin; i < stack.end; ++i) {
                const double top = double(records[i].top);
                for (uint32_t s : sets_of_[records[i].material]) {
                    if (column[s] == 0)
                        touched.push_back(s);
                    column[s] += top - below;
                }
                below = top;
            }
            // into the zone's sums
            for (uint32_t s : touched) {
                const size_t k = size_t(zone) * set_count + s;
                sums.thickness[k] += column[s];
                sums.cells[k] += 1;
                column[s] = 0;
            }
            touched.clear();
        }
}

std::vector<ClassSet> every_class(const std::vector<Material> &table)
{
    std::vector<uint32_t> materials;
    for (uint32_t m = 1; m < table.size(); ++m)
        materials.push_back(m);
    std::sort(materials.begin(), materials.end(),
              [&](uint32_t a, uint32_t b) { return table[a].id < table[b].id; });
    std::vector<ClassSet> sets;
    for (uint32_t m : materials)
        sets.push_back(ClassSet::of_materials(table, {m}));
    return sets;
}

std::vector<ClassSet> every_class(const Model &model) { return every_class(model.materials()); }

VolumeSums::VolumeSums(const Frame &frame, size_t materials, const std::vector<ClassSet> &sets,
                       const CellZones &zones, unsigned threads)
    : frame_(frame), sets_(sets), zones_(zones), threads_(threads),
      sets_of_(sets_of_materials(materials, sets)),
      // a fixed number of row blocks, summed in their order at the end
      block_sums_(size_t(std::min(frame.rows, 32)))
{
    if (zones.cell_zones().size() != frame.cells())
        fail("measure_volumes: zones for ", zones.cell_zones().size(), " cells, the model has ",
             frame.cells());
    const size_t n = sets.size() * size_t(zones.zones());
    for (Sums &sums : block_sums_) {
        sums.thickness.assign(n, 0.0);
        sums.cells.assign(n, 0);
    }
}

void VolumeSums::add_band(const Model &band, int first_row)
{
    const int blocks = int(block_sums_.size());
    const int band_end = first_row + band.frame().rows;
    if (first_row < 0 || band_end > frame_.rows || band.frame().cols != frame_.cols)
        fail("measure_volumes: a band of rows ", first_row, " to ", band_end - 1,
             " is not part of the model");
    // each row block's rows within the band, added in row order to the
    // block's sums: the same additions in the same order whatever the bands
    band.intervals().visit([&](const auto *records) {
        for_each_row(blocks, threads_, [&](int b) {
            const int first = std::max(first_row, int(int64_t(frame_.rows) * b / blocks));
            const int last = std::min(band_end, int(int64_t(frame_.rows) * (b + 1) / blocks));
            if (first < last)
                add_rows(band, records, first_row, first, last, block_sums_[size_t(b)]);
        });
        return 0;
    });
}

VolumeTable VolumeSums::table() const
{
    VolumeTable table(sets_.size(), zones_.zones());
    const double area = frame_.ns_res() * frame_.ew_res();
    for (int z = 0; z < zones_.zones(); ++z)
        for (size_t s = 0; s < sets_.size(); ++s) {
            const size_t k = size_t(z) * sets_.size() + s;
            double local = 0;
            uint64_t cells = 0;
            for (const Sums &sums : block_sums_) {
                local += sums.thickness[k];
                cells += sums.cells[k];
            }
            Volume &v = table.at(z, s);
            v.thickness = local * frame_.tb_res();
            v.volume = v.thickness * area;
            v.cells = cells;
        }
    return table;
}

VolumeTable measure_volumes(const Model &model, const std::vector<ClassSet> &sets,
                            const CellZones &zones, unsigned threads)
{
    VolumeSums sums(model.frame(), model.materials().size(), sets, zones, threads);
    sums.add_band(model, 0);
    return sums.table();
}

} // namespace sbrt
