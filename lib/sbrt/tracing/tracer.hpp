/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Exact CPU reference ray caster (double precision): slab clip
 *            to the model's box, 2D DDA over the cells, and in each cell the
 *            z-range the ray covers selects the intervals it crosses
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TRACER_HPP
#define SBRT_TRACER_HPP

#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "frame/coordinate_frame.hpp"
#include "scene/camera.hpp"
#include "scene/minmax_pyramid.hpp"
#include "model/model.hpp"
#include "scene/scene.hpp"

namespace sbrt {

/// Face of a hit: which surface the ray entered the material through (a
/// cell's wall, an interval's bottom or top, a clip plane, a borehole's
/// mantle or the plane splitting it, a fence curtain).
enum class Face : uint8_t { none, west, east, south, north, bottom, top, plane,
                            cylinder, fence, split };

/// Outward unit normal of a cell face (zero for the other faces).
glm::dvec3 face_normal(Face face);

/// \brief What a ray meets: its first opaque hit (t in map units along the
/// ray), and the light of the translucent strata in front of it. One per
/// pixel, so kept small (72 bytes): the position in double precision, the
/// shading terms in single.
struct Hit {
    double t = std::numeric_limits<double>::infinity();
    glm::dvec3 point{0}; ///< real (unexaggerated) map coordinates
    glm::vec3 normal{0};
    /// Colour (0..1, premultiplied) the translucent strata add in front of
    /// the hit, and the share of the hit's (or background's) light that
    /// reaches the camera through them.
    glm::vec3 veil{0};
    float transmittance = 1;
    uint32_t material = EMPTY;
    Face face = Face::none;
    int8_t plane = -1; ///< the clip plane hit, with Face::plane
    bool is_hit() const { return material != EMPTY; }
};

/// Below this transmittance a ray stops: what is behind adds less than a
/// tenth of one 8-bit colour level.
constexpr double MIN_TRANSMITTANCE = 1.0 / 4096;

/// Slab clip of the ray o + t d to the box [low, high]: narrows [t_near,
/// t_far] and sets `near_axis` to the axis of the wall it enters through
/// (unchanged where no wall narrows t_near); false where the ray runs
/// parallel to a slab outside it.
/// `inv_d` is 1 / d per axis (taken where d is not 0).
bool clip_to_box(glm::dvec3 o, glm::dvec3 d, glm::dvec3 inv_d, glm::dvec3 low,
                 glm::dvec3 high, double &t_near, double &t_far, int &near_axis);

/// \brief Exact traversal of an SBRT. Rays are in map coordinates with
/// vertical exaggeration `zexag` applied about the model's bottom.
class Tracer {
public:
    Tracer(const Model &model, double zexag, Scene scene = {});
    Tracer(const Model &model, double zexag, std::vector<ClipPlane> planes);

    /// The first hit of `ray`; `t_start` (a lower bound of the hit's t, as a
    /// coarse first pass gives) lets the walk begin further along.
    Hit trace(const Ray &ray, double t_start = 0) const;
    /// The same into `hit` (whatever it held): the hit is written in
    /// place, field by field, never copied whole from a temporary.
    void trace_into(const Ray &ray, double t_start, Hit &hit) const;
    /// The same, a paged model's blocks looked up through `pin` (one a
    /// thread, kept from ray to ray: most rays start in the block the
    /// last one did).
    void trace_into(const Ray &ray, double t_start, Hit &hit, StackPin &pin) const;

    /// The model's coordinate frame as drawn (the box up to the highest
    /// top a ray can meet, boreholes' logs included).
    const CoordinateFrame &frame() const { return frame_; }
    const Model &model() const { return model_; }

    /// A clip plane in the local frame: f(l) = n . l + c, kept where f <= 0;
    /// `shading_normal` is its unit normal in exaggerated map space.
    struct LocalPlane {
        glm::dvec3 n;
        double c;
        glm::dvec3 shading_normal;
    };
    const std::vector<LocalPlane> &planes() const { return planes_; }
    double zexag() const { return frame_.zexag(); }
    const Scene &scene() const { return scene_; }
    /// Whether the scene holds more than the model's stacks and planes
    /// (boreholes or a fence; on the GPU, shaders/common/overlays.glsl
    /// draws them where the model is not drawn).
    bool has_overlays() const { return !overlay_items_.empty(); }
    /// Each cell's overlays (row-major, row 0 north): items
    /// [offsets[c], offsets[c + 1]) of overlay_cell_items(), a borehole's
    /// index, or a fence panel's with OVERLAY_PANEL set; empty without
    /// overlays.
    const std::vector<uint32_t> &overlay_cell_offsets() const { return overlay_offsets_; }
    const std::vector<uint32_t> &overlay_cell_items() const { return overlay_items_; }
    static constexpr uint32_t OVERLAY_PANEL = 1u << 31;
    /// Boxes (low, high corners; exaggerated map coordinates) that hold
    /// everything this tracer can hit where it does not draw the model;
    /// empty where it does.
    const std::vector<std::array<glm::dvec3, 2>> &overlay_bounds() const;
    /// Boxes (the same form) that hold each borehole and fence panel,
    /// whether the model is drawn or not: a borehole's up to the highest a
    /// ray can meet in its cells (borehole_top), a panel's the model's
    /// whole height. Found once, with the tracer: every frame asks.
    const std::vector<std::array<glm::dvec3, 2>> &overlay_boxes() const { return overlay_boxes_; }
    /// The empty-space pyramid over what is drawn (no levels when skipping
    /// is off or the model is not drawn).
    const MinMaxPyramid &pyramid() const { return pyramid_; }
    /// The pyramid of the model alone (clip planes applied, no overlays):
    /// pyramid() where no overlay is drawn with the model. The GPU's
    /// model pass skips with it where a pass of their own draws the
    /// boreholes (their cells, full from the bottom, would stop it).
    const MinMaxPyramid &model_pyramid() const
    {
        return model_pyramid_.levels() > 0 ? model_pyramid_ : pyramid_;
    }

private:
    struct Walk;
    struct Entry;
    struct Event;
    /// Where a ray leaves a block of cells it may skip: the parameter and
    /// the cell beyond, entered through `face`.
    struct Jump {
        double t = 0;
        int ix = 0, iy = 0;
        Face face = Face::none;
    };
    /// The stretch [t_near, t_far] of the walk's ray inside the box, on
    /// the kept side of the clip planes and from t_start on, with the
    /// surface `wall` it enters through; false where none is left.
    bool clip_walk(const Walk &walk, double t_start, double &t_near, double &t_far,
                   Entry &wall) const;
    /// The block to leave from cell (ix, iy) at height z_in, into `jump`;
    /// false where even the 2 x 2 block holds material at the ray's height.
    bool leave_block(const Walk &walk, double z_in, double t_far, int ix, int iy,
                     Jump &jump) const;
    void overlay_events(const uint32_t *first, const uint32_t *last, double t_lo,
                        double t_hi, const Walk &walk, std::vector<Event> &events) const;
    bool cross_events(const std::vector<Event> &events, double t_in, double t_out,
                      Entry entry, const std::vector<Interval> *model_stack,
                      Walk &walk) const;
    /// The cell holding local point p (clamped to the grid).
    uint64_t cell_at(glm::dvec3 local) const;
    bool cross_cell(uint64_t cell, double t_in, double t_out, const Entry &entry,
                    Walk &walk) const;
    /// cross_cell's answer from the column's top interval alone (a paged
    /// model's column_tops()), where the ray enters the cell above that
    /// interval's bottom and stays above it or stops in the interval:
    /// then no block is read. Nothing (the hit as it was) where the ray
    /// enters or goes on below.
    std::optional<bool> cross_top_interval(const StackPages &pages, uint64_t cell, double t_in,
                                           double t_out, const Entry &entry, Walk &walk) const;
    bool cross_overlays(uint64_t cell, double t_in, double t_out, const Entry &entry,
                        Walk &walk) const;
    bool cross_borehole(const Borehole &borehole, double t_a, double t_b,
                        const Entry &entry, Walk &walk) const;
    /// Record: Interval or CompactInterval (instantiated for both).
    template <typename Record>
    bool walk_stack(const Record *first, const Record *last, double t_a,
                    double t_b, const Entry &entry, Walk &walk) const;
    bool meet(uint32_t material, double t_enter, double t_exit, const Entry &entry,
              Walk &walk) const;
    void index_overlays();
    void build_pyramid();
    /// overlay_boxes(), found (the pyramid built).
    std::vector<std::array<glm::dvec3, 2>> find_overlay_boxes() const;
    /// The top (exaggerated map z) of the box `lo`-`hi` of borehole `b`:
    /// its log's, its stack's and the model's highest in its cells.
    double borehole_top(const Borehole &b, glm::dvec3 lo, glm::dvec3 hi) const;

    const Model &model_;
    Scene scene_;
    CoordinateFrame frame_;
    std::vector<LocalPlane> planes_;
    /// cells' lists of boreholes (index) and fence panels (index | PANEL)
    std::vector<uint32_t> overlay_offsets_, overlay_items_;
    std::vector<uint32_t> all_overlays_; ///< every overlay, coded the same
    /// local x, y box the rays are clipped to: the grid, or only the cells
    /// with overlays where the model is not drawn
    glm::dvec2 box_low_{0}, box_high_{0};
    MinMaxPyramid pyramid_;
    MinMaxPyramid model_pyramid_; ///< with overlays drawn with the model only
    std::vector<std::array<glm::dvec3, 2>> overlay_boxes_;
};

} // namespace sbrt

#endif
