/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Random voxel models with fixed seeds for the library tests
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TEST_SUPPORT_HPP
#define SBRT_TEST_SUPPORT_HPP

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "format/byte_sink.hpp"
#include "format/channels_file.hpp"
#include "tracing/cpu_tracing.hpp"
#include "model/model.hpp"
#include "scene/scene.hpp"
#include "shading/shading.hpp"
#include "builders/voxel_builder.hpp"

namespace sbrt_test {

/// Voxels of a frame, index ((depth * rows) + row) * cols + col.
struct Voxels {
    sbrt::Frame frame;
    std::vector<int32_t> classes;
    const int32_t *slice(int depth) const
    {
        return classes.data() + size_t(depth) * frame.cells();
    }
};

/// Columns of random runs: classes 1..class_count, NULL runs (caves, air),
/// runs of one voxel included.
inline Voxels random_voxels(unsigned seed, int rows, int cols, int depths,
                            int class_count = 12)
{
    std::mt19937 rng(seed);
    Voxels v;
    v.frame.rows = rows;
    v.frame.cols = cols;
    v.frame.depths = depths;
    v.frame.north = 1000 + rows * 10.0;
    v.frame.south = 1000;
    v.frame.west = 500;
    v.frame.east = 500 + cols * 5.0;
    v.frame.bottom = -50;
    v.frame.top = -50 + depths * 2.0;
    v.classes.assign(v.frame.voxels(), sbrt::NULL_CLASS);
    std::uniform_int_distribution<int> run_length(1, std::max(1, depths / 4));
    std::uniform_int_distribution<int> pick(0, class_count);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            int z = 0;
            while (z < depths) {
                const int len = std::min(depths - z, run_length(rng));
                const int k = pick(rng);
                const int32_t id = k == 0 ? sbrt::NULL_CLASS : k * 7 - 20;
                for (int i = 0; i < len; ++i, ++z)
                    v.classes[(size_t(z) * rows + r) * cols + c] = id;
            }
        }
    return v;
}

/// A model with `stack` intervals of continuous (non-integer) tops in
/// every cell, over `materials` materials.
inline sbrt::Model float_model(int rows, int cols, int stack, int materials)
{
    sbrt::Frame f;
    f.rows = rows;
    f.cols = cols;
    f.depths = 40;
    std::vector<sbrt::Material> table(size_t(materials) + 1);
    for (int i = 1; i <= materials; ++i)
        table[size_t(i)].id = i * 3;
    std::vector<uint32_t> offsets(f.cells() + 1, 0);
    sbrt::Intervals intervals;
    std::mt19937 rng(7);
    for (uint64_t c = 0; c < f.cells(); ++c) {
        const int n = 1 + int(rng() % unsigned(stack));
        for (int i = 0; i < n; ++i) {
            const float top = 40.0f * float(i + 1) / float(n) - 0.013f * float(c % 7);
            intervals.push_back({1 + uint32_t(rng() % unsigned(materials)), top});
            if (i > 0 && intervals[intervals.size() - 2].material == intervals.back().material)
                intervals.back().material = intervals.back().material % uint32_t(materials) + 1;
        }
        offsets[c + 1] = uint32_t(intervals.size());
    }
    return sbrt::Model(f, std::move(table), std::move(offsets), sbrt::IntervalArray(std::move(intervals)));
}

/// The SBRT of a voxel model, built slice by slice.
inline sbrt::Model build_model(const Voxels &v)
{
    sbrt::VoxelStackBuilder builder(v.frame);
    for (int z = 0; z < v.frame.depths; ++z)
        builder.add_slice(v.slice(z));
    return builder.finish();
}

/// A top view of the whole frame, one pixel per cell, from `above`.
inline sbrt::Camera top_camera(const sbrt::Frame &f, double above)
{
    return sbrt::Camera::top(f.north, f.south, f.east, f.west, above, f.rows, f.cols);
}

/// The CPU reference image of a model seen by `camera`.
inline sbrt::Image render_cpu(const sbrt::Model &m, const sbrt::Camera &camera,
                              double zexag, unsigned threads = 2)
{
    const sbrt::Tracer tracer(m, zexag);
    return sbrt::shade(tracer, camera, sbrt::trace_image(tracer, camera, threads),
                       sbrt::Shading{}, threads);
}

/// The same model with its intervals held wide (8 bytes, as horizon models
/// and mapped v1 files hold them): a view keeps them from being packed.
inline sbrt::Model widened(const sbrt::Model &m)
{
    auto wide = std::make_shared<std::vector<sbrt::Interval>>(m.intervals().size());
    for (size_t i = 0; i < wide->size(); ++i)
        (*wide)[i] = m.intervals()[i];
    sbrt::IntervalArray view(wide, wide->data(), wide->size());
    sbrt::Model out(m.frame(), m.materials(), m.index(), std::move(view));
    return out;
}

/// A borehole at map (x, y) showing the model's own stack there.
inline sbrt::Borehole borehole_at(const sbrt::Model &m, double x, double y)
{
    const sbrt::Frame &f = m.frame();
    const int col = int(std::floor((x - f.west) / f.ew_res()));
    const int row = int(std::floor((f.north - y) / f.ns_res()));
    const uint64_t cell = m.cell_index(row, col);
    sbrt::Borehole b;
    b.x = x;
    b.y = y;
    b.stack = m.stack_intervals(cell);
    b.model_stack = b.stack;
    return b;
}

/// A scene with a vertical clip plane through the model's centre and
/// material 1 translucent (alpha 0.3 per cell), the rest opaque.
inline sbrt::Scene cut_and_translucent_scene(const sbrt::Model &m)
{
    const sbrt::Frame &f = m.frame();
    sbrt::Scene scene;
    scene.planes = {{{(f.west + f.east) / 2, (f.south + f.north) / 2, 0}, {1, 0.5, 0}}};
    scene.translucency.length = f.ew_res();
    scene.translucency.extinction.assign(m.materials().size(), INFINITY);
    scene.translucency.color.assign(m.materials().size(), glm::dvec3(0.2, 0.5, 0.9));
    scene.translucency.extinction[1] = sbrt::extinction_of(0.3, f.ew_res());
    return scene;
}

/// \brief The first solid voxel along a ray, found without the SBRT.
struct VoxelHit {
    bool hit = false;
    int32_t id = sbrt::NULL_CLASS;
    double t = INFINITY;
    int x = -1, y = -1, z = -1; ///< the voxel: column, row from the south, level
};

/// 3D DDA over voxels in the voxel frame (x east, y north, z up, unit
/// cells); returns the first non-null voxel. Independent of the SBRT.
inline VoxelHit march(const sbrt_test::Voxels &v, glm::dvec3 o, glm::dvec3 d)
{
    const sbrt::Frame &f = v.frame;
    const glm::dvec3 size(f.cols, f.rows, f.depths);
    double t0 = 0, t1 = INFINITY;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            if (o[a] < 0 || o[a] > size[a])
                return {};
            continue;
        }
        double ta = -o[a] / d[a], tb = (size[a] - o[a]) / d[a];
        if (ta > tb)
            std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (t0 > t1)
        return {};
    glm::ivec3 cell, step;
    glm::dvec3 t_max, t_delta;
    const glm::dvec3 p = o + t0 * d;
    for (int a = 0; a < 3; ++a) {
        cell[a] = std::clamp(int(std::floor(p[a])), 0, int(size[a]) - 1);
        step[a] = d[a] > 0 ? 1 : -1;
        t_max[a] = d[a] != 0 ? ((cell[a] + (d[a] > 0)) - o[a]) / d[a] : INFINITY;
        t_delta[a] = d[a] != 0 ? std::fabs(1 / d[a]) : INFINITY;
    }
    double t = t0;
    while (true) {
        const int row = f.rows - 1 - cell.y;
        const int32_t id =
            v.classes[(size_t(cell.z) * f.rows + row) * f.cols + cell.x];
        if (id != sbrt::NULL_CLASS)
            return {true, id, t, cell.x, cell.y, cell.z};
        const int a = t_max.x < t_max.y ? (t_max.x < t_max.z ? 0 : 2)
                                        : (t_max.y < t_max.z ? 1 : 2);
        if (t_max[a] > t1)
            return {};
        t = t_max[a];
        t_max[a] += t_delta[a];
        cell[a] += step[a];
        if (cell[a] < 0 || cell[a] >= int(size[a]))
            return {};
    }
}

/// Channel values for every voxel of the source, as the source holds it.
using Source = std::vector<std::vector<float>>; // [channel][voxel]

inline float source_value(const Source &s, const sbrt::Frame &f, size_t ch, uint64_t cell,
                   uint32_t level)
{
    return s[ch][size_t(level) * f.cells() + cell];
}

/// Writes the channels of `source` over `model`'s spans to `path`.
inline std::vector<sbrt::ChannelInfo> write_channels(const std::string &path, const sbrt::Model &model,
                                        const Source &source,
                                        std::vector<sbrt::ChannelInfo> infos, int block)
{
    const sbrt::Frame &f = model.frame();
    sbrt::FileSink sink(path);
    sbrt::ChannelsWriter writer(sink, f.rows, f.cols, block, std::move(infos), 2);
    std::vector<sbrt::ColumnSpan> spans(size_t(f.cols));
    std::vector<std::vector<float>> values(source.size());
    for (int row = 0; row < f.rows; ++row) {
        for (auto &v : values)
            v.clear();
        for (int col = 0; col < f.cols; ++col) {
            const uint64_t cell = model.cell_index(row, col);
            spans[size_t(col)] = sbrt::solid_span(model, cell);
            for (size_t ch = 0; ch < source.size(); ++ch)
                for (uint32_t z = spans[size_t(col)].lo; z < spans[size_t(col)].hi; ++z)
                    values[ch].push_back(source_value(source, f, ch, cell, z));
        }
        std::vector<const float *> pointers;
        for (auto &v : values)
            pointers.push_back(v.data());
        writer.add_row(spans.data(), pointers);
    }
    writer.finish();
    sink.finish();
    return writer.channels();
}

/// Whether two hits are the same bit for bit: class, the light of the
/// translucent strata in front, and (where they hit) t, point, face,
/// normal and clip plane.
inline bool identical_hits(const sbrt::Hit &a, const sbrt::Hit &b)
{
    if (a.material != b.material || a.transmittance != b.transmittance || a.veil != b.veil)
        return false;
    return !a.is_hit() || (a.t == b.t && a.point == b.point && a.face == b.face &&
                           a.normal == b.normal && a.plane == b.plane);
}

/// A frame of `rows` x `cols` cells of `cell` units a side and `depths`
/// layers of one unit, from (0, 0, 0).
inline sbrt::Frame unit_frame(int rows, int cols, int depths, double cell = 1)
{
    sbrt::Frame f;
    f.rows = rows;
    f.cols = cols;
    f.depths = depths;
    f.north = rows * cell;
    f.south = 0;
    f.east = cols * cell;
    f.west = 0;
    f.bottom = 0;
    f.top = depths;
    return f;
}

/// A random model of 70 x 90 cells and 24 depths of 5 classes (`seed`)
/// whose column 11 holds nothing but air on every seventh row.
inline sbrt::Model model_with_air_columns(unsigned seed)
{
    Voxels voxels = random_voxels(seed, 70, 90, 24, 5);
    for (int z = 0; z < voxels.frame.depths; ++z)
        for (int r = 0; r < voxels.frame.rows; r += 7)
            voxels.classes[(size_t(z) * voxels.frame.rows + r) * voxels.frame.cols + 11] =
                sbrt::NULL_CLASS;
    return build_model(voxels);
}

/// Writes `bytes` as the file `path` (a member damaged on purpose).
inline void put_file_bytes(const std::string &path, const std::vector<uint8_t> &bytes)
{
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
}

inline std::string temp_dir(const std::string &tag)
{
    std::string templ = "/tmp/sbrt_unit_" + tag + "_XXXXXX";
    return mkdtemp(templ.data());
}

} // namespace sbrt_test

#endif
