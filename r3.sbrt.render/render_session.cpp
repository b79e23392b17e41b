/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   One render session shared by the command line, its animation
 *            loop and the view server
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "render_session.hpp"

#include <cmath>
#include <sstream>

#include "frame_cameras.hpp"
#include "material_colors.hpp"
#include "model_reading.hpp"
#include "prepared_scene.hpp"
#include "property_colors.hpp"
#include "sbrt_store.hpp"
#include "request_error.hpp"
#include "scene/camera_path.hpp"
#include "scene_setup.hpp"
#include "skipping_report.hpp"
#include "texture_input.hpp"
#include "builders/voxel_selection.hpp"
#include "format/paged_stacks.hpp"
#include "frame/fitting_exaggeration.hpp"
#include "tracing/scene_pruning.hpp"

namespace {

/// The key of each stage: the keys of the request's parts it consumes
/// (each part keys itself beside its options, *_part.cpp).

/// The model as read: its input and colours, and where only the blocks
/// under the region are read, the region.
std::string model_key(const RenderRequest &request, const struct Cell_head &region)
{
    std::ostringstream key;
    key << std::hexfloat << key_of<InputPart, ColorsPart>(request);
    // (detail= is not in it: the session keeps a level of each detail)
    if (reads_pages(request))
        key << "\npaged";
    // (a paged read may fall back to the region's blocks: an SBRT with
    // channels or older than 2.1)
    if (sees_only_the_region(request))
        key << region.north << ' ' << region.south << ' ' << region.east << ' '
            << region.west;
    return key.str();
}

/// The prepared scene, the camera's share included (the planes of
/// section= and the split direction of -m face it). Camera, light and
/// outputs are not in it: the shading is set for every frame.
std::string scene_key(const RenderRequest &r, const sbrt::Camera &camera)
{
    return key_of<ExaggerationPart, BackendPart, StrataPart, SelectionPart>(r) +
           r.SectionsPart::key(camera) + '\n' + r.BoreholesPart::key(camera);
}

} // namespace

void RenderSession::load(RenderRequest &request, const struct Cell_head &region)
{
    const std::string key = model_key(request, region);
    request.drawn_factor = 1;
    at_ = &levels_[0];
    if (request.coarse && use_coarse_level(request, key))
        at_ = &levels_[1];
    else if (!at_->model || key != at_->model_key) {
        drop_level(*at_);
        at_->model =
            std::make_unique<sbrt::Model>(read_model(request, region));
        apply_color_option(request, at_->model->materials());
        fit(*at_, sbrt::highest_top_local(*at_->model)); // once a model
        at_->model_key = key;
        at_->blocks_budget = at_->model->is_paged() ? at_->model->pages()->budget_bytes() : 0;
        share_budget_with_coarse_level();
    }
    if (request.zexag_fitted)
        request.zexag = at_->fitted_zexag;
    if (!at_->frame || at_->frame->zexag() != request.zexag)
        at_->frame.emplace(at_->model->frame(), request.zexag, at_->top_local);
}

bool RenderSession::use_coarse_level(RenderRequest &request, const std::string &key)
{
    // the property channels are stored for the exact model's columns
    if (!request.property.empty() || !request.select.empty() || !request.fade.empty()) {
        G_important_message(_("detail=coarse: property=, select= and fade= draw the "
                              "exact model (its property channels are the exact "
                              "model's): this frame is exact"));
        return false;
    }
    Level &coarse = levels_[1];
    if (!coarse.model || coarse.model_key != key) {
        if (key == no_coarse_key_)
            return false;
        drop_level(coarse);
        // room for the coarse level while it is read: the exact model's
        // blocks down to the least share_budget_with_coarse_level leaves
        if (levels_[0].model && levels_[0].model->is_paged())
            levels_[0].model->pages()->set_budget_bytes(levels_[0].blocks_budget / 2);
        std::optional<sbrt::CoarseLevel> level =
            sbrt_grass::read_sbrt_lod_map(request.input.c_str());
        if (!level) {
            share_budget_with_coarse_level();
            G_important_message(_("SBRT <%s> has no coarse level of detail (under 512 x 512 "
                                  "cells, or imported before r3.sbrt stored one): "
                                  "detail=coarse draws the exact model"),
                                request.input.c_str());
            no_coarse_key_ = key;
            return false;
        }
        coarse.factor = level->factor();
        coarse.model = std::make_unique<sbrt::Model>(std::move(level->model));
        apply_color_option(request, coarse.model->materials());
        fit(coarse, std::isfinite(level->exact_top_local)
                        ? level->exact_top_local
                        : sbrt::highest_top_local(*coarse.model));
        coarse.model_key = key;
        share_budget_with_coarse_level();
        G_important_message(_("detail=coarse: a coarse frame of SBRT <%s>, 1 cell in %d a "
                              "side (%d x %d cells), not exact"),
                            request.input.c_str(), coarse.factor, coarse.model->frame().rows,
                            coarse.model->frame().cols);
    }
    request.drawn_factor = coarse.factor;
    return true;
}

void RenderSession::fit(Level &level, double top_local)
{
    // fitting_exaggeration(model) of the exact model
    level.top_local = top_local;
    level.fitted_zexag = sbrt::fitting_exaggeration(level.model->frame(), top_local);
}

void RenderSession::share_budget_with_coarse_level()
{
    Level &exact = levels_[0], &coarse = levels_[1];
    if (!exact.model || !exact.model->is_paged())
        return;
    // the coarse model decoded whole, the prepared scene's copy of it and
    // the pyramid over its cells
    const uint64_t coarse_bytes =
        coarse.model
            ? 2 * coarse.model->memory_bytes() + sbrt::skipping_bytes(coarse.model->frame())
            : 0;
    exact.model->pages()->set_budget_bytes(
        exact.blocks_budget - std::min(coarse_bytes, exact.blocks_budget / 2));
}

void RenderSession::drop_level(Level &level)
{
    drop_scene(level);
    level = Level{};
}

std::vector<sbrt::Camera> RenderSession::cameras(const RenderRequest &request,
                                                 const struct Cell_head &region) const
{
    std::vector<sbrt::Camera> cameras = frame_cameras(request, *at_->model, *at_->frame, region);
    if (request.tile)
        for (sbrt::Camera &camera : cameras)
            camera = camera.window((*request.tile)[0], (*request.tile)[2],
                                   (*request.tile)[1], (*request.tile)[3]);
    return cameras;
}

void RenderSession::prepare(const RenderRequest &request, const sbrt::Camera &camera,
                            bool one_view)
{
    prepare_drape(request);
    prepare_property(request);
    prepare_selection(request);
    prepare_scene_for(request, camera, one_view);
    if (at_->renderer)
        at_->renderer->set_shading(
            make_shading(request, at_->drape.get(), at_->property.get(), at_->fade.get()));
}

void RenderSession::prepare_drape(const RenderRequest &request)
{
    // the drape of texture=
    const std::string drape = key_of<DrapePart>(request);
    if (drape != at_->drape_key) {
        drop_scene();
        at_->drape.reset();
        at_->drape_key.clear();
        if (!request.texture.empty())
            at_->drape = std::make_unique<sbrt::Drape>(*at_->model, read_texture(request.texture),
                                                   request.texture_blend);
        at_->drape_key = drape;
    }
}

void RenderSession::prepare_property(const RenderRequest &request)
{
    // the property of property=, over the model as read
    const std::string property = key_of<PropertyPart>(request);
    if (property != at_->property_key) {
        at_->property.reset();
        at_->fade.reset();
        at_->property_key.clear();
        if (!request.fade.empty()) {
            const sbrt::PropertyChannels &all = *channels(request);
            RenderRequest asked = request;
            asked.property = {request.fade};
            const std::vector<size_t> channel = property_channels(asked, &all);
            const sbrt::ChannelInfo &info = all.info(channel[0]);
            // a channel in % (its unit or its kind) fades over 0-100
            const sbrt::ChannelKind kind = info.known_kind();
            const bool in_percent = info.unit == "%" || kind == sbrt::ChannelKind::probability ||
                                    kind == sbrt::ChannelKind::percentage;
            double low = 0, high = in_percent ? 100 : info.physical(float(info.max));
            if (request.fade_range) {
                low = (*request.fade_range)[0];
                high = (*request.fade_range)[1];
            }
            if (!(high > low))
                bad_request(_("fade=%s: its values go up to %g only; give fade_range=low,high"),
                            request.fade.c_str(), high);
            at_->fade = std::make_unique<sbrt::UncertaintyFade>(*at_->model, at_->channels, channel[0],
                                                            low, high);
        }
        if (!request.property.empty()) {
            const std::vector<size_t> summed = property_channels(request, channels(request));
            const auto [low, high] = property_range(*at_->channels, summed);
            at_->property = std::make_unique<sbrt::PropertyPaint>(
                *at_->model, at_->channels, summed,
                property_ramp(request.property_color, low, high));
            at_->property_frames = 0;
        }
        at_->property_key = property;
    }
}

void RenderSession::prepare_selection(const RenderRequest &request)
{
    // select=: only the voxels meeting the condition are solid
    const std::string selection = key_of<SelectionPart>(request);
    if (selection != at_->selection_key) {
        drop_scene();
        at_->selected.reset();
        at_->selection_key.clear();
        if (!request.select.empty()) {
            const sbrt::PropertyChannels &all = *channels(request);
            sbrt::Selection selection;
            try {
                selection = sbrt::parse_selection(request.select, all);
            }
            catch (const sbrt::Error &e) {
                bad_request(_("select=%s: %s"), request.select.c_str(), e.what());
            }
            at_->selected = std::make_unique<sbrt::Model>(
                sbrt::select_voxels(*at_->model, all, selection, unsigned(request.threads)));
            const sbrt::Stats s = at_->selected->stats();
            G_verbose_message(_("select=%s: %llu solid intervals of %llu"),
                              request.select.c_str(), (unsigned long long)s.solid_intervals,
                              (unsigned long long)at_->model->stats().solid_intervals);
        }
        at_->selection_key = selection;
    }
}

void RenderSession::prepare_scene_for(const RenderRequest &request, const sbrt::Camera &camera,
                                      bool one_view)
{
    const std::string key = scene_key(request, camera);
    if (!at_->renderer || key != at_->scene_key) {
        drop_scene();
        const std::string context = key_of<BackendPart>(request);
        if (context != context_key_) {
            for (Level &level : levels_) // their backends use the context
                if (&level != at_)
                    drop_scene(level);
            kept_atlas_.reset(); // its GL objects are the context's
            context_.reset();    // before another on the same display
            context_key_.clear();
            context_ = choose_gl_context(request);
            context_key_ = context;
        }
        // hidden strata (crossed as air while tracing: no pass over the
        // model), planes, boreholes, fence, translucency
        PreparedScene prepared =
            prepare_scene(request, at_->selected ? *at_->selected : *at_->model, camera);
        // on a GPU what no ray of a single view reaches is not uploaded
        // (the CPU never reads it anyway; a paged model's blocks go up as
        // rays reach them)
        const sbrt::Scene &scene = prepared.scene;
        if (one_view && context_ && scene.skip_empty_space && scene.draw_model &&
            !prepared.model.is_paged()) {
            sbrt::Pruning pruning =
                sbrt::prune_for_view(prepared.model, request.zexag, scene, camera);
            report_pruning(pruning, scene.planes.size());
            prepared.model = std::move(pruning.model);
        }
        at_->request = std::make_unique<RenderRequest>(request);
        const bool sweep = request.frames > 1 && request.path == sbrt::PathKind::sweep;
        if (sweep) { // each frame's renderer moves the plane (sweep_to)
            at_->prepared_model = std::make_unique<sbrt::Model>(std::move(prepared.model));
            at_->prepared_scene = std::move(prepared.scene);
        }
        else {
            build_renderer(std::move(prepared.model), std::move(prepared.scene));
            report_pyramid(at_->renderer->tracer().pyramid(), at_->renderer->model());
        }
        at_->scene_key = key;
    }
}

const sbrt::PropertyChannels *RenderSession::stored_channels(const RenderRequest &request)
{
    if (!at_->channels)
        at_->channels = sbrt_grass::read_channels_map(request.input.c_str(), *at_->model);
    return at_->channels.get();
}

const sbrt::PropertyChannels *RenderSession::channels(const RenderRequest &request)
{
    if (!stored_channels(request))
        bad_request(_("SBRT <%s> has no property channels: property= and select= need an "
                      "SBRT imported with properties= (r3.sbrt.convert file=... "
                      "properties=...)"),
                    request.input.c_str());
    return at_->channels.get();
}

void RenderSession::sweep_to(int k)
{
    if (!at_->prepared_model)
        bad_request(_("Internal error: a sweep's frame without a sweep"));
    sbrt::Scene swept = at_->prepared_scene;
    // the sweep moves the first plane= (else section=) across the box of
    // the model as prepared
    const sbrt::CoordinateFrame box =
        sbrt::CoordinateFrame::of(*at_->prepared_model, at_->request->zexag);
    swept.planes.front() =
        sbrt::swept_plane(at_->prepared_scene.planes.front(), box, k, at_->request->frames);
    at_->backend.reset(); // it refers to the previous frame's renderer
    at_->renderer.reset();
    build_renderer(*at_->prepared_model, std::move(swept));
}

void RenderSession::drop_scene()
{
    drop_scene(*at_);
}

void RenderSession::drop_scene(Level &level)
{
    level.backend.reset(); // it refers to the renderer
    level.renderer.reset();
    level.prepared_model.reset();
    level.scene_key.clear();
}

void RenderSession::build_renderer(sbrt::Model model, sbrt::Scene scene)
{
    at_->renderer = std::make_unique<sbrt::Renderer>(
        std::move(model), at_->request->zexag, std::move(scene),
        make_shading(*at_->request, at_->drape.get(), at_->property.get(), at_->fade.get()),
        sbrt::RenderSettings{unsigned(at_->request->threads), true, 0});
    at_->backend =
        std::make_unique<Backend>(*at_->request, *at_->renderer, context_.get(), &kept_atlas_);
}

void RenderSession::render(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                           const sbrt::BandSink &sink)
{
    // a property's sums are kept per block once a second frame shows it
    if (at_->property && at_->property_frames++ > 0)
        at_->property->keep_block_sums();
    at_->backend->render(camera, outputs, sink);
}
