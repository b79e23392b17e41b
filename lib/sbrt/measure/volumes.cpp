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

/// Sums in local units (exact integers for voxel models) for one block.
struct Sums {
    std::vector<double> thickness;
    std::vector<uint64_t> cells;
};

/// The sets each material belongs to.
std::vector<std::vector<uint32_t>> sets_of_materials(const Model &model,
                                                      const std::vector<ClassSet> &sets)
{
    std::vector<std::vector<uint32_t>> of(model.materials().size());
    for (uint32_t s = 0; s < sets.size(); ++s)
        for (uint32_t m : sets[s].materials())
            of.at(m).push_back(s);
    return of;
}

/// Adds the columns of model rows [first, last) to `sums`.
template <typename Record>
void add_rows(const Model &model, const Record *records, int first, int last,
              const std::vector<std::vector<uint32_t>> &sets_of, const CellZones &zones,
              size_t set_count, Sums &sums, std::vector<double> &column)
{
    std::vector<uint32_t> touched;
    for (int r = first; r < last; ++r)
        for (int c = 0; c < model.frame().cols; ++c) {
            const uint64_t cell = model.cell_index(r, c);
            const int32_t zone = zones.zone(cell);
            if (zone == CellZones::NO_ZONE)
                continue;
            // the column's thickness per set
            const StackRange stack = model.stack(cell);
            double below = 0;
            for (uint64_t i = stack.begin; i < stack.end; ++i) {
                const double top = double(records[i].top);
                for (uint32_t s : sets_of[records[i].material]) {
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

} // namespace

std::vector<ClassSet> every_class(const Model &model)
{
    std::vector<uint32_t> materials;
    for (uint32_t m = 1; m < model.materials().size(); ++m)
        materials.push_back(m);
    std::sort(materials.begin(), materials.end(), [&](uint32_t a, uint32_t b) {
        return model.materials()[a].id < model.materials()[b].id;
    });
    std::vector<ClassSet> sets;
    for (uint32_t m : materials)
        sets.push_back(ClassSet::of_materials(model, {m}));
    return sets;
}

VolumeTable measure_volumes(const Model &model, const std::vector<ClassSet> &sets,
                            const CellZones &zones, unsigned threads)
{
    const Frame &f = model.frame();
    if (zones.cell_zones().size() != f.cells())
        fail("measure_volumes: zones for ", zones.cell_zones().size(), " cells, the model has ",
             f.cells());
    const auto sets_of = sets_of_materials(model, sets);
    const size_t n = sets.size() * size_t(zones.zones());
    // a fixed number of row blocks, summed in their order afterwards
    const int blocks = std::min(f.rows, 32);
    std::vector<Sums> block_sums(static_cast<size_t>(blocks));
    model.intervals().visit([&](const auto *records) {
        for_each_row(blocks, threads, [&](int b) {
            Sums &sums = block_sums[size_t(b)];
            sums.thickness.assign(n, 0.0);
            sums.cells.assign(n, 0);
            std::vector<double> column(sets.size(), 0.0);
            const int first = int(int64_t(f.rows) * b / blocks);
            const int last = int(int64_t(f.rows) * (b + 1) / blocks);
            add_rows(model, records, first, last, sets_of, zones, sets.size(), sums, column);
        });
        return 0;
    });
    VolumeTable table(sets.size(), zones.zones());
    const double area = f.ns_res() * f.ew_res();
    for (int z = 0; z < zones.zones(); ++z)
        for (size_t s = 0; s < sets.size(); ++s) {
            const size_t k = size_t(z) * sets.size() + s;
            double local = 0;
            uint64_t cells = 0;
            for (const Sums &sums : block_sums) {
                local += sums.thickness[k];
                cells += sums.cells[k];
            }
            Volume &v = table.at(z, s);
            v.thickness = local * f.tb_res();
            v.volume = v.thickness * area;
            v.cells = cells;
        }
    return table;
}

} // namespace sbrt
