/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Scene pruning before upload: the stacks no ray of a camera can
 *            reach (outside the view, or wholly cut away by the clip
 *            planes) are left out of the model that is traced
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_SCENE_PRUNING_HPP
#define SBRT_SCENE_PRUNING_HPP

#include <cstdint>

#include "scene/camera.hpp"
#include "tracing/tracer.hpp"

namespace sbrt {

/// What pruning left out: non-empty stacks, their intervals and bytes.
struct Pruned {
    uint64_t cells = 0, intervals = 0, bytes = 0;
};

/// \brief The tracer's model less the stacks out of the camera's view and
/// those its pyramid holds as cut away by the planes (the same image).
struct Pruning {
    Model model;
    Pruned outside_view, cut_away;
    bool removed_any() const { return outside_view.cells || cut_away.cells; }
};

/// Whether no ray of `camera` can enter the box [low, high] (exaggerated
/// map coordinates): all its corners lie beyond one edge of the image or
/// behind a perspective camera.
bool outside_view(const Camera &camera, glm::dvec3 low, glm::dvec3 high);

/// Linear in the cells and intervals; the tracer must draw the model.
Pruning prune_for_view(const Tracer &tracer, const Camera &camera);
/// The same for `scene` drawn with `zexag`, without a tracer: the columns
/// its pyramid would hold as empty are found from the stacks, the planes
/// and the overlays (the renderer then builds the one tracer, of the
/// pruned model).
Pruning prune_for_view(const Model &model, double zexag, const Scene &scene,
                       const Camera &camera);

} // namespace sbrt

#endif
