/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   One render session: the model, its frame, the drape, the
 *            prepared scene, the shading and the backend, built from a typed
 *            request and kept while later requests leave them as they are;
 *            the command line, its animation loop and the view server all
 *            render through it
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_RENDER_SESSION_HPP
#define R3_SBRT_RENDER_SESSION_HPP

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backend.hpp"
#include "frame/coordinate_frame.hpp"
#include "render_options.hpp"
#include "renderer.hpp"
#include "shading/drape.hpp"
#include "shading/property_paint.hpp"

/// \brief The pipeline of a render request, stage by stage: load (the
/// model as read, its colours), frame (the cameras), prepare (hidden
/// strata, planes, boreholes, fence, translucency; pruning for one GPU
/// view), then render any number of cameras (trace, shade, write through a
/// sink). Each stage is rebuilt only when what it depends on changed.
/// Errors are sbrt::Error: the caller decides whether they end the run.
class RenderSession {
public:
    RenderSession() = default;
    RenderSession(const RenderSession &) = delete;
    RenderSession &operator=(const RenderSession &) = delete;

    /// Reads the model of `request` (a top view of one frame: only the
    /// blocks under `region`), where its input, colours or area changed;
    /// a request without zexag= gets the model's fitting exaggeration.
    /// detail=coarse: the SBRT's coarse level where it has one (each level
    /// is kept: going back to the other reads nothing), said by
    /// request.drawn_factor and an important message.
    void load(RenderRequest &request, const struct Cell_head &region);
    /// The model as read and its frame at the request's exaggeration: what
    /// cameras frame (the view stays put while strata are hidden or cut).
    const sbrt::Model &model() const { return *at_->model; }
    const sbrt::CoordinateFrame &frame() const { return *at_->frame; }
    /// The cameras of the request's frames (one for a single view).
    std::vector<sbrt::Camera> cameras(const RenderRequest &request,
                                      const struct Cell_head &region) const;

    /// Prepares the scene of `request` as `camera` sees it (sections and
    /// split logs face it) where it changed; with `one_view` a GPU gets only
    /// the stacks that rays of `camera` can reach.
    void prepare(const RenderRequest &request, const sbrt::Camera &camera, bool one_view);
    /// Frame k of a sweep (path=sweep): the first plane moved across the
    /// prepared model's box.
    void sweep_to(int k);
    /// Traces, shades and hands `camera`'s image band by band to `sink`.
    void render(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                const sbrt::BandSink &sink);
    /// The prepared model and scene.
    const sbrt::Renderer &renderer() const { return *at_->renderer; }
    /// The property shown (property=), or null.
    const sbrt::PropertyPaint *property() const { return at_->property.get(); }
    /// The uncertainty fade (fade=), or null.
    const sbrt::UncertaintyFade *fade() const { return at_->fade.get(); }
    /// The property channels of the loaded model (read once), or null for
    /// a model without them.
    const sbrt::PropertyChannels *stored_channels(const RenderRequest &request);

private:
    /// \brief The model of one level of detail (exact or coarse) and every
    /// stage built on it: the session keeps one of each, so that a view
    /// server switching between coarse frames while the camera moves and
    /// the exact frame when it rests reads and prepares neither again.
    struct Level {
        std::string model_key;
        std::unique_ptr<sbrt::Model> model;
        /// a paged model's budget for its blocks, as read
        uint64_t blocks_budget = 0;
        int factor = 1;           ///< fine cells a side per cell (1: exact)
        /// The exact model's highest top (local units): a coarse level is
        /// framed and exaggerated as the exact model
        double top_local = 0;
        double fitted_zexag = 1; ///< of model: what a request without zexag= gets
        std::optional<sbrt::CoordinateFrame> frame;
        std::string drape_key;
        std::unique_ptr<sbrt::Drape> drape;
        std::shared_ptr<const sbrt::PropertyChannels> channels; ///< of the model as read
        /// select=: the model with only the voxels meeting the condition
        std::string selection_key;
        std::unique_ptr<sbrt::Model> selected;
        std::string property_key;
        std::unique_ptr<sbrt::PropertyPaint> property;
        int property_frames = 0; ///< frames that showed property
        std::unique_ptr<sbrt::UncertaintyFade> fade;
        // the prepared scene; the backend refers to the request and renderer
        std::string scene_key;
        std::unique_ptr<RenderRequest> request;
        std::unique_ptr<sbrt::Model> prepared_model; ///< kept for a sweep
        sbrt::Scene prepared_scene;
        std::unique_ptr<sbrt::Renderer> renderer;
        std::unique_ptr<Backend> backend;
    };

    // the stages of prepare(), each rebuilt where its key changed
    void prepare_drape(const RenderRequest &request);
    void prepare_property(const RenderRequest &request);
    void prepare_selection(const RenderRequest &request);
    void prepare_scene_for(const RenderRequest &request, const sbrt::Camera &camera,
                           bool one_view);
    /// Whether `request` (detail=coarse) is drawn from the coarse level of
    /// model `key` (read where it is not held); sets request.drawn_factor.
    bool use_coarse_level(RenderRequest &request, const std::string &key);
    /// The level's box top (`top_local`) and the exaggeration a request
    /// without zexag= gets, from its model's extent and that top.
    static void fit(Level &level, double top_local);
    /// Forgets the level's model and every stage built on it.
    static void drop_level(Level &level);
    /// The coarse level, where held, takes its bytes from the paged exact
    /// model's blocks (up to half of their budget): the process stays
    /// within memory= with both.
    void share_budget_with_coarse_level();
    /// Forgets the prepared scene, its renderer and backend (of `level`;
    /// by default the level drawn).
    void drop_scene();
    static void drop_scene(Level &level);
    void build_renderer(sbrt::Model model, sbrt::Scene scene);
    /// The channels of the model as read (read once; bad_request without).
    const sbrt::PropertyChannels *channels(const RenderRequest &request);

    std::string context_key_;
    std::unique_ptr<sbrt_gl::GlContext> context_;
    /// a paged model's blocks on the GPU, kept from one scene to the next
    /// (a stratum hidden draws from the blocks already up); after the
    /// context, whose GL objects they are
    std::shared_ptr<sbrt_gl::GpuPageAtlas> kept_atlas_;
    /// exact, coarse; after the context (their backends use it)
    Level levels_[2];
    Level *at_ = &levels_[0]; ///< the level drawn
    /// The model key whose SBRT was found without a coarse level.
    std::string no_coarse_key_;
};

#endif
