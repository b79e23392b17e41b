/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   C++ mirror of the GPU blocks of shaders/common/layout.glsl:
 *            the view uniform block (std140) and the per-pixel hit record
 *            (std430); the intervals and offsets go up as the model holds
 *            them. Conversions between the camera, the hits and the
 *            tracer's local frame.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GPU_LAYOUT_HPP
#define SBRT_GPU_LAYOUT_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "output/band.hpp"
#include "shading/shading.hpp"
#include "tracing/tracer.hpp"

namespace sbrt {

class Drape;
class KernelNormals;

/// `uniform View` (std140): every member a 16-byte vec4/uvec4.
struct GpuView {
    float origin_hi[4];
    float origin_lo[4];
    float forward[4];
    float du[4];
    float dv[4];
    float spread_u[4];   ///< w: t where the rays start
    float spread_v[4];
    uint32_t grid[4];    ///< model cols, rows; image cols, rows
    float box[4];        ///< x: highest interval top, local z; yzw: voxel size
    uint32_t options[4]; ///< parallel rays, loop budget, first row, rows
    float planes[MAX_CLIP_PLANES][4]; ///< local n, value at the origin
    uint32_t counts[4];  ///< x: clip planes
};
static_assert(sizeof(GpuView) == 304, "std140 View block");
static_assert(offsetof(GpuView, planes) == 160, "std140 View block");
static_assert(offsetof(GpuView, counts) == 288, "std140 View block");
static_assert(offsetof(GpuView, grid) == 112, "std140 View block");
static_assert(offsetof(GpuView, options) == 144, "std140 View block");

/// `uniform ViewDouble` (std140, binding 3; the shading pass of colours by
/// voxel): the rays of GpuView in double (base = origin, rays start where
/// GpuView says), so that a hit within float's reach of a voxel's edge is
/// placed on its face as the CPU's double tracer places it.
struct GpuViewDouble {
    double origin[4]; ///< xyz: base (origin_hi + origin_lo, unrounded)
    double forward[4];
    double du[4];
    double dv[4];
    double spread_u[4];
    double spread_v[4];
};
static_assert(sizeof(GpuViewDouble) == 192, "std140 ViewDouble block");

/// `struct Interval` (std430) is the model's own Interval.
static_assert(sizeof(Interval) == 8 && offsetof(Interval, material) == 0 &&
                  offsetof(Interval, top) == 4,
              "std430 Interval");

/// `struct PixelHit` (std430): vec3, uint, vec4; 32 bytes.
struct GpuPixelHit {
    float point[3]; ///< local coordinates of the hit
    uint32_t code;  ///< material | face << 16 | plane << 20 | over budget << 24
    float veil[4];  ///< translucent strata's colour (premultiplied), transmittance
};
static_assert(sizeof(GpuPixelHit) == 32 && offsetof(GpuPixelHit, veil) == 16,
              "std430 PixelHit");

/// An entry of `buffer Materials` (std430 vec4): colour and extinction
/// per exaggerated map unit, negative for an opaque material.
struct GpuMaterial {
    float color[3];
    float extinction;
};
static_assert(sizeof(GpuMaterial) == 16, "std430 vec4");

/// `uniform Shade` (std140): what shading on the GPU needs besides the view.
struct GpuShade {
    float light[4];          ///< towards the light, unit; w: ambient share
    float background[4];     ///< rgb 0..255
    float real_unit[4];      ///< real map length per local unit; w: elevation at z 0
    float elevation_step[4]; ///< x: elevation per local z unit
    float plane_normals[MAX_CLIP_PLANES][4];
    /// words from an RGB row to the next; 1 class, 2 elevation, 4 depth
    uint32_t outputs[4];
    /// where the band's planes start in its buffer, in words
    /// (GpuBandLayout): class ids, elevations, depths, rays over the budget
    uint32_t planes[4];
    /// The drape (SBRT_DRAPE): x: blend; y, z: the texture's cols and rows
    float drape[4];
    /// The texture's column and row (pixel centres at whole numbers) of a
    /// local point: u = x * lx + y, v = z * ly + w
    float drape_map[4];
};
static_assert(sizeof(GpuShade) == 256 && offsetof(GpuShade, plane_normals) == 64 &&
                  offsetof(GpuShade, outputs) == 192 && offsetof(GpuShade, planes) == 208 &&
                  offsetof(GpuShade, drape) == 224 && offsetof(GpuShade, drape_map) == 240,
              "std140 Shade block");

/// \brief Where the shading pass writes a band of `rows` x `cols` pixels
/// in its buffer (`buffer Pixels`, 32-bit words), the bytes the caller
/// asked for and no others: RGB8 rows, each starting on a whole word (a
/// work group packs its pixels' bytes into words); then, where asked
/// for, the class ids (int32), the elevations and the depths (double,
/// NaN where missed: the sinks' own type); then the rays over the loop
/// budget (a count, then their pixels' indices), which the host traces.
struct GpuBandLayout {
    int rows = 0, cols = 0;
    size_t rgb_stride_words = 0; ///< words from an RGB row to the next
    /// word offsets of the planes; 0 where not asked for
    size_t material_at = 0, elevation_at = 0, depth_at = 0;
    size_t over_budget_at = 0; ///< the count, then up to rows x cols indices
    size_t words = 0;          ///< the whole buffer
    size_t bytes() const { return words * 4; }
};
GpuBandLayout gpu_band_layout(int rows, int cols, const Outputs &outputs);

/// The Shade block's outputs and planes for a band laid out as `layout`.
void set_band_planes(GpuShade &shade, const GpuBandLayout &layout);

/// `uniform Kernel` (std140): the camera in the terms of the kernel
/// normals' passes (shaders/common/kernel.glsl).
struct GpuKernel {
    float eye[4];     ///< camera origin from the model's corner; w: 1 parallel
    float forward[4]; ///< w: KernelNormals::tolerance_voxel
    float du[4];      ///< w: du . du
    float dv[4];      ///< w: dv . dv
    float voxel[4];   ///< exaggerated map units per local unit
    uint32_t counts[4]; ///< cells; first image row and rows of a dispatch;
                        ///< the smoothing's radius (0: none)
};
static_assert(sizeof(GpuKernel) == 96 && offsetof(GpuKernel, counts) == 80,
              "std140 Kernel block");

/// An entry of `buffer Looks` (std430 uvec4): colour r | g << 8 | b << 16
/// and class id of a material.
struct GpuLook {
    uint32_t rgb;
    int32_t id;
    uint32_t unused[2];
};
static_assert(sizeof(GpuLook) == 16, "std430 uvec4");

/// Bits of GpuShade::outputs[1].
constexpr uint32_t GPU_OUT_CLASS = 1, GPU_OUT_ELEVATION = 2, GPU_OUT_DEPTH = 4;

constexpr uint32_t GPU_CODE_OVER_BUDGET = 1u << 24;
/// Default loop budget per pixel: below llvmpipe's 65,535 iterations with
/// room for the loops the budget does not count.
constexpr uint32_t GPU_LOOP_BUDGET = 60000;

/// Levels the `Pyramid` buffer has room for (MAX_PYRAMID_LEVELS).
constexpr int GPU_MAX_PYRAMID_LEVELS = 32;

/// `buffer Pyramid` (std430): per level (offset, cols, rows, 0) for
/// GPU_MAX_PYRAMID_LEVELS levels, then every node's (low, high) as floats,
/// level 0 first; all as 32-bit words. From `first_level` on only, where
/// given (a paged model's columns' pages hold level 0, and the levels
/// below the first are too large for the GPU's budget): the levels below
/// it are (0, 0, 0, 0), and level 0's fourth word is `first_level`.
std::vector<uint32_t> make_gpu_pyramid(const MinMaxPyramid &pyramid, int first_level = 0);
/// The bytes of make_gpu_pyramid's words, without making them.
uint64_t gpu_pyramid_bytes(const MinMaxPyramid &pyramid, int first_level = 0);

/// The view block of `camera` in the tracer's local frame.
GpuView make_gpu_view(const Tracer &tracer, const Camera &camera,
                      uint32_t loop_budget = GPU_LOOP_BUDGET);

/// The same rays in double (GpuViewDouble).
GpuViewDouble make_gpu_view_double(const Tracer &tracer, const Camera &camera);

/// The t of make_gpu_view's rays at a local point p, as a form of p -
/// `from` (local): t = dot(xyz, p - from) + w, whichever pixel's ray runs
/// through p (a pinhole's rays all leave its eye; a parallel camera's
/// plane of origins and t move together).
glm::dvec4 ray_t_form(const Tracer &tracer, const Camera &camera, glm::dvec3 from);

/// The Kernel block of `camera` (a whole image) with `kernel` and the
/// smoothing of `weights` (gaussian_weights; none: no smoothing).
GpuKernel make_gpu_kernel(const Tracer &tracer, const Camera &camera,
                          const KernelNormals &kernel, const std::vector<double> &weights);

/// `buffer KernelCells` (std430): per cell of `kernel`, (unit vector,
/// offset along forward) and (offsets along du and dv, 0, 0); then each
/// of `weights` as a vec4 (x).
std::vector<float> make_gpu_kernel_cells(const KernelNormals &kernel,
                                         const std::vector<double> &weights);

/// The Shade block of the tracer's scene lit by `shading`, for `outputs`,
/// with its drape's blend and texture frame.
GpuShade make_gpu_shade(const Tracer &tracer, const Shading &shading,
                        const Outputs &outputs);

/// `buffer Drape` (std430, SBRT_DRAPE): the surface of every cell (local
/// z as float bits, < 0 where empty; row from the north, then column, as
/// the model's cells), then the texture's pixels, row from the north, as
/// r | g << 8 | b << 16 | a << 24 with a = 255 where the pixel holds a
/// value, else 0.
std::vector<uint32_t> make_gpu_drape(const Tracer &tracer, const Drape &drape);

/// The colour and class id of every material of the tracer's model.
std::vector<GpuLook> make_gpu_looks(const Tracer &tracer);

/// The material table of the tracer's scene (all opaque without
/// translucency).
std::vector<GpuMaterial> make_gpu_materials(const Tracer &tracer);

/// The hit of a record; `over_budget` tells that the GPU gave up the ray.
Hit decode_gpu_hit(const Tracer &tracer, const Ray &ray,
                   const GpuPixelHit &record, bool &over_budget);

} // namespace sbrt

#endif
