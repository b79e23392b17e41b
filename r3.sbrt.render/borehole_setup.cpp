/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Boreholes from points and logs
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "borehole_setup.hpp"

#include <algorithm>
#include <cmath>

#include "grass.hpp"
#include "vector_input.hpp"
#include "request_error.hpp"

namespace {

/// The material index of class `id`, added to the model when missing.
uint32_t material_of(sbrt::Model &model, int id)
{
    const int64_t k = model.find_material(id);
    if (k > 0)
        return uint32_t(k);
    if (model.materials().size() >= sbrt::MAX_MATERIALS)
        bad_request(_("log_class=: class %d would be material %zu, beyond the "
                        "supported %u"),
                      id, model.materials().size(), sbrt::MAX_MATERIALS - 1);
    G_verbose_message(_("Logged class %d is not in the model: drawn with a "
                        "palette colour"),
                      id);
    sbrt::Material m;
    m.id = id;
    model.materials().push_back(m);
    return uint32_t(model.materials().size() - 1);
}


} // namespace

std::vector<sbrt::Borehole> make_boreholes(const RenderRequest &request,
                                           const sbrt::Model &original,
                                           sbrt::Model &shown,
                                           const std::vector<uint32_t> &hidden)
{
    const BoreholeInput input = read_boreholes(request);
    const std::vector<BoreholePoint> &points = input.points;
    const std::map<int, std::vector<LogRow>> &logs = input.logs;
    const bool is_3d = input.is_3d;
    const sbrt::Frame &f = shown.frame();
    // with -b the cylinders are all there is, and hide= applies to them;
    // else they keep every class, to show what hide= took off the model
    const sbrt::Model &source = request.boreholes_only ? shown : original;
    const std::vector<uint32_t> no_hidden;
    const std::vector<uint32_t> &hidden_here = request.boreholes_only ? hidden : no_hidden;
    std::vector<sbrt::Borehole> boreholes;
    size_t outside = 0, unlogged = 0;
    for (const BoreholePoint &p : points) {
        if (!(p.x >= f.west && p.x < f.east && p.y > f.south && p.y <= f.north)) {
            if (outside++ < 5)
                G_warning(_("Borehole %d at %f,%f lies outside the model: skipped"),
                          p.cat, p.x, p.y);
            continue;
        }
        const int col = std::min(f.cols - 1, int((p.x - f.west) / f.ew_res()));
        const int row = std::min(f.rows - 1, int((f.north - p.y) / f.ns_res()));
        const uint64_t cell = shown.cell_index(row, col);
        sbrt::Borehole b;
        b.x = p.x;
        b.y = p.y;
        b.model_stack = source.stack_intervals(cell);
        b.stack = b.model_stack;
        const auto log = logs.find(p.cat);
        if (!request.log_class.empty() && log == logs.end())
            ++unlogged;
        else if (log != logs.end()) {
            // depths below the collar: the point's z, or the terrain there
            double collar = p.z;
            if (!is_3d) {
                const uint32_t n = original.stack_size(cell);
                collar = n ? f.bottom + f.tb_res() *
                                            original.intervals()[original.stack_end(cell) - 1].top
                           : f.bottom;
            }
            std::vector<sbrt::LoggedInterval> logged;
            for (const LogRow &row_ : log->second) {
                const double top = sbrt::log_elevation(row_.top, request.log_reference, collar);
                const double bottom =
                    sbrt::log_elevation(row_.bottom, request.log_reference, collar);
                if (!(top > bottom) || !std::isfinite(top) || !std::isfinite(bottom)) {
                    G_warning(_("Borehole %d: logged interval %g..%g (%s) is "
                                "empty: skipped"),
                              p.cat, row_.top, row_.bottom,
                              sbrt::log_reference_name(request.log_reference));
                    continue;
                }
                logged.push_back({bottom, top, material_of(shown, row_.class_id)});
            }
            b.stack = sbrt::log_stack(f, std::move(logged), hidden_here);
        }
        boreholes.push_back(std::move(b));
    }
    if (outside > 5)
        G_warning(_("%zu boreholes outside the model skipped in all"), outside);
    if (unlogged)
        G_warning(_("%zu boreholes have no logged intervals: they show the "
                    "model's stack"),
                  unlogged);
    if (boreholes.empty())
        bad_request(_("None of the %zu points of boreholes=%s lies on the model"),
                      points.size(), request.boreholes.c_str());
    return boreholes;
}

void report_borehole_bytes(const sbrt::Model &model,
                           const std::vector<sbrt::Borehole> &boreholes,
                           bool only)
{
    size_t intervals = 0;
    for (const sbrt::Borehole &b : boreholes)
        intervals += b.stack.size() + b.model_stack.size();
    const size_t borehole_bytes =
        intervals * sizeof(sbrt::Interval) + boreholes.size() * sizeof(sbrt::Borehole);
    const size_t model_bytes = size_t(model.memory_bytes());
    G_verbose_message(_("Boreholes: %zu cylinders holding %zu intervals (%zu "
                        "bytes); the model: %zu intervals in %llu cells (%zu "
                        "bytes)%s"),
                      boreholes.size(), intervals, borehole_bytes,
                      model.intervals().size(),
                      (unsigned long long)model.frame().cells(), model_bytes,
                      only ? _("; -b traces the borehole stacks only") : "");
}
