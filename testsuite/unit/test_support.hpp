/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Random voxel models with fixed seeds for the library tests
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TEST_SUPPORT_HPP
#define SBRT_TEST_SUPPORT_HPP

#include <cmath>
#include <random>
#include <string>
#include <vector>

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

inline std::string temp_dir(const std::string &tag)
{
    std::string templ = "/tmp/sbrt_unit_" + tag + "_XXXXXX";
    return mkdtemp(templ.data());
}

} // namespace sbrt_test

#endif
