/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Shading of hits into an image
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "shading/shading.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shading/drape.hpp"
#include "util/error.hpp"
#include "shading/kernel_normals.hpp"
#include "shading/property_paint.hpp"
#include "util/parallel.hpp"

namespace sbrt {

glm::dvec3 Shading::light_from(double azimuth, double elevation)
{
    const double az = azimuth * M_PI / 180, el = elevation * M_PI / 180;
    return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el),
            std::sin(el)};
}

glm::dvec3 Shading::light_of_view(ViewKind kind, double azimuth, double elevation)
{
    if (kind == ViewKind::top)
        return {0, 0, 1};
    return light_from(azimuth, elevation);
}

namespace {

/// lround for 0 <= c <= 255 (half away from zero), without a libm call
/// per channel: c - floor(c) is exact there.
uint8_t round_channel(double c)
{
    if (!(c >= 0))
        return 0; // NaN (lround gave 0 too)
    const double low = std::floor(c);
    return uint8_t(c - low >= 0.5 ? low + 1 : low);
}

/// `surface` (0..255) under the light: ambient plus the diffuse share.
glm::dvec3 lit_surface(const Shading &shading, const glm::dvec3 &surface, double lambert)
{
    return surface * (shading.ambient + (1 - shading.ambient) * lambert);
}

/// A colour (0..255, clamped) as a pixel's bytes.
std::array<uint8_t, 3> rgb_of(const glm::dvec3 &color)
{
    std::array<uint8_t, 3> rgb;
    for (int k = 0; k < 3; ++k)
        rgb[k] = round_channel(std::clamp(color[k], 0.0, 255.0));
    return rgb;
}

} // namespace

/// Most entries of a table of lit face colours (3 bytes each).
constexpr size_t MAX_FACE_TABLE = size_t(1) << 22;

namespace {

/// What a PixelShader of `shading` depends on beyond its model.
std::string pixel_shader_key(const Shading &shading)
{
    std::string key;
    const auto add = [&](const void *p, size_t n) {
        key.append(static_cast<const char *>(p), n);
    };
    const void *pointers[] = {&shading, shading.drape, shading.property, shading.fade};
    add(pointers, sizeof pointers);
    add(&shading.light, sizeof shading.light);
    add(&shading.ambient, sizeof shading.ambient);
    add(shading.background.data(), shading.background.size());
    add(&shading.normals, sizeof shading.normals);
    add(&shading.kernel, sizeof shading.kernel);
    add(&shading.smooth, sizeof shading.smooth);
    // a new paint or fade may take an old one's address
    if (const PropertyPaint *p = shading.property) {
        add(&p->whole().low, sizeof p->whole().low);
        add(&p->whole().count, sizeof p->whole().count);
        for (const glm::dvec3 &c : p->table())
            add(&c, sizeof c);
        add(&p->no_value(), sizeof(glm::dvec3));
    }
    if (const UncertaintyFade *f = shading.fade) {
        const double values[] = {f->low(), f->high(), f->whole().low, double(f->whole().count),
                                 double(f->channel())};
        add(values, sizeof values);
    }
    return key;
}

} // namespace

const PixelShader &KeptPixelShader::of(const Shading &shading)
{
    std::string key = pixel_shader_key(shading);
    if (!shader_ || key != key_) {
        shader_.emplace(model_, shading);
        key_ = std::move(key);
    }
    return *shader_;
}

PixelShader::PixelShader(const Model &model, const Shading &shading)
    : shading_(shading)
{
    base_.reserve(model.materials().size());
    for (size_t m = 0; m < model.materials().size(); ++m) {
        const auto rgb = material_color(model, uint32_t(m));
        base_.emplace_back(rgb[0], rgb[1], rgb[2]);
    }
    if (shading.property && !shading.drape && !shading.fade &&
        !shading.property->table().empty()) {
        // a sum of integers: each value's colour on each face, lit once
        const std::vector<glm::dvec3> entries = shading.property->entry_colors();
        property_face_rgb_.reserve(entries.size() * 6);
        for (const glm::dvec3 &surface : entries)
            for (int face = int(Face::west); face <= int(Face::top); ++face)
                property_face_rgb_.push_back(lit_face(surface, Face(face)));
    }
    const size_t fades = shading.fade ? shading.fade->whole().count + 1 : 0;
    if (shading.fade && !shading.drape && !shading.property && fades > 1 &&
        base_.size() * fades * 6 <= MAX_FACE_TABLE) {
        // few uncertainty values: each class's faded colour on each face
        fade_face_rgb_.reserve(base_.size() * fades * 6);
        for (const glm::dvec3 &base : base_)
            for (const glm::dvec3 &surface : shading.fade->entry_colors(base))
                for (int face = int(Face::west); face <= int(Face::top); ++face)
                    fade_face_rgb_.push_back(lit_face(surface, Face(face)));
    }
    if (shading.drape || shading.property || shading.fade) // colours per hit
        return;
    // (EMPTY's entries are never read: a miss is the background)
    for (const glm::dvec3 &base : base_)
        for (int face = int(Face::west); face <= int(Face::top); ++face)
            cell_face_rgb_.push_back(lit_face(base, Face(face)));
}

std::array<uint8_t, 3> PixelShader::operator()(const Hit &hit) const
{
    if (hit.transmittance == 1 && hit.veil == glm::vec3(0)) {
        // nothing in front: the background, or a cell's face lit as the
        // table has it (with the face's own normal: not a kernel normal)
        if (!hit.is_hit())
            return shading_.background;
        const int face = int(hit.face);
        const bool cell_face = face >= int(Face::west) && face <= int(Face::top) &&
                               hit.normal == glm::vec3(face_normal(hit.face));
        if (cell_face && !cell_face_rgb_.empty())
            return cell_face_rgb_[size_t(hit.material) * 6 + size_t(face - 1)];
        if (cell_face && !fade_face_rgb_.empty()) {
            const size_t fades = shading_.fade->whole().count + 1;
            double v;
            const int64_t k = shading_.fade->value(hit, v) ? shading_.fade->whole().index(v)
                                                           : int64_t(fades - 1);
            if (k >= 0)
                return fade_face_rgb_[(size_t(hit.material) * fades + size_t(k)) * 6 +
                                      size_t(face - 1)];
        }
        if (cell_face && !property_face_rgb_.empty()) {
            double v;
            const int64_t k = shading_.property->value(hit, v)
                                  ? shading_.property->whole().index(v)
                                  : int64_t(shading_.property->table().size());
            if (k >= 0)
                return property_face_rgb_[size_t(k) * 6 + size_t(face - 1)];
        }
    }
    return lit(hit);
}

std::array<uint8_t, 3> PixelShader::lit_face(const glm::dvec3 &surface, Face face) const
{
    // lit() with nothing in front (veil 0, transmittance 1): the same sums
    const glm::dvec3 normal(glm::vec3(face_normal(face)));
    return rgb_of(lit_surface(shading_, surface, std::max(0.0, glm::dot(shading_.light, normal))));
}

std::array<uint8_t, 3> PixelShader::lit(const Hit &hit) const
{
    const Shading &shading = shading_;
    glm::dvec3 color(shading.background[0], shading.background[1],
                     shading.background[2]);
    if (hit.is_hit()) {
        glm::dvec3 surface =
            shading.property ? shading.property->color(hit) : base_[hit.material];
        if (shading.drape)
            surface = shading.drape->color(hit, surface);
        if (shading.fade)
            surface = shading.fade->apply(hit, surface);
        // a cut (section, plane, fence curtain) shows its classes as the
        // legend does, whatever the light: a section seen head-on is not
        // in shadow
        const double lambert =
            hit.face == Face::plane || hit.face == Face::fence
                ? 1.0
                : std::max(0.0, glm::dot(shading.light, glm::dvec3(hit.normal)));
        color = lit_surface(shading, surface, lambert);
    }
    return rgb_of(255.0 * glm::dvec3(hit.veil) + double(hit.transmittance) * color);
}

void shade_into_band(const Tracer &tracer, const PixelShader &shader, const Camera &camera,
                     const Hit &hit, int row, int col, Band &band)
{
    const Model &model = tracer.model();
    const int r = row - band.first_row;
    const auto rgb = shader(hit);
    std::copy(rgb.begin(), rgb.end(), band.rgb.row(r) + size_t(col) * 3);
    if (!band.material.empty())
        band.material.row(r)[col] = hit.is_hit() ? model.materials()[hit.material].id : NULL_CLASS;
    if (!band.elevation.empty())
        band.elevation.row(r)[col] = hit.is_hit() ? hit.point.z : NAN;
    if (!band.value.empty()) {
        double v = NAN;
        if (!shader.property() || !shader.property()->value(hit, v))
            v = NAN;
        band.value.row(r)[col] = v;
    }
    if (!band.depth.empty())
        band.depth.row(r)[col] = hit.is_hit()
                                     ? glm::length(hit.point - tracer.frame().map_from_exaggerated(
                                                                   camera.ray(row, col).origin))
                                     : NAN;
}

Image shade(const Tracer &tracer, const Camera &camera, HitImage hits,
            const Shading &shading, unsigned threads)
{
    const Model &model = tracer.model();
    Image image;
    image.rows = camera.rows();
    image.cols = camera.cols();
    const size_t pixels = size_t(image.rows) * image.cols;
    SBRT_CHECK_EQ(hits.size(), pixels, "shade");
    if (shading.normals == Normals::kernel) {
        apply_kernel_normals(tracer, camera, shading.kernel, hits, threads);
        if (shading.smooth > 0)
            smooth_normals(camera, shading.smooth, hits, threads);
    }
    image.rgb.assign(pixels * 3, 0);
    image.material.assign(pixels, NULL_CLASS);
    image.elevation.assign(pixels, NAN);
    image.depth.assign(pixels, NAN);
    image.value.assign(shading.property ? pixels : 0, NAN);
    const PixelShader shade_pixel(model, shading);
    for_each_row(image.rows, threads, [&](int row) {
        for (int col = 0; col < image.cols; ++col) {
            const size_t i = size_t(row) * image.cols + col;
            const Hit &hit = hits[i];
            if (hit.is_hit()) {
                image.material[i] = model.materials()[hit.material].id;
                image.elevation[i] = hit.point.z;
                image.depth[i] = glm::length(
                    hit.point - tracer.frame().map_from_exaggerated(camera.ray(row, col).origin));
                double v;
                if (shading.property && shading.property->value(hit, v))
                    image.value[i] = v;
            }
            const auto rgb = shade_pixel(hit);
            std::copy(rgb.begin(), rgb.end(), image.rgb.begin() + i * 3);
        }
    });
    return image;
}

} // namespace sbrt
