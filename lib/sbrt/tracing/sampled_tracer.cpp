/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Fixed-step and adaptive ray marching over an SBRT
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "tracing/sampled_tracer.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

/// Where a sample lies: its cell and the index of its interval there.
struct Sample {
    int x = -1, y = -1;
    long interval = -1;
    uint32_t material = EMPTY;
};

Sample sample_at(const Model &model, glm::dvec3 p)
{
    const Frame &f = model.frame();
    Sample s;
    s.x = std::clamp(int(std::floor(p.x)), 0, f.cols - 1);
    s.y = std::clamp(int(std::floor(p.y)), 0, f.rows - 1);
    const uint64_t cell = model.cell_index(f.rows - 1 - s.y, s.x);
    const StackRange stack = model.stack(cell);
    model.intervals().visit([&](const auto *records) {
        using Record = RecordOf<decltype(records)>;
        const Record *first = records + stack.begin, *last = records + stack.end;
        const Record *k = std::upper_bound(
            first, last, p.z, [](double z, const Record &iv) { return z < double(iv.top); });
        s.interval = long(k - first);
        s.material = k != last ? k->material : EMPTY;
    });
    return s;
}

/// The face the step from `before` to `at` crossed, seen from the ray.
Face crossed(const Sample &before, const Sample &at, glm::dvec3 d)
{
    if (at.x != before.x)
        return d.x > 0 ? Face::west : Face::east;
    if (at.y != before.y)
        return d.y > 0 ? Face::south : Face::north;
    return d.z > 0 ? Face::bottom : Face::top;
}

} // namespace

Hit sample_ray(const Tracer &tracer, const Ray &ray, const Sampling &sampling)
{
    if (!(sampling.step > 0) || sampling.fine_step < 0)
        fail("sampling: the step must be positive");
    const Model &model = tracer.model();
    const Frame &f = model.frame();
    const glm::dvec3 o = tracer.frame().local_from_exaggerated(ray.origin);
    const glm::dvec3 d = tracer.frame().local_direction_from_exaggerated(ray.direction);
    // from the camera (t = 0) on, inside the model's box
    double t_near = 0, t_far = INFINITY;
    int near_axis = -1;
    if (!clip_to_box(o, d, 1.0 / d, glm::dvec3(0),
                     glm::dvec3(f.cols, f.rows, tracer.frame().top_local()),
                     t_near, t_far, near_axis) ||
        !(t_near < t_far))
        return {};
    const double per_cell = 1 / glm::length(d); // t per local unit
    double dt = sampling.step * per_cell;
    bool refining = false;
    Sample before;
    for (double t = t_near + dt / 2; t < t_far;) {
        const Sample s = sample_at(model, o + t * d);
        if (s.material == EMPTY) {
            before = s;
            t += dt;
            continue;
        }
        if (sampling.fine_step > 0 && !refining) {
            // adaptive: back one coarse step, on with fine ones
            refining = true;
            const double back = t - dt;
            dt = sampling.fine_step * per_cell;
            t = std::max(t_near + dt / 2, back + dt);
            continue;
        }
        Hit hit;
        hit.t = t;
        hit.material = s.material;
        hit.face = before.x < 0 ? Face::none : crossed(before, s, d);
        hit.normal = hit.face == Face::none ? -ray.direction : face_normal(hit.face);
        hit.point = tracer.frame().map_from_local(o + t * d);
        return hit;
    }
    return {};
}

HitImage sample_image(const Tracer &tracer, const Camera &camera,
                      const Sampling &sampling, unsigned threads)
{
    HitImage hits(size_t(camera.rows()) * camera.cols());
    for_each_row(camera.rows(), threads, [&](int row) {
        for (int col = 0; col < camera.cols(); ++col)
            hits[size_t(row) * camera.cols() + col] =
                sample_ray(tracer, camera.ray(row, col), sampling);
    });
    return hits;
}

} // namespace sbrt
