/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   GPU tracing of an image
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_tracer.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "util/error.hpp"
#include "util/parallel.hpp"
#include "shader_sources.hpp"
#include "shading/kernel_normals.hpp"

#define SBRT_STRINGIFY(x) #x

namespace sbrt_gl {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// GL 4.3 core at least (compute shaders, SSBOs); the largest SSBO binding.
size_t check_version(const GlApi &gl, const std::string &context)
{
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 43)
        sbrt::fail(context, ": OpenGL ", major, ".", minor,
                   " is below 4.3 (compute shaders and storage buffers)");
    GLint64 block = 0;
    gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
    return size_t(std::max<GLint64>(block, 0));
}

size_t checked_bytes(size_t bytes, size_t limit, const char *what)
{
    if (bytes > limit)
        sbrt::fail("the model's ", what, " take ", bytes,
                   " bytes, more than this GPU's largest storage buffer (",
                   limit, " bytes): render with backend=cpu");
    return bytes;
}

/// The largest width and height of a 2D texture.
int max_texture_side(const GlApi &gl)
{
    GLint side = 0;
    gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &side);
    return std::max(side, 1);
}

/// The empty-space pyramid (binding 4).
GlBuffer pyramid_buffer(const GlApi &gl, const sbrt::Tracer &tracer, size_t limit)
{
    const std::vector<uint32_t> words = sbrt::make_gpu_pyramid(tracer.pyramid());
    return GlBuffer(gl, GL_SHADER_STORAGE_BUFFER,
                    checked_bytes(words.size() * sizeof(uint32_t), limit,
                                  "empty-space pyramid"),
                    words.data());
}

/// How each material looks (binding 3).
GlBuffer material_buffer(const GlApi &gl, const sbrt::Tracer &tracer)
{
    const std::vector<sbrt::GpuMaterial> table = sbrt::make_gpu_materials(tracer);
    return GlBuffer(gl, GL_SHADER_STORAGE_BUFFER,
                    table.size() * sizeof(sbrt::GpuMaterial), table.data());
}

} // namespace

GpuTracer::GpuTracer(const GlContext &context, const sbrt::Tracer &tracer,
                     sbrt::GpuLayout layout, ProgramCache cache)
    : created_(Clock::now()), tracer_(tracer), gl_(context), cache_(std::move(cache)),
      max_block_bytes_(check_version(gl_, context.name())), layout_(layout),
      memory_(sbrt::gpu_memory(tracer.model(), layout, max_texture_side(gl_))),
      materials_(material_buffer(gl_, tracer)),
      view_(gl_, GL_UNIFORM_BUFFER, sizeof(sbrt::GpuView)),
      pyramid_(pyramid_buffer(gl_, tracer, max_block_bytes_))
{
    const sbrt::Model &model = tracer.model();
    if (layout == sbrt::GpuLayout::ssbo) {
        // the model's own compact arrays go up as they are: counts and
        // intervals; only the group offsets narrow to 32 bits. The shader
        // reads their bytes as little-endian words.
        static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
                      "the GL path uploads the model's arrays as they lie in memory");
        const std::vector<uint32_t> groups = sbrt::group_offset_words(model);
        group_offsets_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                               checked_bytes(groups.size() * sizeof(uint32_t),
                                             max_block_bytes_, "stack offsets"),
                               groups.data());
        const sbrt::StackIndex &index = model.index();
        counts_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                        checked_bytes(index.count_data_bytes(), max_block_bytes_,
                                      "stack counts"),
                        index.count_data());
        const sbrt::IntervalArray &intervals = model.intervals();
        const void *records =
            intervals.visit([](const auto *first) { return static_cast<const void *>(first); });
        intervals_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                           checked_bytes(memory_.interval_bytes, max_block_bytes_,
                                         "intervals"),
                           records);
    }
    else {
        const sbrt::Frame &f = model.frame();
        index_texture_.emplace(gl_, f.cols, f.rows, sbrt::index_texels(model).data());
        interval_texture_.emplace(
            gl_, memory_.texture_cols, memory_.texture_rows,
            sbrt::interval_texels(model, memory_.texture_cols, memory_.texture_rows).data(),
            model.intervals().is_compact() ? 1 : 2);
    }
    gl_.Finish();
    check_gl(gl_, "uploading the model");
    // llvmpipe ends an invocation after 65,535 loop iterations; a GPU does
    // not: its rays run to the end
    if (!is_software_renderer(gl_renderer()))
        loop_budget_ = UINT32_MAX;
    stats_.upload_ms = ms_since(created_); // with compiling the shader
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
    const double upload_ms = stats_.upload_ms;
    stats_ = GpuStats();
    stats_.upload_ms = upload_ms;
}

sbrt::HitImage GpuTracer::trace_image(const sbrt::Camera &camera,
                                      unsigned cpu_threads,
                                      uint32_t loop_budget)
{
    reset_stats();
    sbrt::HitImage hits(size_t(camera.rows()) * camera.cols());
    trace_rows(camera, 0, camera.rows(), hits.data(), cpu_threads, loop_budget);
    return hits;
}

namespace {

/// What a program of the GPU path does.
enum class Pass {
    records,      ///< raycast.comp: hit records
    shade,        ///< raycast.comp: the shaded outputs (SBRT_SHADE)
    kernel_depth, ///< kernel.comp: the view depths (SBRT_KERNEL_DEPTH)
    kernel_shade, ///< kernel.comp: kernel normals and the shaded outputs
    first_pass    ///< first_pass.comp: the tiles' first-hit bounds
};

/// The first pass's tile and budget, as the CPU's (cpu_tracing.hpp).
const char *const FIRST_PASS_DEFINES =
    "#define SBRT_FIRST_PASS_TILE " SBRT_STRINGIFY(8) "\n"
    "#define SBRT_FIRST_PASS_BUDGET " SBRT_STRINGIFY(32) "\n";
static_assert(sbrt::FIRST_PASS_TILE == 8 && sbrt::FIRST_PASS_BUDGET == 32,
              "FIRST_PASS_DEFINES follow cpu_tracing.hpp");

/// The sources of `pass` for `layout` and the form `model` is held in;
/// with `drape`, a drape's colours among the outputs (SBRT_DRAPE).
std::vector<const char *> pass_sources(Pass pass, sbrt::GpuLayout layout,
                                       const sbrt::Model &model, bool drape = false)
{
    const unsigned count_bytes = model.index().count_bytes();
    const bool shade = pass == Pass::shade || pass == Pass::kernel_shade;
    const bool kernel = pass == Pass::kernel_depth || pass == Pass::kernel_shade;
    return {"#version 450\n",
            layout == sbrt::GpuLayout::textures ? "#define SBRT_TEXTURES 1\n" : "",
            model.intervals().is_compact() ? "#define SBRT_COMPACT_INTERVALS 1\n" : "",
            count_bytes == 1   ? "#define SBRT_COUNT_BYTES 1\n"
            : count_bytes == 2 ? "#define SBRT_COUNT_BYTES 2\n"
                               : "#define SBRT_COUNT_BYTES 4\n",
            shade ? "#define SBRT_SHADE 1\n" : "",
            drape && shade ? "#define SBRT_DRAPE 1\n" : "",
            kernel ? "#define SBRT_KERNEL 1\n" : "",
            pass == Pass::kernel_depth ? "#define SBRT_KERNEL_DEPTH 1\n" : "",
            FIRST_PASS_DEFINES,
            SHADER_COMMON_LAYOUT,
            shade ? SHADER_COMMON_SHADE : "",
            kernel                     ? SHADER_KERNEL
            : pass == Pass::first_pass ? SHADER_FIRST_PASS
                                       : SHADER_RAYCAST};
}

} // namespace

const GlComputeProgram &GpuTracer::record_program() const
{
    // compiled when first used: a render shaded on the GPU never needs it
    if (!program_)
        program_.emplace(gl_, pass_sources(Pass::records, layout_, tracer_.model()), &cache_);
    return *program_;
}

void GpuTracer::bind_model() const
{
    if (layout_ == sbrt::GpuLayout::ssbo) {
        group_offsets_->bind(0);
        intervals_->bind(1);
        counts_->bind(6);
    }
    else {
        index_texture_->bind(0);
        interval_texture_->bind(1);
    }
    materials_.bind(3);
    pyramid_.bind(4);
    view_.bind(0);
    if (tile_starts_)
        tile_starts_->bind(8);
}

std::vector<float> GpuTracer::tile_starts() const
{
    if (!tile_starts_)
        return {};
    const uint32_t side = uint32_t(sbrt::FIRST_PASS_TILE), tile_cols = first_pass_view_.counts[3];
    const uint32_t rows = first_pass_view_.grid[3];
    std::vector<float> starts(size_t(tile_cols) * ((rows + side - 1) / side));
    tile_starts_->download(starts.data(), starts.size() * sizeof(float));
    return starts;
}

sbrt::GpuView GpuTracer::traced_view(const sbrt::Camera &camera, uint32_t loop_budget)
{
    sbrt::GpuView view = sbrt::make_gpu_view(tracer_, camera, loop_budget);
    if (tracer_.pyramid().levels() == 0)
        return view; // no skipping, no first pass
    const uint32_t side = uint32_t(sbrt::FIRST_PASS_TILE);
    const uint32_t tile_cols = (uint32_t(camera.cols()) + side - 1) / side;
    const uint32_t tile_rows = (uint32_t(camera.rows()) + side - 1) / side;
    view.counts[2] = 1;
    view.counts[3] = tile_cols;
    // the bounds of this camera are there already: the same view but for
    // the band's rows
    sbrt::GpuView key = view;
    key.options[1] = key.options[2] = key.options[3] = 0;
    if (tile_starts_ && std::memcmp(&key, &first_pass_view_, sizeof key) == 0)
        return view;
    const auto start = Clock::now();
    const size_t bytes = size_t(tile_cols) * tile_rows * sizeof(float);
    if (!tile_starts_ || tile_starts_->bytes() < bytes)
        tile_starts_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                             checked_bytes(bytes, max_block_bytes_, "first pass's tiles"));
    if (!first_pass_program_)
        first_pass_program_.emplace(
            gl_, pass_sources(Pass::first_pass, layout_, tracer_.model()), &cache_);
    first_pass_program_->use();
    view_.upload(&view, sizeof view);
    view_.bind(0);
    pyramid_.bind(4);
    tile_starts_->bind(8);
    gl_.DispatchCompute(GLuint((tile_cols + 7) / 8), GLuint((tile_rows + 7) / 8), 1);
    gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    check_gl(gl_, "the first pass");
    first_pass_view_ = key;
    stats_.trace_ms += ms_since(start);
    return view;
}

void GpuTracer::dispatch(const sbrt::Camera &camera, sbrt::GpuView &view, int first_row,
                         int row_count, GlBuffer &buffer, size_t bytes_per_pixel, void *out)
{
    const int cols = camera.cols();
    const size_t row_bytes = size_t(cols) * bytes_per_pixel;
    const int band_rows = int(buffer.bytes() / row_bytes);
    buffer.bind(2);
    for (int first = first_row; first < first_row + row_count; first += band_rows) {
        const int count = std::min(band_rows, first_row + row_count - first);
        view.options[2] = uint32_t(first);
        view.options[3] = uint32_t(count);
        view_.upload(&view, sizeof view); // stays bound to index 0
        auto start = Clock::now();
        gl_.DispatchCompute(GLuint((cols + 7) / 8), GLuint((count + 7) / 8), 1);
        gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        gl_.Finish();
        check_gl(gl_, "the ray casting dispatch");
        stats_.trace_ms += ms_since(start);
        start = Clock::now();
        buffer.download(static_cast<uint8_t *>(out) + size_t(first - first_row) * row_bytes,
                        size_t(count) * row_bytes);
        stats_.readback_ms += ms_since(start);
        ++stats_.bands;
    }
}

namespace {

/// A storage buffer for up to `rows` rows of `row_bytes`, within the GPU's
/// largest binding: the one in `buffer` where it is large enough.
void ensure_band_buffer(const GlApi &gl, std::optional<GlBuffer> &buffer, int rows,
                        size_t row_bytes, size_t max_block_bytes)
{
    if (row_bytes > max_block_bytes)
        sbrt::fail("an image row of ", row_bytes, " bytes does not fit a storage buffer");
    const size_t bytes = std::min(size_t(rows), max_block_bytes / row_bytes) * row_bytes;
    if (!buffer || buffer->bytes() < bytes)
        buffer.emplace(gl, GL_SHADER_STORAGE_BUFFER, bytes);
}

} // namespace

void GpuTracer::trace_rows(const sbrt::Camera &camera, int first_row, int row_count,
                           sbrt::Hit *out, unsigned cpu_threads, uint32_t loop_budget)
{
    const int cols = camera.cols();
    ensure_band_buffer(gl_, band_, row_count, size_t(cols) * sizeof(sbrt::GpuPixelHit),
                       max_block_bytes_);
    records_.resize(size_t(row_count) * cols);
    sbrt::GpuView view = traced_view(camera, loop_budget);
    record_program().use();
    bind_model();
    dispatch(camera, view, first_row, row_count, *band_, sizeof(sbrt::GpuPixelHit),
             records_.data());

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

GlComputeProgram &GpuTracer::shading_program(const sbrt::Shading &shading, bool kernel)
{
    const bool draped = shading.drape != nullptr;
    std::optional<GlComputeProgram> &program =
        kernel ? (draped ? kernel_drape_program_ : kernel_program_)
               : (draped ? drape_program_ : shade_program_);
    if (!program) {
        const auto start = Clock::now();
        program.emplace(gl_,
                        pass_sources(kernel ? Pass::kernel_shade : Pass::shade, layout_,
                                     tracer_.model(), draped),
                        &cache_);
        stats_.upload_ms += ms_since(start);
    }
    if (!looks_) {
        const std::vector<sbrt::GpuLook> looks = sbrt::make_gpu_looks(tracer_);
        looks_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, looks.size() * sizeof(sbrt::GpuLook),
                       looks.data());
        shade_.emplace(gl_, GL_UNIFORM_BUFFER, sizeof(sbrt::GpuShade));
    }
    if (draped && shading.drape != drape_on_gpu_) {
        // a GpuTracer meets one Drape (the module's, or the view server's
        // until it prepares the scene again: a new GpuTracer)
        const auto start = Clock::now();
        const std::vector<uint32_t> words = sbrt::make_gpu_drape(tracer_, *shading.drape);
        drape_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                       checked_bytes(words.size() * sizeof(uint32_t), max_block_bytes_,
                                     "drape (surface and texture)"),
                       words.data());
        drape_on_gpu_ = shading.drape;
        stats_.upload_ms += ms_since(start);
    }
    return *program;
}

void GpuTracer::bind_shading(const sbrt::GpuShade &shade, const sbrt::Shading &shading)
{
    shade_->upload(&shade, sizeof shade);
    shade_->bind(1);
    looks_->bind(5);
    if (shading.drape)
        drape_->bind(7);
}

void GpuTracer::shade_rows(const sbrt::Camera &camera, int first_row, int row_count,
                           const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                           sbrt::Band &band, unsigned cpu_threads)
{
    const sbrt::GpuShade shade = sbrt::make_gpu_shade(tracer_, shading, outputs);
    GlComputeProgram &program = shading_program(shading, false);
    const int cols = camera.cols();
    const size_t words_per_pixel = shade.outputs[0];
    ensure_band_buffer(gl_, pixels_, row_count, size_t(cols) * words_per_pixel * 4,
                       max_block_bytes_);
    words_.resize(size_t(row_count) * cols * words_per_pixel);
    sbrt::GpuView view = traced_view(camera, loop_budget_);
    program.use();
    bind_model();
    bind_shading(shade, shading);
    dispatch(camera, view, first_row, row_count, *pixels_, words_per_pixel * 4,
             words_.data());
    unpack_words(camera, first_row, row_count, shading, outputs, words_per_pixel, band,
                 cpu_threads);
}

bool GpuTracer::kernel_fits(const sbrt::Camera &camera) const
{
    const size_t pixels = size_t(camera.rows()) * size_t(camera.cols());
    return !camera.is_window() && pixels * sizeof(sbrt::GpuPixelHit) <= max_block_bytes_;
}

void GpuTracer::prepare_kernel(const sbrt::Camera &camera, const sbrt::Shading &shading)
{
    if (!kernel_fits(camera))
        sbrt::fail("kernel normals on the GPU: the image's hit records do not fit one "
                   "storage buffer");
    const int rows = camera.rows(), cols = camera.cols();
    const size_t pixels = size_t(rows) * size_t(cols);
    // 1. the hit records of the whole image, kept on the GPU
    if (!image_hits_ || image_hits_->bytes() < pixels * sizeof(sbrt::GpuPixelHit)) {
        image_hits_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, pixels * sizeof(sbrt::GpuPixelHit));
        depths_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, pixels * sizeof(float));
    }
    sbrt::GpuView view = traced_view(camera, loop_budget_);
    view.options[2] = 0;
    view.options[3] = uint32_t(rows);
    record_program().use();
    bind_model();
    view_.upload(&view, sizeof view);
    image_hits_->bind(2);
    auto start = Clock::now();
    gl_.DispatchCompute(GLuint((cols + 7) / 8), GLuint((rows + 7) / 8), 1);
    gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    // 2. the kernel's cells and camera, and every pixel's view depth
    const sbrt::KernelNormals kernel(tracer_, camera, shading.kernel);
    kernel_ = sbrt::make_gpu_kernel(tracer_, camera, kernel);
    const std::vector<float> cells = sbrt::make_gpu_kernel_cells(kernel);
    kernel_cells_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, cells.size() * sizeof(float),
                          cells.data());
    if (!kernel_block_)
        kernel_block_.emplace(gl_, GL_UNIFORM_BUFFER, sizeof(sbrt::GpuKernel));
    kernel_block_->upload(&kernel_, sizeof kernel_);
    if (!kernel_depth_program_)
        kernel_depth_program_.emplace(
            gl_, pass_sources(Pass::kernel_depth, layout_, tracer_.model()), &cache_);
    kernel_depth_program_->use();
    view_.bind(0);
    kernel_block_->bind(2);
    image_hits_->bind(0);
    depths_->bind(1);
    gl_.DispatchCompute(GLuint((cols + 7) / 8), GLuint((rows + 7) / 8), 1);
    gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gl_.Finish();
    check_gl(gl_, "the kernel normals' trace and depth passes");
    stats_.trace_ms += ms_since(start);
}

void GpuTracer::shade_kernel_rows(const sbrt::Camera &camera, int first_row, int row_count,
                                  const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                                  sbrt::Band &band, unsigned cpu_threads)
{
    const sbrt::GpuShade shade = sbrt::make_gpu_shade(tracer_, shading, outputs);
    GlComputeProgram &program = shading_program(shading, true);
    const int cols = camera.cols();
    const size_t words_per_pixel = shade.outputs[0], row_bytes = size_t(cols) * words_per_pixel * 4;
    ensure_band_buffer(gl_, pixels_, row_count, row_bytes, max_block_bytes_);
    words_.resize(size_t(row_count) * cols * words_per_pixel);
    sbrt::GpuView view = sbrt::make_gpu_view(tracer_, camera, loop_budget_);
    view_.upload(&view, sizeof view);
    program.use();
    view_.bind(0);
    bind_shading(shade, shading);
    kernel_block_->bind(2);
    image_hits_->bind(0);
    depths_->bind(1);
    kernel_cells_->bind(4);
    pixels_->bind(2);
    const int band_rows = int(pixels_->bytes() / row_bytes);
    for (int first = first_row; first < first_row + row_count; first += band_rows) {
        const int count = std::min(band_rows, first_row + row_count - first);
        kernel_.counts[1] = uint32_t(first);
        kernel_.counts[2] = uint32_t(count);
        kernel_block_->upload(&kernel_, sizeof kernel_);
        auto start = Clock::now();
        gl_.DispatchCompute(GLuint((cols + 7) / 8), GLuint((count + 7) / 8), 1);
        gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        gl_.Finish();
        check_gl(gl_, "the kernel normals' shading pass");
        stats_.trace_ms += ms_since(start);
        start = Clock::now();
        pixels_->download(reinterpret_cast<uint8_t *>(words_.data()) +
                              size_t(first - first_row) * row_bytes,
                          size_t(count) * row_bytes);
        stats_.readback_ms += ms_since(start);
        ++stats_.bands;
    }
    unpack_words(camera, first_row, row_count, shading, outputs, words_per_pixel, band,
                 cpu_threads);
}

void GpuTracer::unpack_words(const sbrt::Camera &camera, int first_row, int row_count,
                             const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                             size_t words_per_pixel, sbrt::Band &band, unsigned cpu_threads)
{
    // the words into the band; rays over the budget traced and shaded here
    // (with their face normals)
    const int cols = camera.cols();
    const auto start = Clock::now();
    std::vector<size_t> over_per_row(size_t(row_count), 0);
    const sbrt::PixelShader shader(tracer_.model(), shading);
    sbrt::for_each_row(first_row, first_row + row_count, cpu_threads, [&](int row) {
        for (int col = 0; col < cols; ++col) {
            const size_t i = size_t(row - band.first_row) * cols + col;
            const uint32_t *w = words_.data() + size_t(row - first_row) * cols * words_per_pixel +
                                size_t(col) * words_per_pixel;
            if ((w[0] >> 24) == 0) {
                const sbrt::Hit hit = tracer_.trace(camera.ray(row, col));
                sbrt::shade_into_band(tracer_, shader, camera, hit, row, col, band);
                ++over_per_row[size_t(row - first_row)];
                continue;
            }
            for (int k = 0; k < 3; ++k)
                band.rgb[i * 3 + size_t(k)] = uint8_t(w[0] >> (8 * k));
            size_t next = 1;
            auto as_float = [](uint32_t bits) {
                float f;
                std::memcpy(&f, &bits, 4);
                return double(f);
            };
            if (outputs.material)
                band.material[i] = int32_t(w[next++]);
            if (outputs.elevation)
                band.elevation[i] = as_float(w[next++]);
            if (outputs.depth)
                band.depth[i] = as_float(w[next++]);
        }
    });
    for (size_t n : over_per_row)
        stats_.over_budget += n;
    stats_.readback_ms += ms_since(start);
}

} // namespace sbrt_gl
