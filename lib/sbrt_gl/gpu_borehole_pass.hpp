/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The boreholes' pass of a shaded band (boreholes drawn with the
 *            model): the band's 8 x 8 tiles that a borehole's box may
 *            cover, listed on the GPU (shaders/tile_cull.comp), then the
 *            model and the boreholes shaded again over those tiles alone
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_BOREHOLE_PASS_HPP
#define SBRT_GL_GPU_BOREHOLE_PASS_HPP

#include <array>
#include <cstdint>
#include <optional>

#include "gl_objects.hpp"
#include "gpu/gpu_layout.hpp"
#include "mapped_bands.hpp"
#include "gpu_pass_context.hpp"
#include "program_set.hpp"
#include "scene/camera.hpp"
#include "tracing/tracer.hpp"

namespace sbrt_gl {

/// \brief The boreholes' pass: its tile lists and their counts, one of each
/// for every slot of MappedBands (a band dispatched ahead writes its own
/// while the band before is still read). Holds the tracer's PassContext
/// by reference; the context must be current.
class BoreholePass {
public:
    explicit BoreholePass(const PassContext &passes);

    /// The bytes of scratch each slot needs for bands of `layout` (each
    /// pixel's t of its model hit, then each tile's farthest: binding 13);
    /// throws where a dispatch could not hold the band's tiles or boxes.
    size_t scratch_bytes(const sbrt::Camera &camera, const sbrt::GpuBandLayout &layout) const;
    /// Queues rows [first, first + count) of `camera`'s image into slot
    /// `slot`: its tiles a box reaches listed (by the GPU; by the host, all
    /// of them, where `every_tile`: the camera among the boxes), `shade`
    /// over them, the count listed copied out for the host. Adds to the
    /// tracer's figures.
    void dispatch(const sbrt::Camera &camera, GlComputeProgram &shade, bool every_tile,
                  int first, int count, int slot);
    /// The tiles listed in the band of slot `slot`, once it is done.
    uint32_t listed(int slot) const;

private:
    /// The head (or, every tile, the whole list) of the band's list,
    /// written into the slot's buffer.
    GlBuffer &tile_list(const sbrt::Camera &camera, bool every_tile, int first, int count,
                        int slot);

    const PassContext &passes_;
    const GlApi &gl_;
    const sbrt::Tracer &tracer_;
    size_t max_block_bytes_;
    /// the tiles of the band dispatched into each slot (binding 12):
    /// written only once the GPU is done with the slot
    std::array<std::optional<GlBuffer>, MappedBands::SLOTS> tile_lists_;
    /// the count of tiles listed, copied there for the host once the band
    /// is done (a read of GPU memory would wait for all queued)
    std::array<std::optional<MappedBuffer>, MappedBands::SLOTS> tile_counts_;
};

} // namespace sbrt_gl

#endif
