/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The GPU path (compute shader through EGL or OSMesa; llvmpipe
 *            on machines without a GPU) against the exact CPU tracer: the
 *            block layout, agreement from many cameras, the loop budget
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tracing/cpu_tracing.hpp"
#include "util/error.hpp"
#include "gpu_model.hpp"
#include "gpu_renderer.hpp"
#include "gpu_row_tracer.hpp"
#include "gpu_tracer.hpp"
#include "program_cache.hpp"
#include "scene/hidden_materials.hpp"
#include "shading/drape.hpp"
#include "gpu_compare.hpp"
#include "gpu/gpu_memory_layout.hpp"
#include "gpu/gpu_overlays.hpp"
#include "renderer.hpp"
#include "test_support.hpp"

using namespace sbrt;
using namespace sbrt_test;

namespace {

/// Each test runs on every GL backend and in both GPU memory layouts, and
/// on EGL with a GPU's branches (gpu_variants).
class Gpu : public GpuVariantTest {};

INSTANTIATE_TEST_SUITE_P(Backends, Gpu, ::testing::ValuesIn(gpu_variants()), variant_name);

} // namespace

TEST_P(Gpu, ReportsItsVersionAndRenderer)
{
    const Model m = geology(8, 8, 6);
    const Tracer tracer(m, 1.0);
    sbrt_gl::GpuTracer gpu(*context_, tracer, options());
    EXPECT_NE(gpu.gl_version().find("4."), std::string::npos) << gpu.gl_version();
    EXPECT_FALSE(gpu.gl_renderer().empty());
}

TEST_P(Gpu, TheModelStaysOnTheGpuApartFromThePasses)
{
    // GpuModel alone: the model in its layout, its pyramid; a storage
    // buffer limit it exceeds names what does not fit
    const Model m = geology(12, 16, 10);
    const Tracer tracer(m, 1.0);
    const sbrt_gl::GlApi gl(*context_);
    GLint side = 0;
    gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &side);
    {
        sbrt_gl::GpuModel model(gl, tracer, options(), size_t(1) << 26);
        const GpuMemory want = gpu_memory(m, layout(), side);
        EXPECT_EQ(model.layout(), layout());
        EXPECT_EQ(model.memory().interval_bytes, want.interval_bytes);
        EXPECT_EQ(model.memory().texture_cols, want.texture_cols);
        EXPECT_EQ(model.pyramid_bytes(), make_gpu_pyramid(tracer.pyramid()).size() * 4);
        model.bind();
        model.bind_looks();
        model.bind_pyramid(true);
        EXPECT_EQ(gl.GetError(), GLenum(GL_NO_ERROR));
    }
    try {
        sbrt_gl::GpuModel too_large(gl, tracer, options(), 64);
        ADD_FAILURE() << "a model over the limit went up";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("largest storage buffer"), std::string::npos)
            << e.what();
    }
    // the tracer holds one
    const sbrt_gl::GpuTracer gpu(*context_, tracer, options());
    EXPECT_EQ(gpu.model().memory().interval_bytes, gpu.memory().interval_bytes);
}

TEST_P(Gpu, BlockLayoutMatchesTheShader)
{
    // wide intervals: the shader's Interval struct mirrors the model's
    const Model m = widened(geology(4, 4, 4));
    const Tracer tracer(m, 1.0);
    sbrt_gl::GpuTracer gpu(*context_, tracer, options());
    const sbrt_gl::GlApi &gl = gpu.gl();
    auto offset_of = [&](GLenum interface, const char *name) {
        const GLuint index = gl.GetProgramResourceIndex(gpu.program(), interface, name);
        EXPECT_NE(index, GL_INVALID_INDEX) << name;
        const GLenum property = GL_OFFSET;
        GLint offset = -1;
        gl.GetProgramResourceiv(gpu.program(), interface, index, 1, &property, 1,
                                nullptr, &offset);
        return offset;
    };
    EXPECT_EQ(offset_of(GL_UNIFORM, "origin_hi"), int(offsetof(GpuView, origin_hi)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "origin_lo"), int(offsetof(GpuView, origin_lo)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "forward"), int(offsetof(GpuView, forward)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "spread_u"), int(offsetof(GpuView, spread_u)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "spread_v"), int(offsetof(GpuView, spread_v)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "du"), int(offsetof(GpuView, du)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "dv"), int(offsetof(GpuView, dv)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "grid"), int(offsetof(GpuView, grid)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "box"), int(offsetof(GpuView, box)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "options"), int(offsetof(GpuView, options)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "planes[0]"), int(offsetof(GpuView, planes)));
    EXPECT_EQ(offset_of(GL_UNIFORM, "counts"), int(offsetof(GpuView, counts)));
    EXPECT_EQ(offset_of(GL_BUFFER_VARIABLE, "hits[0].point"),
              int(offsetof(GpuPixelHit, point)));
    EXPECT_EQ(offset_of(GL_BUFFER_VARIABLE, "hits[0].code"),
              int(offsetof(GpuPixelHit, code)));
    EXPECT_EQ(offset_of(GL_BUFFER_VARIABLE, "hits[0].veil"),
              int(offsetof(GpuPixelHit, veil)));
    const GLenum stride = GL_TOP_LEVEL_ARRAY_STRIDE;
    GLint hit_stride = 0;
    gl.GetProgramResourceiv(
        gpu.program(), GL_BUFFER_VARIABLE,
        gl.GetProgramResourceIndex(gpu.program(), GL_BUFFER_VARIABLE, "hits[0].point"),
        1, &stride, 1, nullptr, &hit_stride);
    EXPECT_EQ(hit_stride, int(sizeof(GpuPixelHit)));
    if (layout() == GpuLayout::textures) {
        // the model is read from the two textures, not from buffers
        EXPECT_NE(gl.GetProgramResourceIndex(gpu.program(), GL_UNIFORM, "index_texture"),
                  GL_INVALID_INDEX);
        EXPECT_NE(gl.GetProgramResourceIndex(gpu.program(), GL_UNIFORM, "interval_texture"),
                  GL_INVALID_INDEX);
        EXPECT_EQ(gl.GetProgramResourceIndex(gpu.program(), GL_BUFFER_VARIABLE,
                                             "intervals[0].top"),
                  GL_INVALID_INDEX);
        return;
    }
    EXPECT_EQ(offset_of(GL_BUFFER_VARIABLE, "intervals[0].material"),
              int(offsetof(Interval, material)));
    EXPECT_EQ(offset_of(GL_BUFFER_VARIABLE, "intervals[0].top"),
              int(offsetof(Interval, top)));
    GLint interval_stride = 0;
    gl.GetProgramResourceiv(
        gpu.program(), GL_BUFFER_VARIABLE,
        gl.GetProgramResourceIndex(gpu.program(), GL_BUFFER_VARIABLE,
                                   "intervals[0].top"),
        1, &stride, 1, nullptr, &interval_stride);
    EXPECT_EQ(interval_stride, int(sizeof(Interval)));
}

TEST_P(Gpu, CompactIntervalsAndTheStackIndexGoUpAsTheModelHoldsThem)
{
    const Model m = geology(4, 4, 4);
    ASSERT_TRUE(m.intervals().is_compact());
    const Tracer tracer(m, 1.0);
    sbrt_gl::GpuTracer gpu(*context_, tracer, options());
    const sbrt_gl::GlApi &gl = gpu.gl();
    auto stride_of = [&](const char *name) {
        const GLuint index =
            gl.GetProgramResourceIndex(gpu.program(), GL_BUFFER_VARIABLE, name);
        EXPECT_NE(index, GL_INVALID_INDEX) << name;
        const GLenum property = GL_ARRAY_STRIDE; // of a block's array of words
        GLint stride = -1;
        gl.GetProgramResourceiv(gpu.program(), GL_BUFFER_VARIABLE, index, 1, &property, 1,
                                nullptr, &stride);
        return stride;
    };
    if (layout() == GpuLayout::textures) {
        EXPECT_EQ(gpu.memory().interval_bytes % 4, 0u);
        EXPECT_LT(gpu.memory().interval_bytes, m.intervals().size() * 4 + 4 * 64);
        return;
    }
    // one word an interval, the counts in words, an offset per 16 cells
    EXPECT_EQ(stride_of("intervals[0]"), int(sizeof(CompactInterval)));
    EXPECT_EQ(stride_of("count_words[0]"), 4);
    EXPECT_EQ(stride_of("group_offsets[0]"), 4);
    EXPECT_EQ(gpu.memory().interval_bytes, m.intervals().size() * 4);
    EXPECT_EQ(gpu.memory().index_bytes, 4u + 16u); // 16 cells: one group
}

TEST_P(Gpu, AgreesWithTheCpuOnStacksLongerThanACountByte)
{
    // 7 x 6 cells (not whole groups of 16) of alternating voxels: stacks of
    // up to 600 intervals, counted in 16 bits; some columns short
    Voxels v;
    v.frame.rows = 6;
    v.frame.cols = 7;
    v.frame.depths = 600;
    v.frame.north = 60;
    v.frame.east = 70;
    v.frame.top = 60;
    v.classes.assign(v.frame.voxels(), NULL_CLASS);
    for (int z = 0; z < v.frame.depths; ++z)
        for (uint64_t c = 0; c < v.frame.cells(); ++c)
            if (c % 5 != 3 || z < 40)
                v.classes[size_t(z) * v.frame.cells() + c] = 1 + (z + int(c)) % 3;
    const Model m = build_model(v);
    ASSERT_EQ(m.index().count_bytes(), 2u);
    ASSERT_GT(m.index().max_size(), 255u);
    const Tracer tracer(m, 0.2);
    sbrt_gl::GpuTracer gpu(*context_, tracer, options());
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    for (const glm::dvec3 &from : {glm::dvec3(-0.6, -0.7, 0.5), glm::dvec3(0.5, 0.4, 0.3)}) {
        size_t over = 0;
        const Agreement a =
            compare(gpu, tracer, Camera::perspective(c + from * size, c, 40, 60, 80), &over);
        EXPECT_GT(a.hits, a.pixels / 10);
        expect_agreement(a, "long stacks");
    }
}

TEST_P(Gpu, AgreesWithTheCpuTracerFromManyCameras)
{
    // compact (4-byte intervals) at zexag 1, the same model wide at 3
    const Model compact = geology(48, 64, 30), wide = widened(compact);
    ASSERT_TRUE(compact.intervals().is_compact());
    ASSERT_FALSE(wide.intervals().is_compact());
    for (double zexag : {1.0, 3.0}) {
        const Model &m = zexag == 1.0 ? compact : wide;
        const Tracer tracer(m, zexag);
        sbrt_gl::GpuTracer gpu(*context_, tracer, options());
        const glm::dvec3 c = tracer.frame().centre(), lo = tracer.frame().corner(0),
                         hi = tracer.frame().corner(7);
        const double size = glm::length(hi - lo);
        struct View {
            const char *name;
            Camera camera;
        };
        const View views[] = {
            {"oblique", Camera::perspective(c + glm::dvec3(-0.5, -0.6, 0.4) * size,
                                            c, 40, 90, 120)},
            // grazing: just above the highest top, looking along the surface
            {"grazing", Camera::perspective(
                            glm::dvec3(lo.x - 0.5 * size, c.y, hi.z + 1e-3),
                            glm::dvec3(hi.x, c.y + 0.1 * size, hi.z - 0.02 * size),
                            30, 80, 160)},
            {"inside the box", Camera::perspective(
                                   glm::dvec3(c.x, c.y, lo.z + 0.3 * (hi.z - lo.z)),
                                   glm::dvec3(hi.x, hi.y, lo.z), 90, 80, 100)},
            {"from below", Camera::perspective(c - glm::dvec3(0.3, 0.2, 1.5) * size,
                                               c, 50, 70, 90)},
            {"orthographic", Camera::orthographic(c + glm::dvec3(1, -2, 1) * size,
                                                  c, size, 75, 100)},
            {"horizontal", Camera::orthographic(
                               glm::dvec3(c.x, c.y - 2 * size, lo.z + 0.4 * (hi.z - lo.z)),
                               glm::dvec3(c.x, c.y, lo.z + 0.4 * (hi.z - lo.z)),
                               (hi.z - lo.z) * 0.7, 60, 110)},
            {"top", Camera::top(hi.y, lo.y, hi.x, lo.x, hi.z + size, 48, 64)},
        };
        for (const View &view : views) {
            size_t over = 0;
            const Agreement a = compare(gpu, tracer, view.camera, &over);
            EXPECT_GT(a.hits, a.pixels / 10) << view.name;
            EXPECT_EQ(over, 0u) << view.name;
            expect_agreement(a, view.name);
        }
    }
}

TEST_P(Gpu, AgreesWithClipPlanesAndHiddenMaterials)
{
    const Model full = geology(40, 56, 24);
    const Model m = hide_materials(full, {2, 5});
    const Frame &f = m.frame();
    // off the cell walls and interval tops: a cut along one of them would
    // leave every ray on an edge
    const glm::dvec3 mid((f.west + f.east) / 2 + 0.37 * f.ew_res(),
                         (f.south + f.north) / 2 + 0.29 * f.ns_res(),
                         (f.bottom + f.top) / 2 + 0.41 * f.tb_res());
    const std::vector<ClipPlane> planes = {
        {mid, {0, 0, 1}},                         // horizontal cut
        {mid, {1, -0.6, 0.2}},                    // oblique cut
        {mid + glm::dvec3(0, 8 * f.ns_res(), 0), {0, 1, 0}}, // vertical section
    };
    for (size_t n = 1; n <= planes.size(); ++n) {
        const Tracer tracer(m, 2.0, {planes.begin(), planes.begin() + n});
        sbrt_gl::GpuTracer gpu(*context_, tracer, options());
        const glm::dvec3 c = tracer.frame().centre();
        const double size = 2 * tracer.frame().radius();
        size_t over = 0;
        const Agreement a = compare(
            gpu, tracer,
            Camera::perspective(c + glm::dvec3(0.4, 0.8, 0.5) * size, c, 40, 80, 100),
            &over);
        EXPECT_EQ(over, 0u);
        expect_agreement(a, "planes");
        const Agreement top = compare(
            gpu, tracer,
            sbrt_test::top_camera(f, f.top + size));
        expect_agreement(top, "planes, top");
    }
}

TEST_P(Gpu, AgreesOnStrataHiddenWhileTracing)
{
    // the model as read, two strata marked hidden (a material that absorbs
    // nothing on the GPU), with and without a cut and translucent strata
    const Model m = geology(40, 56, 24);
    const Frame &f = m.frame();
    for (const bool cut_and_translucent : {false, true}) {
        Scene scene = cut_and_translucent ? sbrt_test::cut_and_translucent_scene(m) : Scene{};
        scene.hidden.assign(m.materials().size(), 0);
        scene.hidden[2] = scene.hidden[5] = 1;
        const Tracer tracer(m, 2.0, scene);
        sbrt_gl::GpuTracer gpu(*context_, tracer, options());
        const glm::dvec3 c = tracer.frame().centre();
        const double size = 2 * tracer.frame().radius();
        size_t over = 0;
        const Camera oblique =
            Camera::perspective(c + glm::dvec3(0.4, 0.8, 0.5) * size, c, 40, 80, 100);
        const Agreement a = compare(gpu, tracer, oblique, &over);
        EXPECT_EQ(over, 0u);
        expect_agreement(a, "hidden");
        expect_agreement(compare(gpu, tracer, sbrt_test::top_camera(f, f.top + size)),
                         "hidden, top");
        // the hidden strata were in view: the frame differs from the one
        // that draws them
        Scene shown = scene;
        shown.hidden.clear();
        const HitImage with = trace_image(Tracer(m, 2.0, shown), oblique, 2);
        const HitImage want = trace_image(tracer, oblique, 2);
        const HitImage without = gpu.trace_image(oblique, 2);
        size_t changed = 0, same_light = 0;
        for (size_t i = 0; i < with.size(); ++i) {
            changed += with[i].material != without[i].material;
            // a hidden stratum veils nothing: the light as the CPU's
            same_light += std::fabs(want[i].transmittance - without[i].transmittance) < 2e-3;
        }
        EXPECT_GT(changed, with.size() / 50) << cut_and_translucent;
        EXPECT_GE(same_light, with.size() - with.size() / 1000) << cut_and_translucent;
    }
}

TEST_P(Gpu, AgreesOnTranslucentStrata)
{
    const Model m = geology(36, 44, 24);
    Translucency tr;
    tr.extinction.assign(m.materials().size(), std::numeric_limits<double>::infinity());
    tr.color.assign(m.materials().size(), glm::dvec3(0));
    for (uint32_t k : {1u, 3u, 4u, 6u}) { // four of the seven strata
        tr.extinction[k] = extinction_of(0.2 + 0.1 * k, 25.0);
        tr.color[k] = glm::dvec3(0.1 * k, 1 - 0.1 * k, 0.5);
    }
    for (double zexag : {1.0, 3.0}) {
        const Tracer tracer(m, zexag, Scene{{}, tr, {}, 0, {}, {}, true});
        sbrt_gl::GpuTracer gpu(*context_, tracer, options());
        const glm::dvec3 c = tracer.frame().centre();
        const double size = 2 * tracer.frame().radius();
        for (const Camera &camera :
             {Camera::perspective(c + glm::dvec3(0.5, -0.7, 0.45) * size, c, 40, 70, 90),
              sbrt_test::top_camera(m.frame(), m.frame().top + size)}) {
            const HitImage want = trace_image(tracer, camera, 2);
            const HitImage got = gpu.trace_image(camera, 2);
            size_t agreeing = 0, veiled = 0;
            for (size_t i = 0; i < want.size(); ++i) {
                veiled += want[i].transmittance < 0.99;
                double worst = std::fabs(double(want[i].transmittance) - got[i].transmittance);
                for (int k = 0; k < 3; ++k)
                    worst = std::max(worst, std::fabs(double(want[i].veil[k]) - got[i].veil[k]));
                agreeing += want[i].material == got[i].material && worst < 2e-3;
            }
            EXPECT_GT(veiled, want.size() / 10);
            EXPECT_GE(agreeing, want.size() - want.size() / 1000)
                << agreeing << " of " << want.size();
        }
    }
}

TEST_P(Gpu, AgreesOnRandomModels)
{
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const auto v = sbrt_test::random_voxels(seed, 20 + seed, 17 + 2 * seed, 25);
        const Model m = sbrt_test::build_model(v);
        const Tracer tracer(m, 2.0);
        sbrt_gl::GpuTracer gpu(*context_, tracer, options());
        const glm::dvec3 c = tracer.frame().centre();
        const double size = 2 * tracer.frame().radius();
        for (double az = 0.3; az < 6.28; az += 1.1) {
            const glm::dvec3 eye =
                c + size * glm::dvec3(std::sin(az), std::cos(az), 0.4 + 0.1 * seed);
            expect_agreement(compare(gpu, tracer, Camera::perspective(eye, c, 45, 60, 80)),
                             "random");
        }
    }
}

TEST_P(Gpu, LongestRayStaysWithinTheLoopBudget)
{
    // the largest supported grid side (16384 cells): a grazing ray along
    // it skims the surface of every cell and hits the far end's wall
    const int cols = 16384, rows = 4, depths = 3;
    sbrt_test::Voxels v;
    v.frame.rows = rows;
    v.frame.cols = cols;
    v.frame.depths = depths;
    v.frame.west = 0;
    v.frame.east = cols;
    v.frame.south = 0;
    v.frame.north = rows;
    v.frame.bottom = 0;
    v.frame.top = depths;
    v.classes.assign(v.frame.voxels(), NULL_CLASS);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            for (int z = 0; z < (c == cols - 1 ? 3 : 1 + (c % 3 == 0)); ++z)
                v.classes[(size_t(z) * rows + r) * cols + c] = 1 + z;
    const Model m = sbrt_test::build_model(v);
    const Tracer tracer(m, 1.0);
    sbrt_gl::GpuTracer gpu(*context_, tracer, options());
    const Camera camera = Camera::orthographic({-10, 2, 2.5}, {cols, 2, 2.5}, 1.0, 3, 3);
    size_t over = 0;
    const Agreement a = compare(gpu, tracer, camera, &over);
    EXPECT_EQ(over, 0u);
    EXPECT_EQ(a.agreeing, a.pixels);
    // the centre ray crosses every cell and ends on the last one's wall
    const HitImage hits = gpu.trace_image(camera, 1);
    EXPECT_EQ(m.materials()[hits[4].material].id, 3);
    EXPECT_NEAR(hits[4].point.x, cols - 1, 1e-3);
}

TEST_P(Gpu, TheFirstPassBoundsTheTilesAsTheCpuDoes)
{
    // the GPU's first pass: conservative (the images agree, tested with
    // every other GPU test) and as tight as the CPU's: the same tiles
    // meet nothing, and the others start where the CPU's do, give or take
    // the float margin
    const Model m = hide_materials(geology(48, 64, 30), {1, 2, 3});
    const Tracer tracer(m, 2.0);
    sbrt_gl::GpuTracer gpu(*context_, tracer, options());
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    const Camera camera = Camera::perspective(c + glm::dvec3(-0.5, -0.6, 0.4) * size, c, 40,
                                              90, 120);
    gpu.trace_image(camera, 2);
    const std::vector<float> gpu_starts = gpu.tile_starts();
    const FirstHitBounds cpu(tracer, camera, FIRST_PASS_TILE, FIRST_PASS_BUDGET, 2);
    ASSERT_EQ(gpu_starts.size(), cpu.tiles());
    const size_t gpu_empty = size_t(std::count(gpu_starts.begin(), gpu_starts.end(), INFINITY));
    EXPECT_GT(cpu.empty_tiles(), cpu.tiles() / 10);
    EXPECT_NEAR(double(gpu_empty), double(cpu.empty_tiles()), 0.01 * double(cpu.tiles()) + 1);
    // at a pixel of each tile with a bound, the GPU's t (from the view's
    // base) against the CPU's (along the unit ray from the camera)
    const GpuView view = make_gpu_view(tracer, camera);
    const double t_eye = -view.spread_u[3];
    size_t compared = 0, close = 0;
    for (int row = 0; row < camera.rows(); row += FIRST_PASS_TILE)
        for (int col = 0; col < camera.cols(); col += FIRST_PASS_TILE) {
            const Ray ray = camera.ray(row, col);
            const double want = cpu.t_start(row, col, ray);
            const size_t tile = size_t(row / FIRST_PASS_TILE) *
                                    size_t((camera.cols() + FIRST_PASS_TILE - 1) / FIRST_PASS_TILE) +
                                size_t(col / FIRST_PASS_TILE);
            if (!std::isfinite(want) || !std::isfinite(gpu_starts[tile]) || want <= 0)
                continue;
            // the GPU's d at this pixel is D / |D| scaled by the local
            // frame: its t from the eye, in map units along the ray
            const glm::dvec2 ndc = camera.pixel_ndc(row, col);
            const glm::dvec3 d(view.forward[0] + ndc.x * view.du[0] + ndc.y * view.dv[0],
                               view.forward[1] + ndc.x * view.du[1] + ndc.y * view.dv[1],
                               view.forward[2] + ndc.x * view.du[2] + ndc.y * view.dv[2]);
            const double got = (gpu_starts[tile] + t_eye) *
                               glm::length(glm::dvec3(tracer.frame().voxel_size()) * d);
            ++compared;
            close += std::fabs(got - want) <= 1e-3 * want + 0.05;
        }
    EXPECT_GT(compared, 20u);
    EXPECT_GE(close, compared * 9 / 10) << close << " of " << compared;
}

TEST_P(Gpu, SkipsEmptySpaceWithThePyramidAndKeepsTheImage)
{
    // five of the seven strata hidden: most rays cross empty space
    const Model m = hide_materials(geology(48, 64, 30), {1, 2, 3, 4, 5});
    Scene plain;
    plain.skip_empty_space = false;
    const Tracer skipping(m, 2.0), walking(m, 2.0, plain);
    ASSERT_GT(skipping.pyramid().levels(), 3);
    sbrt_gl::GpuTracer gpu_skipping(*context_, skipping, options());
    sbrt_gl::GpuTracer gpu_walking(*context_, walking, options());
    const glm::dvec3 c = skipping.frame().centre();
    const double size = 2 * skipping.frame().radius();
    const Camera cameras[] = {
        Camera::perspective(c + glm::dvec3(-0.5, -0.6, 0.4) * size, c, 40, 90, 120),
        Camera::perspective(c + glm::dvec3(0.9, 0.2, 0.05) * size, c, 40, 90, 120),
        Camera::perspective(c - glm::dvec3(0.3, 0.2, 1.5) * size, c, 50, 70, 90),
    };
    for (const Camera &camera : cameras) {
        size_t over = 0;
        expect_agreement(compare(gpu_skipping, skipping, camera, &over), "skipping");
        EXPECT_EQ(over, 0u);
        // a loop budget that walking every cell exceeds on many rays: the
        // pyramid's steps over empty blocks stay within it
        size_t over_skipping = 0, over_walking = 0;
        const Agreement a =
            compare(gpu_skipping, skipping, camera, &over_skipping, 16);
        compare(gpu_walking, walking, camera, &over_walking, 16);
        expect_agreement(a, "skipping, small budget");
        EXPECT_GT(over_walking, a.pixels / 50);
        EXPECT_LT(over_skipping * 2, over_walking)
            << over_skipping << " rays over the budget with skipping, " << over_walking
            << " without";
    }
}

TEST_P(Gpu, RaysOverTheBudgetAreTracedOnTheCpu)
{
    const Model m = geology(40, 50, 20);
    const Tracer tracer(m, 1.0);
    sbrt_gl::GpuTracer gpu(*context_, tracer, options());
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    const Camera camera = Camera::perspective(c + glm::dvec3(-0.4, -0.5, 0.3) * size,
                                              c, 40, 60, 80);
    size_t over = 0;
    // a budget of 4 loop iterations: many rays give up on the GPU
    const Agreement a = compare(gpu, tracer, camera, &over, 4);
    EXPECT_GT(over, a.pixels / 20);
    EXPECT_GE(a.agreeing, a.pixels - a.pixels / 1000);
}

TEST(GpuContext, UnknownBackendIsAnError)
{
    EXPECT_THROW(sbrt_gl::create_gl_context("vulkan"), Error);
}

namespace {

/// Voxels of 30 x 41 cells x 20 depths whose interval count follows from
/// how they are made: cell k holds 5 runs, 6 where k % 8 < 3, below 0 to 3
/// voxels of air (not stored); neighbouring runs differ in class, run 1 is
/// a cave (an EMPTY interval) in every other cell. `runs` gets the count.
Voxels counted_columns(uint64_t &runs)
{
    Voxels v;
    v.frame = placed_frame(30, 41, 20); // 25 m cells, 4 m levels from -300
    v.classes.assign(v.frame.voxels(), NULL_CLASS);
    runs = 0;
    const int cells = 30 * 41;
    for (int k = 0; k < cells; ++k) {
        const int count = k % 8 < 3 ? 6 : 5;
        const int solid = 20 - k % 4; // voxels under the air
        for (int j = 0; j < count; ++j) {
            const bool cave = j == 1 && k % 2 == 0;
            const int32_t id = cave ? NULL_CLASS : 1 + (j + k) % 7;
            for (int z = j * solid / count; z < (j + 1) * solid / count; ++z)
                v.classes[size_t(z) * cells + k] = id;
        }
        runs += count;
    }
    return v;
}

} // namespace

TEST(GpuMemoryLayout, TexturesHoldEveryIntervalWithLessThanARowWasted)
{
    uint64_t runs = 0;
    const Model m = build_model(counted_columns(runs));
    const uint64_t n = m.intervals().size();
    // 1230 cells x 5 runs + 462 cells with a sixth: 6612 intervals, more
    // than 81 x 81 texels, so at a largest side of 82 the texture is 82 x 81
    ASSERT_EQ(runs, 1230u * 5u + 462u);
    ASSERT_EQ(n, runs);
    ASSERT_TRUE(m.intervals().is_compact());
    const GpuMemory ssbo = gpu_memory(m, GpuLayout::ssbo, 16384);
    // byte counts padded to groups of 16 cells, a 32-bit offset per group;
    // 4-byte intervals
    const uint64_t groups = (m.frame().cells() + 15) / 16;
    EXPECT_EQ(ssbo.index_bytes, groups * 16 + groups * 4);
    EXPECT_LE(ssbo.index_bytes, 2 * m.frame().cells());
    EXPECT_EQ(ssbo.interval_bytes, n * 4);
    EXPECT_EQ(ssbo.waste_bytes, 0u);
    EXPECT_EQ(gpu_memory(widened(m), GpuLayout::ssbo, 16384).interval_bytes, n * 8);
    for (int max_side : {16384, 128, 82}) {
        const GpuMemory tex = gpu_memory(m, GpuLayout::textures, max_side);
        EXPECT_LE(tex.texture_cols, max_side);
        EXPECT_GE(uint64_t(tex.texture_cols) * tex.texture_rows, n);
        EXPECT_LT(uint64_t(tex.texture_cols) * (tex.texture_rows - 1), n);
        EXPECT_EQ(tex.index_bytes, m.frame().cells() * 8);
        EXPECT_EQ(tex.waste_bytes, tex.interval_bytes - n * 4);
        // the texels hold each interval where the shader looks for it: one
        // word (material | top << 16) compact, material and float bits wide
        const std::vector<uint32_t> texels =
            interval_texels(m, tex.texture_cols, tex.texture_rows);
        const std::vector<uint32_t> wide_texels =
            interval_texels(widened(m), tex.texture_cols, tex.texture_rows);
        for (uint64_t j = 0; j < n; j += 7) {
            const size_t x = j % tex.texture_cols, y = j / tex.texture_cols;
            const size_t at = y * tex.texture_cols + x;
            EXPECT_EQ(texels[at] & 0xffff, m.intervals()[j].material);
            EXPECT_EQ(float(texels[at] >> 16), m.intervals()[j].top);
            EXPECT_EQ(wide_texels[2 * at], m.intervals()[j].material);
            float top;
            std::memcpy(&top, &wide_texels[2 * at + 1], sizeof top);
            EXPECT_EQ(top, m.intervals()[j].top);
        }
    }
    const GpuMemory at_82 = gpu_memory(m, GpuLayout::textures, 82);
    EXPECT_EQ(at_82.texture_cols, 82);
    EXPECT_EQ(at_82.texture_rows, 81);
    const std::vector<uint32_t> index = index_texels(m);
    for (uint64_t cell = 0; cell < m.frame().cells(); ++cell) {
        EXPECT_EQ(index[2 * cell], m.stack_begin(cell));
        EXPECT_EQ(index[2 * cell] + index[2 * cell + 1], m.stack_end(cell));
    }
    // a grid wider than the largest texture, too many intervals: clear errors
    // needs 82 x 81 texels at least (n > 81 x 81), so 80 x 80 is too few
    EXPECT_THROW(gpu_memory(m, GpuLayout::textures, 40), Error);
    EXPECT_THROW(gpu_memory(m, GpuLayout::textures, 80), Error);
    EXPECT_THROW(parse_gpu_layout("3d-texture"), Error);
}


namespace {

/// The GPU's shaded image of `renderer` from `camera`, its programs from
/// `cache`; `from_cache` tells whether the shading program came from it.
Image gpu_image(const sbrt_gl::GlContext &context, const sbrt_gl::GpuOptions &options,
                const Renderer &renderer, const Camera &camera,
                const sbrt_gl::ProgramCache &cache, bool &from_cache)
{
    sbrt_gl::GpuRenderer on_gpu(context, renderer, options, cache);
    Image image = on_gpu.render_image(camera, {true, true, true}, 2);
    from_cache = on_gpu.gpu().shade_program_from_cache();
    return image;
}

std::vector<uint8_t> read_bytes(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string &path, const std::vector<uint8_t> &bytes)
{
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
}

} // namespace

TEST_P(Gpu, ASecondRunLoadsItsProgramsFromTheCache)
{
    const Model m = geology(20, 24, 16);
    const Renderer renderer(m, 2.0, Scene{}, Shading{}, {2, true, 16});
    const Tracer &t = renderer.tracer();
    const Camera camera = Camera::perspective(t.frame().centre() + 2.2 * t.frame().radius() *
                                                               glm::normalize(glm::dvec3(1, -1, 1)),
                                              t.frame().centre(), 40, 31, 37);
    const sbrt_gl::ProgramCache cache(sbrt_test::temp_dir("programs") + "/cache");
    bool from_cache = true;
    const Image first = gpu_image(*context_, options(), renderer, camera, cache, from_cache);
    EXPECT_FALSE(from_cache) << "an empty cache gave a program";
    // a file a program (the first pass's and the shading one); the next
    // tracer loads them
    std::vector<std::string> files;
    for (const auto &entry : std::filesystem::directory_iterator(cache.directory()))
        files.push_back(entry.path());
    ASSERT_EQ(files.size(), 2u);
    const Image second = gpu_image(*context_, options(), renderer, camera, cache, from_cache);
    EXPECT_TRUE(from_cache) << "the cached binary was not used";
    EXPECT_EQ(second.rgb, first.rgb);
    EXPECT_EQ(second.material, first.material);
    // a damaged file (a byte of the binary flipped, or cut short) is a
    // miss: the program is compiled again and the file replaced
    std::vector<std::vector<uint8_t>> good;
    for (const std::string &file : files)
        good.push_back(read_bytes(file));
    const auto damage_all = [&](const auto &damage) {
        for (size_t k = 0; k < files.size(); ++k) {
            std::vector<uint8_t> bytes = good[k];
            damage(bytes);
            write_bytes(files[k], bytes);
        }
    };
    const auto flip = [](std::vector<uint8_t> &b) { b[b.size() / 2] ^= 0x40; };
    const auto cut = [](std::vector<uint8_t> &b) { b.resize(b.size() / 3); };
    // a whole file whose binary the driver refuses (as after a driver
    // update: another format): compiled again
    const auto foreign = [](std::vector<uint8_t> &b) { b[8] ^= 0x01; };
    for (int damage = 0; damage < 3; ++damage) {
        damage_all([&](std::vector<uint8_t> &b) {
            damage == 0 ? flip(b) : damage == 1 ? cut(b) : foreign(b);
        });
        EXPECT_EQ(gpu_image(*context_, options(), renderer, camera, cache, from_cache).rgb,
                  first.rgb);
        EXPECT_FALSE(from_cache) << "damage " << damage;
        for (size_t k = 0; k < files.size(); ++k)
            EXPECT_EQ(read_bytes(files[k]), good[k]) << "a damaged file was not replaced";
    }
    // other sources are another file
    EXPECT_NE(sbrt_gl::ProgramCache::key("gl", {"a", "b"}),
              sbrt_gl::ProgramCache::key("gl", {"ab"}));
    EXPECT_NE(sbrt_gl::ProgramCache::key("gl 2", {"a"}), sbrt_gl::ProgramCache::key("gl", {"a"}));
}

TEST(ProgramCache, ItsDirectoryComesFromTheEnvironment)
{
    // the environment as it was, for the other tests
    const char *names[] = {"SBRT_PROGRAM_CACHE", "XDG_CACHE_HOME"};
    std::vector<std::optional<std::string>> saved;
    for (const char *name : names)
        saved.push_back(std::getenv(name) ? std::optional<std::string>(std::getenv(name))
                                          : std::nullopt);
    setenv("SBRT_PROGRAM_CACHE", "off", 1);
    EXPECT_FALSE(sbrt_gl::ProgramCache::from_environment().enabled());
    setenv("SBRT_PROGRAM_CACHE", "/tmp/elsewhere", 1);
    EXPECT_EQ(sbrt_gl::ProgramCache::from_environment().directory(), "/tmp/elsewhere");
    unsetenv("SBRT_PROGRAM_CACHE");
    setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
    EXPECT_EQ(sbrt_gl::ProgramCache::from_environment().directory(), "/tmp/xdg/r3.sbrt/programs");
    for (size_t k = 0; k < saved.size(); ++k) {
        if (saved[k])
            setenv(names[k], saved[k]->c_str(), 1);
        else
            unsetenv(names[k]);
    }
    // nothing there, or a directory that cannot be made: misses, no error
    const sbrt_gl::ProgramCache nowhere("/proc/no/such/place");
    EXPECT_FALSE(nowhere.load("0123456789abcdef"));
    EXPECT_FALSE(nowhere.store("0123456789abcdef", sbrt_gl::ProgramBinary{1, {1, 2, 3}}));
}

TEST_P(Gpu, ShadesOnTheGpuAsTheCpuDoes)
{
    const Model m = geology(40, 56, 30);
    Shading lit;
    lit.light = Shading::light_from(300, 35);
    lit.ambient = 0.25;
    lit.background = {10, 20, 30};
    const Renderer plain(m, 2.0, Scene{}, lit, {2, true, 16});
    const Tracer &t = plain.tracer();
    for (double azimuth : {30.0, 210.0}) {
        const glm::dvec3 dir(std::sin(azimuth * M_PI / 180), std::cos(azimuth * M_PI / 180), 0.6);
        expect_gpu_shading_as_cpu(*context_, options(), plain,
                                  Camera::perspective(t.frame().centre() + 2.2 * t.frame().radius() * dir,
                                                      t.frame().centre(), 40, 61, 83),
                                  "view " + std::to_string(azimuth));
    }
    // parallel rays from above
    const glm::dvec3 c = t.frame().centre();
    expect_gpu_shading_as_cpu(*context_, options(), plain,
                              Camera::orthographic(c + glm::dvec3(300, -400, 500), c,
                                                   1.5 * t.frame().radius(), 47, 64),
                              "orthographic");
    // clip planes (their shading normals) and translucent strata (the veil)
    const Renderer cut(m, 2.0, sbrt_test::cut_and_translucent_scene(m), lit, {2, true, 16});
    const glm::dvec3 dir(0.8, -0.3, 0.5);
    expect_gpu_shading_as_cpu(*context_, options(), cut,
                              Camera::perspective(c + 2.2 * t.frame().radius() * dir, c, 40, 61, 83),
                              "planes and translucency");
    // the camera inside the model (faces none)
    const glm::dvec3 inside = c + glm::dvec3(0, 0, -0.1 * t.frame().radius());
    expect_gpu_shading_as_cpu(*context_, options(), plain,
                              Camera::perspective(inside, inside + glm::dvec3(1, 0.3, -0.2),
                                                  70, 40, 50),
                              "inside");
}

TEST_P(Gpu, FindsKernelNormalsOnTheGpuAsTheCpuDoes)
{
    const Model m = geology(40, 56, 30);
    for (int k : {3, 5, 9}) {
        Shading kernel;
        kernel.light = Shading::light_from(250, 30);
        kernel.normals = Normals::kernel;
        kernel.kernel = k;
        const Renderer renderer(m, 2.0, Scene{}, kernel, {2, true, 16});
        const Tracer &t = renderer.tracer();
        const glm::dvec3 c = t.frame().centre();
        const std::string what = "kernel " + std::to_string(k);
        expect_gpu_shading_as_cpu(*context_, options(), renderer,
                                  Camera::perspective(c + 2.2 * t.frame().radius() *
                                                              glm::normalize(glm::dvec3(0.6, -0.5, 0.6)),
                                                      c, 40, 61, 83),
                                  what);
        expect_gpu_shading_as_cpu(*context_, options(), renderer,
                                  Camera::orthographic(c + glm::dvec3(300, -400, 500), c,
                                                       1.5 * t.frame().radius(), 47, 64),
                                  what + " orthographic");
    }
    // smoothed (Gaussian sigma in pixels): two more passes on the GPU
    for (double sigma : {0.8, 2.0}) {
        Shading smooth;
        smooth.light = Shading::light_from(250, 30);
        smooth.normals = Normals::kernel;
        smooth.kernel = 5;
        smooth.smooth = sigma;
        const Renderer renderer(m, 2.0, Scene{}, smooth, {2, true, 16});
        const Tracer &t = renderer.tracer();
        expect_gpu_shading_as_cpu(*context_, options(), renderer,
                                  Camera::perspective(t.frame().centre() + 2.2 * t.frame().radius() *
                                                                      glm::normalize(glm::dvec3(-0.5, -0.7, 0.5)),
                                                      t.frame().centre(), 40, 61, 83),
                                  "smoothed " + std::to_string(sigma));
    }
}

namespace {

/// A borehole at (col, row) cells from the south-west corner with a log
/// of its own (classes 1-3 in the model's layers), so it shows against the
/// model.
Borehole logged_borehole(const Model &m, double col, double row)
{
    const Frame &f = m.frame();
    Borehole b = sbrt_test::borehole_at(m, f.west + col * f.ew_res(), f.south + row * f.ns_res());
    for (Interval &iv : b.stack)
        iv.material = 1 + (iv.material % 3);
    return b;
}

/// `scene` with split cylinders: the model's side in classes 4 and 5, gaps
/// in every other interval of the logs (rays reach the split face through
/// them).
Scene split_through_gaps(Scene scene)
{
    for (Borehole &b : scene.boreholes) {
        for (Interval &iv : b.model_stack)
            iv.material = 4 + (iv.material % 2);
        for (size_t k = 0; k < b.stack.size(); k += 2)
            b.stack[k].material = EMPTY;
    }
    scene.split = glm::normalize(glm::dvec2(1, 1));
    return scene;
}

/// Boreholes with logs of their own and a fence of three curtains over
/// geology(40, 56, 30), without the model.
Scene overlays_alone(const Model &m)
{
    const Frame &f = m.frame();
    Scene scene;
    for (int k = 0; k < 3; ++k)
        scene.boreholes.push_back(logged_borehole(m, 7.5 + 15 * k, 29.5 - 9 * k));
    scene.borehole_radius = 1.5 * f.ew_res();
    const glm::dvec2 corner(f.west, f.south);
    const glm::dvec2 cell(f.ew_res(), f.ns_res());
    const glm::dvec2 points[] = {{4, 6}, {20, 14}, {33, 8}, {50, 27}};
    for (int k = 0; k < 3; ++k)
        scene.fence.push_back({corner + points[k] * cell, corner + points[k + 1] * cell});
    scene.draw_model = false;
    return scene;
}

} // namespace

TEST_P(Gpu, DrawsBoreholesWithTheModelAsTheCpuDoes)
{
    // boreholes drawn with the model: shading, the GPU draws both; its hit
    // records (no normals of a cylinder) leave the pixels whose rays may
    // meet a borehole to the CPU
    const Model m = geology(40, 56, 30);
    const Frame &f = m.frame();
    Scene scene;
    for (int k = 0; k < 3; ++k)
        scene.boreholes.push_back(logged_borehole(m, 7.5 + 12 * k, 9.5 + 14 * k));
    scene.borehole_radius = 1.5 * f.ew_res();
    const Renderer renderer(m, 2.0, scene, Shading{}, {2, true, 16});
    const Tracer &t = renderer.tracer();
    ASSERT_TRUE(t.has_overlays());
    const Camera camera = Camera::perspective(
        t.frame().centre() + 2.2 * t.frame().radius() * glm::normalize(glm::dvec3(0.4, -0.9, 0.7)), t.frame().centre(),
        40, 61, 83);
    expect_gpu_shading_as_cpu(*context_, options(), renderer, camera, "boreholes");
    // the boreholes show: the image differs from the model's alone
    const Image want = renderer.render_image(camera, {});
    const Renderer plain(m, 2.0, Scene{}, Shading{}, {2, true, 16});
    EXPECT_NE(plain.render_image(camera, {}).rgb, want.rgb);
    // logs standing above the surface, seen from low: rays meet them in
    // their boxes before ground beyond the boxes (the boreholes' pass traces
    // again only where a ray is in a box)
    Scene tall = scene;
    for (Borehole &b : tall.boreholes)
        b.stack.push_back({2, b.stack.back().top + 8});
    const Renderer towers(m, 2.0, tall, Shading{}, {2, true, 16});
    const Camera low = Camera::perspective(
        t.frame().centre() + 2.2 * t.frame().radius() * glm::normalize(glm::dvec3(0.5, -0.9, 0.25)),
        t.frame().centre(), 40, 61, 83);
    expect_gpu_shading_as_cpu(*context_, options(), towers, low, "logs above the surface");
    // split cylinders through gaps in their logs, and a translucent material
    Scene split = split_through_gaps(scene);
    split.translucency = sbrt_test::cut_and_translucent_scene(m).translucency;
    // cut through one borehole's axis, the cut face towards the camera
    const glm::dvec3 axis(split.boreholes[1].x, split.boreholes[1].y, t.frame().centre().z);
    split.planes = {{axis, {1, 0.5, 0}}};
    const Renderer halves(m, 2.0, split, Shading{}, {2, true, 16});
    const Camera close = Camera::perspective(
        axis + glm::dvec3(7 * f.ew_res(), 8 * f.ns_res(), 3 * f.ew_res()), axis, 40, 61, 83);
    expect_gpu_shading_as_cpu(*context_, options(), halves, close, "split cylinders");
    expect_gpu_shading_as_cpu(*context_, options(), halves, camera, "split cylinders, far");

    // hit records: the CPU's pixels are the CPU's hits exactly, and only a part
    sbrt_gl::GpuTracer gpu(*context_, t, options());
    sbrt_gl::GpuRowTracer rows(gpu, camera, 2);
    ASSERT_TRUE(rows.cpu_pixels());
    const auto &rects = *rows.cpu_pixels();
    HitImage got(size_t(camera.rows()) * size_t(camera.cols()));
    rows.trace_rows(0, camera.rows(), got.data());
    size_t cpu_pixels = 0, differing = 0;
    for (int row = 0; row < camera.rows(); ++row)
        for (const auto &[c0, c1] : row_spans(rects, row))
            for (int col = c0; col <= c1; ++col) {
                const Hit hit = t.trace(camera.ray(row, col));
                const Hit &g = got[size_t(row) * size_t(camera.cols()) + size_t(col)];
                ++cpu_pixels;
                differing += hit.material != g.material || hit.t != g.t;
            }
    EXPECT_GT(cpu_pixels, 30u);
    EXPECT_LT(cpu_pixels, size_t(camera.rows()) * size_t(camera.cols()) / 3);
    EXPECT_EQ(differing, 0u);
}

TEST_P(Gpu, ShadesADrapeOnTheGpuAsTheCpuDoes)
{
    const Model m = geology(40, 56, 30);
    const Frame &f = m.frame();
    // a texture over part of the model and beyond its east and north
    // edges, with pixels that hold no value
    Texture texture;
    const double width = f.east - f.west, height = f.north - f.south;
    texture.west = f.west + 0.15 * width;
    texture.east = f.east + 0.2 * width;
    texture.south = f.south + 0.1 * height;
    texture.north = f.north + 0.3 * height;
    texture.rows = 29;
    texture.cols = 37;
    for (int r = 0; r < texture.rows; ++r)
        for (int c = 0; c < texture.cols; ++c) {
            texture.rgb.push_back({uint8_t(7 * c), uint8_t(255 - 8 * r), uint8_t(40 + 5 * (r + c))});
            texture.valid.push_back(!(r % 5 == 2 && c % 4 == 1));
        }
    const Drape drape(m, texture, 0.7);
    Shading draped;
    draped.light = Shading::light_from(120, 40);
    draped.drape = &drape;
    const Renderer renderer(m, 2.0, Scene{}, draped, {2, true, 16});
    const Tracer &t = renderer.tracer();
    // from above (tops) and low from the south-west (the staircase's walls)
    for (const glm::dvec3 dir : {glm::dvec3(0.3, -0.4, 1.2), glm::dvec3(-0.7, -0.6, 0.5)})
        expect_gpu_shading_as_cpu(*context_, options(), renderer,
                                  Camera::perspective(t.frame().centre() + 2.2 * t.frame().radius() *
                                                                       glm::normalize(dir),
                                                      t.frame().centre(), 40, 61, 83),
                                  "drape", 1);
    // the drape's colours differ from the classes' (the test sees them)
    Shading plain = draped;
    plain.drape = nullptr;
    const Renderer undraped(m, 2.0, Scene{}, plain, {2, true, 16});
    const Camera above = Camera::perspective(t.frame().centre() + 2.2 * t.frame().radius() *
                                                              glm::normalize(glm::dvec3(0.3, -0.4, 1.2)),
                                             t.frame().centre(), 40, 61, 83);
    const Image with = renderer.render_image(above, {}), without = undraped.render_image(above, {});
    size_t changed = 0;
    for (size_t i = 0; i < with.rgb.size(); ++i)
        changed += with.rgb[i] != without.rgb[i];
    EXPECT_GT(changed, with.rgb.size() / 10);
}

TEST_P(Gpu, DrawsBoreholesAndCurtainsAloneOnTheGpuAsTheCpuDoes)
{
    const Model m = geology(40, 56, 30);
    const Frame &f = m.frame();
    Shading lit;
    lit.light = Shading::light_from(230, 35);
    const Renderer alone(m, 2.0, overlays_alone(m), lit, {2, true, 16});
    const Tracer &t = alone.tracer();
    const glm::dvec3 c = t.frame().centre();
    const Camera views[] = {
        Camera::perspective(c + 2.2 * t.frame().radius() * glm::normalize(glm::dvec3(0.4, -0.9, 0.6)), c,
                            40, 61, 83),
        Camera::perspective(c + 2.2 * t.frame().radius() * glm::normalize(glm::dvec3(-0.8, 0.5, 0.3)), c,
                            40, 61, 83),
        Camera::orthographic(c + glm::dvec3(300, -400, 500), c, 1.5 * t.frame().radius(), 47, 64),
        // among the overlays, looking along the fence
        Camera::perspective(c + glm::dvec3(-0.45 * (f.east - f.west), -0.2 * (f.north - f.south), 0),
                            c + glm::dvec3(0, 0, -50), 70, 40, 50)};
    for (size_t k = 0; k < std::size(views); ++k)
        expect_gpu_shading_as_cpu(*context_, options(), alone, views[k],
                                  "boreholes and fence, view " + std::to_string(k), 0, 30);
    {
        // the overlays' buffers as the shader reads them (gpu_overlays.hpp)
        sbrt_gl::GpuRenderer on_gpu(*context_, alone, options());
        on_gpu.render_image(views[0], {}, 2);
        const sbrt_gl::GlApi &gl = on_gpu.gpu().gl();
        const GLuint program = on_gpu.gpu().shade_program();
        ASSERT_NE(program, 0u);
        auto property = [&](const char *name, GLenum what) {
            const GLuint index = gl.GetProgramResourceIndex(program, GL_BUFFER_VARIABLE, name);
            EXPECT_NE(index, GL_INVALID_INDEX) << name;
            GLint value = -1;
            gl.GetProgramResourceiv(program, GL_BUFFER_VARIABLE, index, 1, &what, 1, nullptr,
                                    &value);
            return value;
        };
        EXPECT_EQ(property("overlay_head", GL_OFFSET), int(offsetof(GpuOverlayHead, borehole_radius)));
        EXPECT_EQ(property("map_unit", GL_OFFSET), int(offsetof(GpuOverlayHead, map_unit)));
        EXPECT_EQ(property("overlay_count", GL_OFFSET), int(offsetof(GpuOverlayHead, count)));
        EXPECT_EQ(property("overlays[0].ends", GL_OFFSET), int(sizeof(GpuOverlayHead)));
        EXPECT_EQ(property("overlays[0].stacks", GL_OFFSET),
                  int(sizeof(GpuOverlayHead) + offsetof(GpuOverlay, log_first)));
        EXPECT_EQ(property("overlays[0].ends", GL_TOP_LEVEL_ARRAY_STRIDE), int(sizeof(GpuOverlay)));
        EXPECT_EQ(property("logs[0].top", GL_OFFSET), int(offsetof(Interval, top)));
        EXPECT_EQ(property("logs[0].top", GL_TOP_LEVEL_ARRAY_STRIDE), int(sizeof(Interval)));
    }
    // split cylinders: the log on one side, the model's stack on the other
    Scene alone_split = overlays_alone(m);
    alone_split.fence.clear();
    const Scene split = split_through_gaps(alone_split);
    const Renderer halves(m, 2.0, split, lit, {2, true, 16});
    // close to one of them, seeing both halves
    const glm::dvec3 axis(split.boreholes[1].x, split.boreholes[1].y, c.z);
    const Camera close = Camera::perspective(
        axis + glm::dvec3(7 * f.ew_res(), 8 * f.ns_res(), 3 * f.ew_res()), axis, 40, 61, 83);
    size_t on_split = 0;
    for (int row = 0; row < close.rows(); ++row)
        for (int col = 0; col < close.cols(); ++col)
            on_split += halves.tracer().trace(close.ray(row, col)).face == Face::split;
    EXPECT_GT(on_split, 20u);
    expect_gpu_shading_as_cpu(*context_, options(), halves, close, "split cylinders");
    // a clip plane and a translucent material (the curtains' alpha)
    Scene veiled = sbrt_test::cut_and_translucent_scene(m);
    const Scene overlays = overlays_alone(m);
    veiled.boreholes = overlays.boreholes;
    veiled.borehole_radius = overlays.borehole_radius;
    veiled.fence = overlays.fence;
    veiled.draw_model = false;
    const Renderer translucent(m, 2.0, veiled, lit, {2, true, 16});
    expect_gpu_shading_as_cpu(*context_, options(), translucent, views[1], "plane and veil", 0, 30);
    // more overlays than the CPU meets directly (it walks the cells then)
    Scene many;
    for (int row = 0; row < 40; row += 2)
        for (int col = 0; col < 56; col += 4)
            many.boreholes.push_back(sbrt_test::borehole_at(
                m, f.west + (col + 0.5) * f.ew_res(), f.north - (row + 0.5) * f.ns_res()));
    ASSERT_GT(many.boreholes.size(), 256u);
    many.borehole_radius = 0.6 * f.ew_res();
    many.draw_model = false;
    const Renderer forest(m, 2.0, many, lit, {2, true, 16});
    expect_gpu_shading_as_cpu(*context_, options(), forest, views[0], "280 boreholes");
    // a fence wholly outside the model: nothing to draw, not the model
    Scene outside;
    outside.fence = {{{f.east + 100, f.south}, {f.east + 300, f.north}}};
    outside.draw_model = false;
    const Renderer nothing(m, 2.0, outside, lit, {2, true, 16});
    ASSERT_FALSE(nothing.tracer().has_overlays());
    sbrt_gl::GpuRenderer on_gpu(*context_, nothing, options());
    const Image image = on_gpu.render_image(views[0], {true, false, false}, 2);
    EXPECT_EQ(std::count(image.material.begin(), image.material.end(), NULL_CLASS),
              long(image.material.size()));
    EXPECT_EQ(image.rgb, nothing.render_image(views[0], {}).rgb);
}
