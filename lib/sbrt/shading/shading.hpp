/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Turns the first hits of an image into its outputs: colour
 *            with Lambert lighting, material, elevation and depth
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_SHADING_HPP
#define SBRT_SHADING_HPP

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "model/material_table.hpp"
#include "output/band.hpp"
#include "scene/view.hpp"
#include "tracing/hit_image.hpp"

namespace sbrt {

/// How the normal at a hit is found: the exact normal of the face that was
/// hit, or the hybrid image-space kernel (see kernel_normals.hpp).
enum class Normals { face, kernel };

/// \brief Lighting I = ia + kd (L.N) id with kd id = 1 - ambient.
struct Shading {
    glm::dvec3 light{0, 0, 1}; ///< towards the light, unit length
    double ambient = 0.35;
    std::array<uint8_t, 3> background{255, 255, 255};
    Normals normals = Normals::face;
    int kernel = 5;      ///< kernel size k (odd, 3..11) of Normals::kernel
    double smooth = 0;   ///< Gaussian sigma of the normals, pixels (0: off)
    const class Drape *drape = nullptr; ///< an image on the terrain, or none
    /// a property colouring the hits instead of their class, or none
    const class PropertyPaint *property = nullptr;
    /// an uncertainty greying the colours, or none
    const class UncertaintyFade *fade = nullptr;

    /// Direction from azimuth (degrees clockwise from north) and elevation.
    static glm::dvec3 light_from(double azimuth, double elevation);
    /// The light of a view of `kind`: a top view (a map) is lit from
    /// straight above, so that L.N = 1 on an upward face and a flat top
    /// shows its legend colour exactly (whatever the ambient share), as
    /// a map's legend promises; the other views from azimuth, elevation.
    static glm::dvec3 light_of_view(ViewKind kind, double azimuth, double elevation);
};

/// \brief Per-pixel outputs, row-major, row 0 at the top of the image.
struct Image {
    int rows = 0, cols = 0;
    std::vector<uint8_t> rgb;       ///< 3 per pixel
    std::vector<int32_t> material;  ///< class id, NULL_CLASS where missed
    std::vector<double> elevation;  ///< z of the hit, NaN where missed
    std::vector<double> depth;      ///< distance from the ray origin, NaN
    std::vector<double> value;      ///< the shown property, NaN (property only)
};


/// \brief A Shading made ready for one model's pixels: each material's
/// colour is looked up once, not per pixel. Holds a reference to `shading`.
class PixelShader {
public:
    PixelShader(const Model &model, const Shading &shading);

    /// A pixel's colour: the veil of the translucent strata plus, through
    /// them, the lit colour of the hit (or the background).
    std::array<uint8_t, 3> operator()(const Hit &hit) const;
    /// The property the shading shows, or null.
    const class PropertyPaint *property() const { return shading_.property; }

private:
    std::array<uint8_t, 3> lit(const Hit &hit) const;

    const Shading &shading_;
    std::vector<glm::dvec3> base_; ///< per material, 0..255
    /// Without a drape, the colours lit() gives a hit on each of a cell's
    /// six faces with its face normal, nothing in front: per material,
    /// faces west..top (Face values 1..6).
    std::vector<std::array<uint8_t, 3>> cell_face_rgb_;
    /// The same for a property with a colour table (PropertyPaint::table)
    /// and no drape or fade: per table entry, then for hits without a
    /// value (the last six), faces west..top.
    std::vector<std::array<uint8_t, 3>> property_face_rgb_;
    /// The same for a fade whose channel holds few whole numbers, with
    /// neither drape nor property: per material, per fade entry and then
    /// for hits without a value, faces west..top.
    std::vector<std::array<uint8_t, 3>> fade_face_rgb_;
    /// lit()'s colour of `surface` on a cell face with its face normal.
    std::array<uint8_t, 3> lit_face(const glm::dvec3 &surface, Face face) const;
};

/// \brief One model's PixelShader, kept from frame to frame while what it
/// depends on stays: the address of the shading (the shader holds a
/// reference), its settings and what its property or fade colours are
/// made of (a fade's face tables, classes x values x faces, cost more than
/// a frame of a GPU).
class KeptPixelShader {
public:
    explicit KeptPixelShader(const Model &model) : model_(model) {}
    /// The shader of `shading`, made again only where it changed.
    const PixelShader &of(const Shading &shading);

private:
    const Model &model_;
    std::optional<PixelShader> shader_;
    std::string key_;
};

/// Pixel (row, col) of `band` (a band of camera's image): the colour of
/// `hit` and the outputs the band holds (class id, elevation, depth from
/// the ray's origin; NULL_CLASS and NaN where the ray met nothing).
void shade_into_band(const Tracer &tracer, const PixelShader &shader, const Camera &camera,
                     const Hit &hit, int row, int col, Band &band);

/// The whole-image reference of the pipeline (tests and benchmarks; the
/// module streams through Renderer): outputs of the hits of camera's rays
/// (row-major, as trace_image gives). Material, elevation and depth are
/// those of the first opaque hit.
Image shade(const Tracer &tracer, const Camera &camera, HitImage hits,
            const Shading &shading, unsigned threads = 0);

} // namespace sbrt

#endif
