/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Reading the part of an SBRT a render needs
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model_reading.hpp"

extern "C" {
#include <grass/glocale.h>
}

#include "sbrt_store.hpp"

bool sees_only_the_region(const RenderRequest &request)
{
    return request.view.kind == sbrt::ViewKind::top && request.frames == 1 &&
           request.depth.empty() && request.boreholes.empty() && request.fence.empty();
}

sbrt::Model read_model(const RenderRequest &request, const struct Cell_head &region)
{
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
