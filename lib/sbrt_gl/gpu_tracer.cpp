/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   GPU tracing of an image
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_tracer.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>

#include "util/error.hpp"
#include "util/parallel.hpp"
#include "gpu_internal.hpp"
#include "gpu/gpu_overlays.hpp"
#include "gpu/gpu_paint.hpp"

namespace sbrt_gl {

namespace {

/// GL 4.4 core at least (compute shaders, SSBOs, persistently mapped
/// buffers); the largest SSBO binding.
size_t check_version(const GlApi &gl, const std::string &context)
{
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 44)
        sbrt::fail(context, ": OpenGL ", major, ".", minor,
                   " is below 4.4 (compute shaders, storage buffers, mapped buffers)");
    GLint64 block = 0;
    gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
    return size_t(std::max<GLint64>(block, 0));
}

} // namespace

GpuTracer::GpuTracer(const GlContext &context, const sbrt::Tracer &tracer,
                     sbrt::GpuLayout layout, ProgramCache cache)
    : GpuTracer(context, tracer, GpuOptions::from_environment(layout), std::move(cache))
{
}

GpuTracer::GpuTracer(const GlContext &context, const sbrt::Tracer &tracer,
                     const GpuOptions &options, ProgramCache cache)
    : created_(Clock::now()), tracer_(tracer), gl_(context),
      max_block_bytes_(check_version(gl_, context.name())),
      model_(gl_, tracer, options, max_block_bytes_),
      programs_(gl_, tracer, model_, std::move(cache)),
      boreholes_(gl_, tracer, max_block_bytes_),
      shading_inputs_(gl_, tracer, model_, max_block_bytes_),
      view_(gl_, GL_UNIFORM_BUFFER, sizeof(sbrt::GpuView)), kernel_buffers_(gl_),
      bands_(gl_, max_block_bytes_, sbrt_gl::staged_bands(options, gl_renderer())), timer_(gl_),
      host_shader_(tracer.model()), loop_budget_(sbrt_gl::loop_budget(options, gl_renderer())),
      crowded_band_pixels_(std::max(options.crowded_band_pixels, 1))
{
    stats_.upload_ms = ms_since(created_);
}

std::string GpuTracer::gl_version() const
{
    return reinterpret_cast<const char *>(gl_.GetString(GL_VERSION));
}

std::string GpuTracer::gl_renderer() const
{
    return reinterpret_cast<const char *>(gl_.GetString(GL_RENDERER));
}

void GpuTracer::reset_stats()
{
    // what the tracer's life has cost so far, not a frame's
    const double upload_ms = stats_.upload_ms, paint_ms = stats_.paint_ms;
    stats_ = GpuStats();
    stats_.upload_ms = upload_ms;
    stats_.paint_ms = paint_ms;
    timer_.take_ms(0); // the queries of what went before
}

void GpuTracer::begin_frame()
{
    reset_stats();
    frame_start_ = Clock::now();
    bands_.begin_frame();
    if (GpuPageAtlas *pages = model_.pages())
        pages->begin_frame();
}

bool GpuTracer::brought_wanted_blocks()
{
    GpuPageAtlas *pages = model_.pages();
    if (!pages)
        return false;
    const auto start = Clock::now();
    const bool brought = pages->bring_wanted() > 0;
    stats_.page_ms += ms_since(start);
    stats_.page_passes += brought ? 1 : 0;
    return brought;
}

int GpuTracer::crowded_band_rows(int cols) const
{
    const GpuPageAtlas *pages = model_.pages();
    if (!pages || !pages->crowded())
        return 0;
    return std::max(1, crowded_band_pixels_ / std::max(cols, 1));
}

bool GpuTracer::band_again(bool &restarted)
{
    if (brought_wanted_blocks())
        return true;
    GpuPageAtlas *pages = model_.pages();
    if (restarted || !pages || !pages->begin_band_where_full())
        return false;
    restarted = true;
    return true;
}

std::vector<double> GpuTracer::take_pass_ms()
{
    if (!timer_.enabled())
        return {};
    return timer_.take_ms(int(Pass::cull_tiles) + 1);
}

const char *pass_name(int k)
{
    static const char *const names[] = {"records",        "shade",         "kernel_depth",
                                        "kernel_normals", "kernel_across", "kernel_shade",
                                        "first_pass",     "shade_boreholes", "cull_tiles"};
    return k >= 0 && k < int(std::size(names)) ? names[k] : "?";
}

sbrt::HitImage GpuTracer::trace_image(const sbrt::Camera &camera,
                                      unsigned cpu_threads,
                                      uint32_t loop_budget)
{
    begin_frame();
    sbrt::HitImage hits(size_t(camera.rows()) * camera.cols());
    trace_rows(camera, 0, camera.rows(), hits.data(), cpu_threads, loop_budget);
    return hits;
}


const GlComputeProgram *GpuTracer::shading_program_built() const
{
    for (const ProgramVariant variant : {ProgramVariant{false, true}, ProgramVariant{true, false},
                                         ProgramVariant{}})
        if (const GlComputeProgram *program = programs_.built(Pass::shade, variant))
            return program;
    return nullptr;
}

void GpuTracer::bind_model() const
{
    model_.bind();
    view_.bind(0);
    if (tile_starts_)
        tile_starts_->bind(8);
}


void GpuTracer::dispatch_records(const sbrt::Camera &camera, sbrt::GpuView &view,
                                 int first_row, int row_count)
{
    const int cols = camera.cols();
    const size_t row_bytes = size_t(cols) * sizeof(sbrt::GpuPixelHit);
    int band_rows = int(band_->bytes() / row_bytes);
    if (const int crowded = crowded_band_rows(cols))
        band_rows = std::min(band_rows, crowded);
    band_->bind(2);
    for (int first = first_row; first < first_row + row_count; first += band_rows) {
        const int count = std::min(band_rows, first_row + row_count - first);
        view.options[2] = uint32_t(first);
        view.options[3] = uint32_t(count);
        view_.upload(&view, sizeof view); // stays bound to index 0
        // a paged model: again once the blocks its rays missed are up
        bool restarted = false;
        do {
            auto start = Clock::now();
            timer_.time(int(Pass::records), [&] {
                gl_.DispatchCompute(GLuint((cols + 7) / 8), GLuint((count + 7) / 8), 1);
            });
            gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
            gl_.Finish();
            check_gl(gl_, "the ray casting dispatch");
            stats_.trace_ms += ms_since(start);
            start = Clock::now();
            band_->download(records_.data() + size_t(first - first_row) * size_t(cols),
                            size_t(count) * row_bytes);
            stats_.readback_ms += ms_since(start);
        } while (band_again(restarted));
        ++stats_.bands;
    }
}


void GpuTracer::trace_rows(const sbrt::Camera &camera, int first_row, int row_count,
                           sbrt::Hit *out, unsigned cpu_threads, uint32_t loop_budget)
{
    const int cols = camera.cols();
    if (!tracer_.scene().draw_model) {
        // boreholes and curtains alone: the GPU shades them (shade_rows),
        // a hit record would lack their surfaces' normals
        sbrt::for_each_row(first_row, first_row + row_count, cpu_threads, [&](int row) {
            for (int col = 0; col < cols; ++col)
                tracer_.trace_into(camera.ray(row, col), 0,
                                   out[size_t(row - first_row) * cols + size_t(col)]);
        });
        return;
    }
    ensure_band_buffer(gl_, band_, row_count, size_t(cols) * sizeof(sbrt::GpuPixelHit),
                       max_block_bytes_);
    records_.resize(size_t(row_count) * cols);
    sbrt::GpuView view = traced_view(camera, loop_budget);
    record_program().use();
    bind_model();
    dispatch_records(camera, view, first_row, row_count);

    const auto start = Clock::now();
    std::vector<size_t> over_per_row(size_t(row_count), 0);
    sbrt::for_each_row(first_row, first_row + row_count, cpu_threads, [&](int row) {
        for (int col = 0; col < cols; ++col) {
            const size_t i = size_t(row - first_row) * cols + col;
            const sbrt::Ray ray = camera.ray(row, col);
            bool over_budget = false;
            out[i] = sbrt::decode_gpu_hit(tracer_, ray, records_[i], over_budget);
            if (over_budget) {
                out[i] = tracer_.trace(ray);
                ++over_per_row[size_t(row - first_row)];
            }
        }
    });
    for (size_t n : over_per_row)
        stats_.over_budget += n;
    stats_.readback_ms += ms_since(start);
}

bool GpuTracer::paints(const sbrt::Shading &shading, const sbrt::Outputs &outputs) const
{
    return sbrt::gpu_paints(tracer_, shading, outputs) &&
           sbrt::gpu_paint_bytes(tracer_, shading) <= max_block_bytes_;
}

GlComputeProgram &GpuTracer::shading_program(const sbrt::Shading &shading, Pass pass)
{
    const bool draped = shading.drape != nullptr;
    // colours by voxel: only the model pass of face normals (gpu_paints)
    const bool painted = shading.property || shading.fade;
    if (painted && pass != Pass::shade)
        sbrt::fail("colours by voxel are not made in this GPU pass");
    return programs_.get(pass, {draped, painted});
}

void GpuTracer::run_pass(Pass pass, int width, int height)
{
    programs_.get(pass).use();
    timer_.time(int(pass), [&] {
        gl_.DispatchCompute(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1);
    });
    gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

int GpuTracer::max_band_rows(int cols, const sbrt::Outputs &outputs) const
{
    const size_t row_bytes = sbrt::gpu_band_layout(1, cols, outputs).bytes();
    return int(std::clamp<size_t>(max_block_bytes_ / std::max<size_t>(row_bytes, 1), 1,
                                  size_t(INT32_MAX)));
}

sbrt::GpuBandLayout GpuTracer::band_layout(const sbrt::Camera &camera, int count,
                                           const sbrt::Outputs &outputs, sbrt::GpuShade &shade)
{
    const std::optional<sbrt::GpuBandLayout> layout =
        bands_.layout(count, camera.cols(), outputs);
    if (!layout)
        sbrt::fail("a band of ", count, " rows of ", camera.cols(),
                   " pixels does not fit this GPU's largest storage buffer (",
                   max_block_bytes_, " bytes): fewer rows a band");
    sbrt::set_band_planes(shade, *layout);
    return *layout;
}

void GpuTracer::shade_rows(const sbrt::Camera &camera, int first_row, int row_count,
                           const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                           sbrt::Band &band, unsigned cpu_threads)
{
    if ((shading.property || shading.fade) && !paints(shading, outputs))
        sbrt::fail("these colours by voxel are made on the host, not on the GPU");
    sbrt::GpuShade shade = sbrt::make_gpu_shade(tracer_, shading, outputs);
    const sbrt::GpuBandLayout layout = band_layout(camera, row_count, outputs, shade);
    ShadePlan plan;
    plan.model_program = &shading_program(shading, Pass::shade);
    // boreholes with the model: the model alone everywhere, then the model
    // and the boreholes again over the tiles where a ray may meet one (no
    // other ray pays for them)
    if (sbrt::gpu_overlay_mode(tracer_) == sbrt::GpuOverlayMode::with_model) {
        plan.borehole_program = &shading_program(shading, Pass::shade_boreholes);
        // the camera among the boxes: every tile in the boreholes' pass,
        // and no model pass (no box lists to test its hits against)
        plan.every_tile = sbrt::overlay_tiles_everywhere(tracer_.overlay_boxes(), camera);
    }
    plan.view = traced_view(camera, loop_budget_);
    bind_model();
    shading_inputs_.bind(shade, shading, stats_);
    if (shading.property || shading.fade)
        shading_inputs_.bind_double_rays(camera);
    // a scratch buffer for each slot, as a band dispatched ahead writes its
    // own while the band before still reads (binding 13)
    bands_.set_scratch(plan.borehole_program ? boreholes_.scratch_bytes(camera, layout) : 0, 13);
    shade_band(camera, first_row, row_count, shading, layout, band, cpu_threads,
               [&](int first, int count, int slot) {
                   dispatch_shading(camera, plan, first, count, slot);
               });
    if (plan.borehole_program) // the tiles listed in the band just done
        stats_.borehole_tiles += boreholes_.listed(bands_.last_slot());
}

void GpuTracer::dispatch_shading(const sbrt::Camera &camera, ShadePlan &plan, int first,
                                 int count, int slot)
{
    if (stats_.before_dispatch_ms == 0) // the first band
        stats_.before_dispatch_ms = ms_since(frame_start_);
    plan.view.options[2] = uint32_t(first);
    plan.view.options[3] = uint32_t(count);
    view_.upload(&plan.view, sizeof plan.view); // stays bound to index 0
    const bool boreholes = plan.borehole_program != nullptr;
    if (!plan.every_tile) {
        ++stats_.model_pass_bands;
        // the model alone: skipping as if there were no boreholes
        model_.bind_pyramid(boreholes);
        plan.model_program->use();
        timer_.time(int(Pass::shade), [&] {
            gl_.DispatchCompute(GLuint((camera.cols() + 7) / 8), GLuint((count + 7) / 8), 1);
        });
        model_.bind_pyramid();
    }
    if (boreholes)
        boreholes_.dispatch(camera, programs_, *plan.borehole_program, plan.every_tile, first,
                            count, slot, timer_, stats_);
}

void GpuTracer::shade_band(const sbrt::Camera &camera, int first_row, int row_count,
                           const sbrt::Shading &shading, const sbrt::GpuBandLayout &layout,
                           sbrt::Band &band, unsigned cpu_threads,
                           const std::function<void(int, int, int)> &dispatch,
                           bool reads_model)
{
    bands_.reset_gpu_ms();
    uint8_t *host = bands_.band(first_row, row_count, camera.rows(), dispatch);
    // a paged model: the band again once the blocks its rays missed are up
    // (they are sent back as rays over the budget)
    const auto sent_back = [&] {
        uint32_t over = 0;
        std::memcpy(&over, host + layout.over_budget_at * 4, 4);
        return over;
    };
    bool restarted = false;
    while (reads_model && model_.pages() && sent_back() > 0 && band_again(restarted))
        host = bands_.redo(dispatch);
    stats_.trace_ms += bands_.gpu_ms();
    ++stats_.bands;
    // the band views the mapped memory as the GPU wrote it
    const size_t cols = size_t(layout.cols);
    uint32_t *words = reinterpret_cast<uint32_t *>(host);
    band.first_row = first_row;
    band.rows = row_count;
    band.cols = layout.cols;
    band.rgb = sbrt::BandPlane<uint8_t>(host, layout.rgb_stride_words * 4);
    band.material = layout.material_at ? sbrt::BandPlane<int32_t>(
                                             reinterpret_cast<int32_t *>(words + layout.material_at), cols)
                                       : sbrt::BandPlane<int32_t>();
    const auto doubles = [&](size_t at) {
        return at ? sbrt::BandPlane<double>(reinterpret_cast<double *>(words + at), cols)
                  : sbrt::BandPlane<double>();
    };
    band.elevation = doubles(layout.elevation_at);
    band.depth = doubles(layout.depth_at);
    band.value = sbrt::BandPlane<double>();
    stats_.host_bytes += band.pixels() * band.bytes_per_pixel() + 4;

    // the rays over the loop budget, traced and shaded here (each pixel
    // listed once: the boreholes' pass leaves the model pass's alone)
    const uint32_t over = words[layout.over_budget_at];
    if (over == 0)
        return;
    if (over > band.pixels())
        sbrt::fail("the GPU listed ", over, " rays over its loop budget in a band of ",
                   band.pixels(), " pixels");
    const auto start = Clock::now();
    const uint32_t *pixels = words + layout.over_budget_at + 1;
    const sbrt::PixelShader &shader = host_shader(shading);
    // 256 rays a thread: a ray traced alone takes microseconds, starting a
    // thread tens (the few dozen a property view sends back: one thread;
    // 16 host threads made a frame slower than one: docs/performance.md)
    constexpr uint32_t CHUNK = 256;
    const int chunks = int((over + CHUNK - 1) / CHUNK);
    sbrt::for_each_row(0, chunks, cpu_threads, [&](int chunk) {
        const uint32_t end = std::min<uint32_t>(over, uint32_t(chunk + 1) * CHUNK);
        for (uint32_t k = uint32_t(chunk) * CHUNK; k < end; ++k) {
            const int row = first_row + int(pixels[k] / cols), col = int(pixels[k] % cols);
            const sbrt::Hit hit = tracer_.trace(camera.ray(row, col));
            sbrt::shade_into_band(tracer_, shader, camera, hit, row, col, band);
        }
    });
    stats_.over_budget += over;
    stats_.host_bytes += size_t(over) * (4 + band.bytes_per_pixel());
    stats_.readback_ms += ms_since(start);
}

} // namespace sbrt_gl
