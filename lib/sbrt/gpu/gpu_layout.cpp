/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   GPU view block and hit records
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu/gpu_layout.hpp"

#include <algorithm>
#include <cstring>

#include <glm/geometric.hpp>

#include "shading/drape.hpp"
#include "shading/kernel_normals.hpp"
#include "util/error.hpp"

namespace sbrt {

namespace {

void put(float out[4], glm::dvec3 v)
{
    for (int i = 0; i < 3; ++i)
        out[i] = float(v[i]);
    out[3] = 0;
}

/// The rays of `camera` in the tracer's local frame: through origin + x
/// spread_u + y spread_v along forward + x du + y dv for x, y in
/// normalised device coordinates (du = dv = 0 for parallel rays), from t
/// = -s (the eye). They are re-based on the plane through the model's
/// centre across the view: a camera far away keeps its precision (float
/// directions and distances would lose the model).
struct LocalRays {
    glm::dvec3 origin{0.0}, forward{0.0}, du{0.0}, dv{0.0}, spread_u{0.0}, spread_v{0.0};
    double s = 0;
};

LocalRays local_rays(const Tracer &tracer, const Camera &camera)
{
    glm::dvec3 map_origin, map_forward, map_du, map_dv;
    camera.linear_rays(map_origin, map_forward, map_du, map_dv);
    const glm::dvec3 eye = tracer.frame().local_from_exaggerated(map_origin);
    LocalRays rays;
    rays.forward = tracer.frame().local_direction_from_exaggerated(map_forward);
    const glm::dvec3 du = tracer.frame().local_direction_from_exaggerated(map_du);
    const glm::dvec3 dv = tracer.frame().local_direction_from_exaggerated(map_dv);
    const glm::dvec3 centre = tracer.frame().local_from_exaggerated(tracer.frame().centre());
    rays.s = std::max(0.0, glm::dot(centre - eye, rays.forward) /
                               glm::dot(rays.forward, rays.forward));
    rays.origin = eye + rays.s * rays.forward;
    if (camera.parallel()) {
        rays.spread_u = du;
        rays.spread_v = dv;
    }
    else {
        rays.du = du;
        rays.dv = dv;
        rays.spread_u = rays.s * du;
        rays.spread_v = rays.s * dv;
    }
    return rays;
}

void put(double out[4], glm::dvec3 v)
{
    for (int i = 0; i < 3; ++i)
        out[i] = v[i];
    out[3] = 0;
}

} // namespace

GpuView make_gpu_view(const Tracer &tracer, const Camera &camera,
                      uint32_t loop_budget)
{
    const Frame &f = tracer.model().frame();
    GpuView view{};
    const LocalRays rays = local_rays(tracer, camera);
    const glm::dvec3 origin = rays.origin, hi = glm::dvec3(glm::vec3(origin));
    const double s = rays.s;
    put(view.origin_hi, hi);
    put(view.origin_lo, origin - hi);
    put(view.forward, rays.forward);
    put(view.du, rays.du);
    put(view.dv, rays.dv);
    put(view.spread_u, rays.spread_u);
    put(view.spread_v, rays.spread_v);
    view.spread_u[3] = float(-s);
    view.grid[0] = uint32_t(f.cols);
    view.grid[1] = uint32_t(f.rows);
    view.grid[2] = uint32_t(camera.cols());
    view.grid[3] = uint32_t(camera.rows());
    view.box[0] = float(tracer.frame().top_local());
    for (int a = 0; a < 3; ++a)
        view.box[1 + a] = float(tracer.frame().voxel_size()[a]);
    view.options[0] = camera.parallel() ? 1 : 0;
    view.options[1] = loop_budget;
    // each plane's value at the base, in double: the shader adds only what
    // varies per ray
    const std::vector<Tracer::LocalPlane> &planes = tracer.planes();
    for (size_t k = 0; k < planes.size(); ++k) {
        put(view.planes[k], planes[k].n);
        view.planes[k][3] = float(glm::dot(planes[k].n, origin) + planes[k].c);
    }
    view.counts[0] = uint32_t(planes.size());
    view.counts[1] = uint32_t(tracer.pyramid().levels());
    return view;
}

GpuViewDouble make_gpu_view_double(const Tracer &tracer, const Camera &camera)
{
    const LocalRays rays = local_rays(tracer, camera);
    GpuViewDouble view{};
    put(view.origin, rays.origin);
    put(view.forward, rays.forward);
    put(view.du, rays.du);
    put(view.dv, rays.dv);
    put(view.spread_u, rays.spread_u);
    put(view.spread_v, rays.spread_v);
    return view;
}

glm::dvec4 ray_t_form(const Tracer &tracer, const Camera &camera, glm::dvec3 from)
{
    // a ray: origin + s (x du + y dv) + t (forward + x du + y dv) for a
    // pinhole, origin + x spread_u + y spread_v + t forward for a parallel
    // camera; a form across the image plane's two axes, 1 along forward,
    // gives t
    const LocalRays rays = local_rays(tracer, camera);
    const glm::dvec3 n = camera.parallel() ? glm::cross(rays.spread_u, rays.spread_v)
                                           : glm::cross(rays.du, rays.dv);
    const glm::dvec3 a = n / glm::dot(n, rays.forward);
    return {a, glm::dot(a, from - rays.origin)};
}

std::vector<uint32_t> make_gpu_pyramid(const MinMaxPyramid &pyramid, int first_level)
{
    if (pyramid.levels() > GPU_MAX_PYRAMID_LEVELS)
        fail("a pyramid of ", pyramid.levels(), " levels, the GPU holds ",
             GPU_MAX_PYRAMID_LEVELS);
    std::vector<uint32_t> words(size_t(gpu_pyramid_bytes(pyramid, first_level) / 4), 0);
    words[3] = uint32_t(first_level);
    static_assert(sizeof(ZRange) == 2 * sizeof(uint32_t), "two floats");
    ZRange *nodes = reinterpret_cast<ZRange *>(&words[4 * GPU_MAX_PYRAMID_LEVELS]);
    uint32_t offset = 0;
    for (int level = first_level; level < pyramid.levels(); ++level) {
        words[4 * level] = offset;
        words[4 * level + 1] = uint32_t(pyramid.cols(level));
        words[4 * level + 2] = uint32_t(pyramid.rows(level));
        for (int y = 0; y < pyramid.rows(level); ++y)
            for (int x = 0; x < pyramid.cols(level); ++x)
                nodes[offset++] = pyramid.node(level, x, y);
    }
    return words;
}

uint64_t gpu_pyramid_bytes(const MinMaxPyramid &pyramid, int first_level)
{
    uint64_t nodes = 0;
    for (int level = first_level; level < pyramid.levels(); ++level)
        nodes += uint64_t(pyramid.cols(level)) * uint64_t(pyramid.rows(level));
    return (4 * uint64_t(GPU_MAX_PYRAMID_LEVELS) + 2 * nodes) * 4;
}

GpuShade make_gpu_shade(const Tracer &tracer, const Shading &shading,
                        const Outputs &outputs)
{
    GpuShade shade{};
    put(shade.light, shading.light);
    shade.light[3] = float(shading.ambient);
    for (int k = 0; k < 3; ++k)
        shade.background[k] = float(shading.background[size_t(k)]);
    const glm::dvec3 zero = tracer.frame().map_from_local(glm::dvec3(0));
    put(shade.real_unit, tracer.frame().map_from_local(glm::dvec3(1)) - zero);
    shade.real_unit[3] = float(zero.z);
    shade.elevation_step[0] = float(tracer.frame().map_from_local(glm::dvec3(0, 0, 1)).z - zero.z);
    const std::vector<Tracer::LocalPlane> &planes = tracer.planes();
    for (size_t k = 0; k < planes.size(); ++k)
        put(shade.plane_normals[k], planes[k].shading_normal);
    shade.outputs[1] = (outputs.material ? GPU_OUT_CLASS : 0) |
                       (outputs.elevation ? GPU_OUT_ELEVATION : 0) |
                       (outputs.depth ? GPU_OUT_DEPTH : 0);
    if (const Drape *drape = shading.drape) {
        // the texture's pixel centres (Texture::sample) from local x, y
        const Texture &t = drape->texture();
        const Frame &f = tracer.model().frame();
        const double per_x = t.cols / (t.east - t.west), per_y = t.rows / (t.north - t.south);
        shade.drape[0] = float(drape->blend());
        shade.drape[1] = float(t.cols);
        shade.drape[2] = float(t.rows);
        shade.drape_map[0] = float(f.ew_res() * per_x);
        shade.drape_map[1] = float((f.west - t.west) * per_x - 0.5);
        shade.drape_map[2] = float(-f.ns_res() * per_y);
        shade.drape_map[3] = float((t.north - f.south) * per_y - 0.5);
    }
    return shade;
}

GpuBandLayout gpu_band_layout(int rows, int cols, const Outputs &outputs)
{
    GpuBandLayout l;
    l.rows = rows;
    l.cols = cols;
    const size_t pixels = size_t(rows) * size_t(cols);
    l.rgb_stride_words = (size_t(cols) * 3 + 3) / 4;
    size_t at = l.rgb_stride_words * size_t(rows);
    at += at & 1; // doubles on 8 bytes
    if (outputs.material) {
        l.material_at = at;
        at += pixels + (pixels & 1);
    }
    if (outputs.elevation) {
        l.elevation_at = at;
        at += 2 * pixels;
    }
    if (outputs.depth) {
        l.depth_at = at;
        at += 2 * pixels;
    }
    l.over_budget_at = at;
    l.words = at + 1 + pixels;
    return l;
}

void set_band_planes(GpuShade &shade, const GpuBandLayout &layout)
{
    const auto word = [](size_t w) {
        if (w > UINT32_MAX)
            fail("a band of ", w, " words is beyond the GPU's 32-bit indices");
        return uint32_t(w);
    };
    shade.outputs[0] = word(layout.rgb_stride_words);
    shade.planes[0] = word(layout.material_at);
    shade.planes[1] = word(layout.elevation_at);
    shade.planes[2] = word(layout.depth_at);
    shade.planes[3] = word(layout.over_budget_at);
    word(layout.words);
}

GpuKernel make_gpu_kernel(const Tracer &tracer, const Camera &camera,
                          const KernelNormals &kernel, const std::vector<double> &weights)
{
    GpuKernel k{};
    put(k.eye, camera.origin() - tracer.frame().corner(0));
    k.eye[3] = camera.parallel() ? 1 : 0;
    put(k.forward, camera.forward());
    k.forward[3] = float(kernel.tolerance_voxel());
    put(k.du, camera.du());
    k.du[3] = float(glm::dot(camera.du(), camera.du()));
    put(k.dv, camera.dv());
    k.dv[3] = float(glm::dot(camera.dv(), camera.dv()));
    put(k.voxel, tracer.frame().voxel_size());
    k.counts[0] = uint32_t(kernel.cells().size());
    k.counts[3] = uint32_t(weights.size() / 2);
    return k;
}

std::vector<float> make_gpu_kernel_cells(const KernelNormals &kernel,
                                         const std::vector<double> &weights)
{
    std::vector<float> words;
    words.reserve(kernel.cells().size() * 8 + weights.size() * 4);
    for (const KernelNormals::Cell &cell : kernel.cells())
        words.insert(words.end(), {float(cell.unit.x), float(cell.unit.y), float(cell.unit.z),
                                   float(cell.along_forward), float(cell.along_du),
                                   float(cell.along_dv), 0.0f, 0.0f});
    for (double weight : weights)
        words.insert(words.end(), {float(weight), 0.0f, 0.0f, 0.0f});
    return words;
}

std::vector<uint32_t> make_gpu_drape(const Tracer &tracer, const Drape &drape)
{
    const Frame &f = tracer.model().frame(), &d = drape.frame();
    if (f.rows != d.rows || f.cols != d.cols)
        fail("drape: made for a grid of ", d.rows, " x ", d.cols, " cells, the model has ",
             f.rows, " x ", f.cols);
    const std::vector<float> &tops = drape.surface_tops();
    const Texture &t = drape.texture();
    std::vector<uint32_t> words(tops.size() + t.rgb.size());
    std::memcpy(words.data(), tops.data(), tops.size() * sizeof(float));
    for (size_t i = 0; i < t.rgb.size(); ++i)
        words[tops.size() + i] = uint32_t(t.rgb[i][0]) | uint32_t(t.rgb[i][1]) << 8 |
                                 uint32_t(t.rgb[i][2]) << 16 |
                                 (t.valid[i] ? 255u << 24 : 0u);
    return words;
}

std::vector<GpuLook> make_gpu_looks(const Tracer &tracer)
{
    const Model &model = tracer.model();
    std::vector<GpuLook> looks(model.materials().size(), GpuLook{0, NULL_CLASS, {0, 0}});
    for (size_t m = 1; m < looks.size(); ++m) {
        const auto rgb = material_color(model, uint32_t(m));
        looks[m].rgb = uint32_t(rgb[0]) | uint32_t(rgb[1]) << 8 | uint32_t(rgb[2]) << 16;
        looks[m].id = model.materials()[m].id;
    }
    return looks;
}

std::vector<GpuMaterial> make_gpu_materials(const Tracer &tracer)
{
    const Translucency &tr = tracer.scene().translucency;
    std::vector<GpuMaterial> table(tracer.model().materials().size(),
                                   GpuMaterial{{0, 0, 0}, -1});
    const std::vector<uint8_t> &hidden = tracer.scene().hidden;
    for (size_t m = 0; m < table.size(); ++m)
        if (!hidden.empty() && hidden[m])
            table[m] = {{0, 0, 0}, 0}; // crossed as air: absorbs nothing, adds nothing
        else if (!tr.opaque(uint32_t(m)))
            table[m] = {{float(tr.color[m].r), float(tr.color[m].g),
                         float(tr.color[m].b)},
                        float(tr.extinction[m])};
    return table;
}

Hit decode_gpu_hit(const Tracer &tracer, const Ray &ray,
                   const GpuPixelHit &record, bool &over_budget)
{
    over_budget = (record.code & GPU_CODE_OVER_BUDGET) != 0;
    Hit hit;
    const uint32_t material = record.code & 0xffffu;
    const uint32_t face = (record.code >> 16) & 0xfu;
    const uint32_t plane = (record.code >> 20) & 0xfu;
    hit.veil = glm::vec3(record.veil[0], record.veil[1], record.veil[2]);
    hit.transmittance = record.veil[3];
    if (over_budget || material == EMPTY)
        return hit;
    if (material >= tracer.model().materials().size() || face > 7 ||
        (face == uint32_t(Face::plane) && plane >= tracer.planes().size()))
        fail("GPU hit record with material ", material, ", face ", face,
             " and plane ", plane, " is out of range");
    hit.material = material;
    hit.face = Face(face);
    const glm::dvec3 local(record.point[0], record.point[1], record.point[2]);
    hit.point = tracer.frame().map_from_local(local);
    hit.t = glm::length(tracer.frame().exaggerated_from_map(hit.point) - ray.origin);
    if (hit.face == Face::plane) {
        hit.plane = int8_t(plane);
        hit.normal = tracer.planes()[plane].shading_normal;
    }
    else
        hit.normal = hit.face == Face::none ? -ray.direction : face_normal(hit.face);
    return hit;
}

} // namespace sbrt
