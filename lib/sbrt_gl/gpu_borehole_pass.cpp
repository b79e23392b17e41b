/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The boreholes' pass over the tiles their boxes may cover
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_borehole_pass.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include "gpu_internal.hpp"
#include "gpu_stats.hpp"
#include "gpu/gpu_overlays.hpp"
#include "util/error.hpp"

namespace sbrt_gl {

namespace {

/// The 8 x 8 tiles of a band of `count` rows of `camera`'s image.
size_t band_tiles(const sbrt::Camera &camera, int count)
{
    return size_t((camera.cols() + 7) / 8) * size_t((count + 7) / 8);
}

} // namespace

BoreholePass::BoreholePass(const PassContext &passes)
    : passes_(passes), gl_(passes.gl), tracer_(passes.tracer),
      max_block_bytes_(passes.max_block_bytes)
{
}

size_t BoreholePass::scratch_bytes(const sbrt::Camera &camera,
                                   const sbrt::GpuBandLayout &layout) const
{
    const size_t boxes = tracer_.overlay_boxes().size();
    // GL takes at least 65535 work groups a dimension: the cull's a box,
    // the boreholes' pass's a tile of the band
    const size_t tiles = band_tiles(camera, layout.rows);
    if (tiles > 65535 || boxes > 65535)
        sbrt::fail("boreholes with the model on the GPU: ", boxes, " boreholes over bands of ",
                   tiles,
                   " tiles, more than one dispatch takes (65535): fewer rows a band or "
                   "fewer boreholes");
    // each pixel's t of its hit in the model's pass, then each tile's
    // farthest, for the boreholes' pass and its culling
    return checked_bytes((size_t(layout.rows) * size_t(camera.cols()) + tiles) * sizeof(float),
                         max_block_bytes_, "hits' distances");
}

GlBuffer &BoreholePass::tile_list(const sbrt::Camera &camera, bool every_tile, int first,
                                  int count, int slot)
{
    const sbrt::GpuTileHead head =
        sbrt::make_gpu_tile_head(tracer_, camera, first, count,
                                 uint32_t(tracer_.overlay_boxes().size()), every_tile ? 0 : 8);
    const std::vector<uint32_t> words =
        every_tile ? sbrt::gpu_every_tile_list(head)
                   : std::vector<uint32_t>(reinterpret_cast<const uint32_t *>(&head),
                                           reinterpret_cast<const uint32_t *>(&head + 1));
    const size_t bytes =
        checked_bytes(size_t(head.words) * 4, max_block_bytes_, "boreholes' tiles");
    std::optional<GlBuffer> &list = tile_lists_[size_t(slot)];
    if (!list || list->bytes() < bytes) // room to grow
        list.emplace(gl_, GL_SHADER_STORAGE_BUFFER, std::min(bytes + bytes / 2, max_block_bytes_));
    list->write(0, words.data(), words.size() * 4);
    if (!every_tile) {
        // no box counted in any tile yet
        const GLuint zero = 0;
        gl_.ClearBufferSubData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GLintptr(head.counts_at) * 4,
                               GLsizeiptr(band_tiles(camera, count)) * 4, GL_RED_INTEGER,
                               GL_UNSIGNED_INT, &zero);
    }
    return *list;
}

void BoreholePass::dispatch(const sbrt::Camera &camera, GlComputeProgram &shade,
                            bool every_tile, int first, int count, int slot)
{
    GpuStats &stats = passes_.stats;
    PassTimer &timer = passes_.timer;
    const size_t all_tiles = band_tiles(camera, count);
    stats.tiles += all_tiles;
    // the band's tiles a box reaches: listed by the GPU (or every tile by
    // the host)
    const auto listing = Clock::now();
    const GlBuffer &list = tile_list(camera, every_tile, first, count, slot);
    stats.borehole_list_ms += ms_since(listing);
    // then the boreholes' pass over them, as many work groups as tiles
    // listed
    const auto submit = Clock::now();
    list.bind(12);
    if (!every_tile) {
        // the model pass's farthest t of each tile before the culling
        // reads them
        gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        passes_.programs.get(Pass::cull_tiles).use();
        timer.time(int(Pass::cull_tiles), [&] {
            gl_.DispatchCompute(GLuint(tracer_.overlay_boxes().size()), 1, 1);
        });
    }
    // the list and the model pass's hits before the pass reads them (and
    // the count before it is copied out)
    gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT |
                      GL_BUFFER_UPDATE_BARRIER_BIT);
    shade.use();
    timer.time(int(Pass::shade_boreholes), [&] {
        if (every_tile) {
            gl_.DispatchCompute(GLuint(all_tiles), 1, 1);
            return;
        }
        gl_.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, list.name());
        gl_.DispatchComputeIndirect(0);
    });
    std::optional<MappedBuffer> &listed = tile_counts_[size_t(slot)];
    if (!listed)
        listed.emplace(gl_, sizeof(uint32_t));
    gl_.BindBuffer(GL_COPY_READ_BUFFER, list.name());
    gl_.BindBuffer(GL_COPY_WRITE_BUFFER, listed->name());
    gl_.CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, sizeof(uint32_t));
    stats.borehole_submit_ms += ms_since(submit);
}

uint32_t BoreholePass::listed(int slot) const
{
    uint32_t count = 0;
    if (tile_counts_[size_t(slot)])
        std::memcpy(&count, tile_counts_[size_t(slot)]->host(), sizeof count);
    return count;
}

} // namespace sbrt_gl
