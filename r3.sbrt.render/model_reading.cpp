/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Reading the part of an SBRT a render needs
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model_reading.hpp"

extern "C" {
#include <grass/glocale.h>
}

#include "request_error.hpp"
#include "sbrt_store.hpp"
#include "gl_context.hpp"
#include "scene_camera.hpp"
#include "column_reading.hpp"

bool sees_only_the_region(const RenderRequest &request)
{
    return request.view.kind == sbrt::ViewKind::top && request.frames == 1 &&
           request.depth.empty() && request.boreholes.empty() && request.fence.empty();
}

bool reads_pages(const RenderRequest &request)
{
    // the rays alone read the stacks (boreholes, fences, drapes and
    // property channels and value= read them whole); a GPU takes a paged
    // model's blocks into its atlas in layout=ssbo, the whole model else
    const bool cpu = request.backend == "cpu" ||
                     (request.backend == "auto" && sbrt_gl::gpu_device_node().empty());
    return (cpu || request.gpu_layout == "ssbo") && request.boreholes.empty() &&
           request.fence.empty() && request.texture.empty() && request.property.empty() &&
           request.fade.empty() && request.select.empty() && request.value.empty();
}

namespace {

/// The paged model of the request's input, or nothing where its stacks
/// are older than format 2.1 or it has property channels.
std::optional<sbrt::Model> read_paged_model(const RenderRequest &request,
                                            const struct Cell_head &region)
{
    const std::optional<sbrt::ModelSummary> summary =
        sbrt_grass::read_sbrt_summary_map(request.input.c_str());
    if (!summary || summary->has_channels) // channels lie along whole columns
        return std::nullopt;
    // an image too large is that error, not a budget's
    const bool top = request.view.kind == sbrt::ViewKind::top;
    check_image_fits(request, top ? region.rows : request.height,
                     top ? region.cols : request.width);
    sbrt::Paging paging;
    paging.budget_bytes = request.memory_bytes;
    paging.threads = unsigned(request.threads > 0 ? request.threads : 0);
    // memory= bounds the process: beside the model it holds itself (code,
    // GRASS), a block a tracing thread, and the image's buffers
    paging.reserved_bytes = sbrt_grass::reserved_beside_blocks(*summary, paging.threads) +
                            uint64_t(image_memory(request, region));
    try {
        sbrt::block_budget(*summary, paging);
    }
    catch (const sbrt::Error &e) {
        if (request.memory_given)
            bad_request(_("SBRT <%s>: %s"), request.input.c_str(), e.what());
        // the default gives way: the least that works, with room for
        // blocks held as long as GRASS's default would hold them
        const uint64_t least = sbrt::least_budget(*summary, paging);
        paging.budget_bytes = least + request.memory_bytes / 2;
        G_verbose_message(_("SBRT <%s> needs more than the default memory=%.0f MB: %.0f MB "
                            "given to it (give memory= to choose)"),
                          request.input.c_str(), double(request.memory_bytes) / (1 << 20),
                          double(paging.budget_bytes) / (1 << 20));
    }
    std::optional<sbrt::Model> model =
        sbrt_grass::read_sbrt_paged_map(request.input.c_str(), paging);
    if (model)
        G_verbose_message(_("SBRT <%s> paged: its %d blocks decoded as the rays reach "
                            "them, at most %.0f MB held (memory=)"),
                          request.input.c_str(), model->pages()->block_count(),
                          double(paging.budget_bytes) / (1 << 20));
    return model;
}

} // namespace

sbrt::Model read_model(const RenderRequest &request, const struct Cell_head &region)
{
    if (reads_pages(request))
        if (std::optional<sbrt::Model> model = read_paged_model(request, region))
            return std::move(*model);
    sbrt::ReadOptions options;
    sbrt::ReadReport report;
    options.report = &report;
    if (sees_only_the_region(request))
        options.area = sbrt::MapArea{region.north, region.south, region.east, region.west};
    sbrt::Model model = sbrt_grass::read_sbrt_map(request.input.c_str(), options);
    if (report.blocks)
        G_verbose_message(_("Read %llu of the %llu blocks of SBRT <%s>"),
                          (unsigned long long)report.blocks_read,
                          (unsigned long long)report.blocks, request.input.c_str());
    return model;
}
