// Blocks shared by the ray casting shaders; mirrored in C++ by
// lib/sbrt/gpu/gpu_layout.hpp (static_asserts there, offsets checked by the
// unit test GpuLayout.MatchesTheShader). Local frame: x in cells from the
// west edge, y in cells from the south edge, z in tb_res steps from the
// bottom, vertical exaggeration applied.

// The view: per pixel (x, y) in normalised device coordinates, a ray
// passes through base + x spread_u + y spread_v (base = hi + lo, a point
// near the model) along forward + x du + y dv (du = dv = 0 for parallel
// rays), and starts at t = spread_u.w (the eye; 0 where the camera is
// near). Starting from near the model keeps the precision of a camera far
// away; the base is split into a high and a low float so that distances
// to cell walls keep theirs far from the origin of the map.
layout(std140, binding = 0) uniform View {
    vec4 origin_hi;     // xyz: base, high part
    vec4 origin_lo;     // xyz: base, low part
    vec4 forward;       // xyz
    vec4 du;            // xyz: direction per unit of x
    vec4 dv;            // xyz: direction per unit of y
    vec4 spread_u;      // xyz: base per unit of x; w: t where rays start
    vec4 spread_v;      // xyz: base per unit of y
    uvec4 grid;         // cols, rows of the model; image cols, rows
    vec4 box;           // x: highest interval top (local z); yzw: size of
                        // a local unit in exaggerated map units
    uvec4 options;      // x: 1 = parallel rays, y: loop budget,
                        // z: first image row of this dispatch, w: its rows
    vec4 planes[8];     // clip planes: xyz normal n (local), w: n . base + c;
                        // kept where n . (x - base) + w <= 0
    uvec4 counts;       // x: clip planes; y: levels of the pyramid (0: no
                        // empty-space skipping); z: 1 where the first
                        // pass's bounds are in TileStarts; w: tile columns
};

#ifndef SBRT_KERNEL
// The model, in one of two layouts (section 4.2 of Graciano et al.), read
// through stack_range, interval_material and interval_top. A cell's stack
// is the intervals [first, last), bottom to top; an interval is its
// material (index into the material table, 0 = empty) and its top (local z).
// Where the model holds its intervals compact (SBRT_COMPACT_INTERVALS: tops
// are voxel boundaries), an interval is one word, material | top << 16.
#ifdef SBRT_COMPACT_INTERVALS
uint compact_material(uint word) { return word & 0xffffu; }
float compact_top(uint word) { return float(word >> 16); }
#endif
#if defined(SBRT_PAGED)
// A paged model (lib/sbrt/gpu/gpu_pages.hpp): the blocks rays reached, in
// one atlas of words found through the page table. A block's words: for
// each of its cells (row by row) where its stack starts and where the last
// ends, in records from the block's first; then, from the next even word,
// its intervals. A block not in the atlas is marked wanted, and the ray
// that reached it is sent back (walk_into_stack) to be traced again once
// the host brought the block up; a block read is marked too (the host
// keeps a frame's blocks).
layout(std430, binding = 0) readonly buffer PageTable {
    uvec4 page_head; // block size, blocks a row, words of each half of the marks
    uint page_base[]; // each block's first word in the atlas, PAGE_MISSING
};
layout(std430, binding = 1) readonly buffer Atlas { uint atlas[]; };
layout(std430, binding = 6) buffer PageMarks { uint page_marks[]; }; // wanted, then read
const uint PAGE_MISSING = 0xffffffffu;
#ifdef SBRT_COLUMN_TOPS
// Each column's top interval (cell row by row from the north), as the
// intervals: its material and, for its top, its bottom. A ray that meets
// only that interval walks a stack of two records instead of its block's
// (walk.glsl, top_interval_stack): TOP_STACK, nothing up to that bottom,
// and TOP_STACK + 1, the interval up to the column's top; set for the
// cell being walked.
#ifndef SBRT_COLUMN_PAGES
layout(std430, binding = 15) readonly buffer ColumnTops { uint column_tops[]; };
#endif
#endif
#ifdef SBRT_COLUMN_RANGES
// Each column's range (cell row by row from the north): the pyramid's
// level 0, held for the model (the scene's levels above are in Pyramid)
layout(std430, binding = 16) readonly buffer ColumnRanges { vec2 column_ranges[]; };
#endif
#ifdef SBRT_COLUMN_TOPS
// below 2^31, so that a search's (low + high) / 2 does not wrap; above every
// record of the atlas (gpu_pages.hpp, GPU_MAX_ATLAS_WORDS)
const uint TOP_STACK = 0x7ffffff0u;
uint top_material = 0u;
float top_bottom = 0.0, top_high = 0.0;
#define TOP_RECORD(j, below, top) if (j >= TOP_STACK) return j == TOP_STACK ? below : top
#else
#define TOP_RECORD(j, below, top)
#endif
#ifdef SBRT_COMPACT_INTERVALS
uint interval_material(uint j)
{
    TOP_RECORD(j, 0u, top_material);
    return compact_material(atlas[j]);
}
float interval_top(uint j)
{
    TOP_RECORD(j, top_bottom, top_high);
    return compact_top(atlas[j]);
}
#else
uint interval_material(uint j)
{
    TOP_RECORD(j, 0u, top_material);
    return atlas[2u * j];
}
float interval_top(uint j)
{
    TOP_RECORD(j, top_bottom, top_high);
    return uintBitsToFloat(atlas[2u * j + 1u]);
}
#endif

// Block `block`'s bit in part `part` of the marks (0 wanted, 1 read)
void mark_page(uint part, uint block)
{
    uint word = part * page_head.z + (block >> 5), bit = 1u << (block & 31u);
    if ((page_marks[word] & bit) == 0u)
        atomicOr(page_marks[word], bit);
}

// Page `page`'s first word in the atlas, marked read; PAGE_MISSING where
// it is not there (marked wanted)
uint page_at(uint page)
{
    uint base = page_base[page];
    mark_page(base == PAGE_MISSING ? 0u : 1u, page);
    return base;
}

// (PAGE_MISSING, 0) where the cell's block is not in the atlas
uvec2 stack_range(int col, int row_from_north)
{
    uint size = page_head.x;
    uint bx = uint(col) / size, by = uint(row_from_north) / size;
    uint base = page_at(by * page_head.y + bx);
    if (base == PAGE_MISSING)
        return uvec2(PAGE_MISSING, 0u);
    uint cols = min(size, grid.x - bx * size), rows = min(size, grid.y - by * size);
    uint cell = (uint(row_from_north) - by * size) * cols + (uint(col) - bx * size);
    uint records = base + ((cols * rows + 2u) & ~1u);
#ifndef SBRT_COMPACT_INTERVALS
    records >>= 1; // two words a record
#endif
    return uvec2(records + atlas[base + cell], records + atlas[base + cell + 1u]);
}

#ifdef SBRT_COLUMN_PAGES
// A model too large for the GPU to hold every column's top interval and
// range (the pyramid's level 0): each block's columns in a page of their
// own, page page_head.w + block (gpu_pages.hpp, gpu_column_page_words):
// per cell, row by row, its top interval (as ColumnTops) and its range; a
// word each where compact, else two each.
#ifdef SBRT_COMPACT_INTERVALS
const uint COLUMN_WORDS = 2u;
#else
const uint COLUMN_WORDS = 4u;
#endif

// The cell's first word in its columns' page; PAGE_MISSING where that is
// not in the atlas (marked wanted)
uint column_entry(int col, int row_from_north)
{
    uint size = page_head.x;
    uint bx = uint(col) / size, by = uint(row_from_north) / size;
    uint base = page_at(page_head.w + by * page_head.y + bx);
    if (base == PAGE_MISSING)
        return PAGE_MISSING;
    uint cols = min(size, grid.x - bx * size);
    return base + ((uint(row_from_north) - by * size) * cols + (uint(col) - bx * size)) *
                      COLUMN_WORDS;
}

// The range of the column whose entry is at `at`, as a pyramid node
vec2 column_range(uint at)
{
#ifdef SBRT_COMPACT_INTERVALS
    uint word = atlas[at + 1u];
    return vec2(float(word & 0xffffu), float(word >> 16));
#else
    return vec2(uintBitsToFloat(atlas[at + 2u]), uintBitsToFloat(atlas[at + 3u]));
#endif
}
#endif
#elif defined(SBRT_TEXTURES)
// 1-Textures: texel (col, row from the north) of the index texture holds
// the cell's first interval and count; texel (j % width, j / width) of the
// interval texture holds interval j's material and the bits of its top.
layout(binding = 0) uniform usampler2D index_texture;
layout(binding = 1) uniform usampler2D interval_texture;
uint interval_texture_width = 1u; // set once per invocation by main

uvec2 stack_range(int col, int row_from_north)
{
    uvec2 texel = texelFetch(index_texture, ivec2(col, row_from_north), 0).rg;
    return uvec2(texel.x, texel.x + texel.y);
}
uvec2 interval_texel(uint j)
{
    return texelFetch(interval_texture,
                      ivec2(j % interval_texture_width, j / interval_texture_width), 0).rg;
}
#ifdef SBRT_COMPACT_INTERVALS
uint interval_material(uint j) { return compact_material(interval_texel(j).x); }
float interval_top(uint j) { return compact_top(interval_texel(j).x); }
#else
uint interval_material(uint j) { return interval_texel(j).x; }
float interval_top(uint j) { return uintBitsToFloat(interval_texel(j).y); }
#endif
#else
// 5-SSBO, the model's stack index as it holds it (lib/sbrt/model/stack_index.hpp):
// cell = row_from_north * cols + col starts at the offset of its group of 16
// cells plus the counts of the cells before it there; counts are
// SBRT_COUNT_BYTES wide, packed into words (little-endian).
layout(std430, binding = 0) readonly buffer GroupOffsets { uint group_offsets[]; };
layout(std430, binding = 6) readonly buffer Counts { uint count_words[]; };
#ifdef SBRT_COMPACT_INTERVALS
layout(std430, binding = 1) readonly buffer Intervals { uint intervals[]; };
uint interval_material(uint j) { return compact_material(intervals[j]); }
float interval_top(uint j) { return compact_top(intervals[j]); }
#else
struct Interval {
    uint material;
    float top;
};
layout(std430, binding = 1) readonly buffer Intervals { Interval intervals[]; };
uint interval_material(uint j) { return intervals[j].material; }
float interval_top(uint j) { return intervals[j].top; }
#endif

uint stack_count(uint cell)
{
#if SBRT_COUNT_BYTES == 1
    return (count_words[cell >> 2] >> (8u * (cell & 3u))) & 0xffu;
#elif SBRT_COUNT_BYTES == 2
    return (count_words[cell >> 1] >> (16u * (cell & 1u))) & 0xffffu;
#else
    return count_words[cell];
#endif
}

// Sum of the counts before `cell` in its group.
uint counts_before(uint cell)
{
    uint sum = 0u;
#if SBRT_COUNT_BYTES == 1
    // four counts a word: whole words, then the bytes below the cell's own
    uint word = (cell & ~15u) >> 2;
    for (; word < cell >> 2; ++word) {
        uint w = count_words[word];
        uint lanes = (w & 0x00ff00ffu) + ((w >> 8) & 0x00ff00ffu);
        sum += (lanes & 0xffffu) + (lanes >> 16);
    }
    uint bits = 8u * (cell & 3u);
    uint w = bits == 0u ? 0u : count_words[word] & ((1u << bits) - 1u);
    uint lanes = (w & 0x00ff00ffu) + ((w >> 8) & 0x00ff00ffu);
    sum += (lanes & 0xffffu) + (lanes >> 16);
#else
    for (uint c = cell & ~15u; c < cell; ++c)
        sum += stack_count(c);
#endif
    return sum;
}

uvec2 stack_range(int col, int row_from_north)
{
    uint cell = uint(row_from_north) * grid.x + uint(col);
    uint first = group_offsets[cell >> 4] + counts_before(cell);
    return uvec2(first, first + stack_count(cell));
}
#endif

// Empty-space skipping: the min-max pyramid of lib/sbrt/scene/minmax_pyramid.hpp.
// Level L has (offset, cols, rows) in levels[L]; its node (x, y), x from
// the west and y from the south, is nodes[offset + y * cols + x]: the
// lowest bottom and highest top (local z) of what is drawn in its cells,
// low > high where they hold nothing.
const uint MAX_PYRAMID_LEVELS = 32u;
layout(std430, binding = 4) readonly buffer Pyramid {
    uvec4 levels[MAX_PYRAMID_LEVELS];
    vec2 nodes[];
};

// The coarse first pass (first_pass.comp): per tile of the image, row-major,
// a t before which no ray of the tile meets anything (inf: nothing at all).
layout(std430, binding = 8) buffer TileStarts { float tile_starts[]; };

// How each material looks: rgb colour (0..1) and its Beer-Lambert
// extinction per exaggerated map unit; negative for an opaque material.
layout(std430, binding = 3) readonly buffer Materials { vec4 materials[]; };

#endif // SBRT_KERNEL

#ifdef SBRT_SHADE
// Shaded on the GPU: the band's outputs, the bytes the host hands on
// (sbrt::GpuBandLayout): RGB8 rows packed into words, each row from a
// whole word (Shade.outputs.x words apart); then, where Shade.outputs.y
// asks for them, the class ids, the elevations and the depths (doubles as
// two words, NaN where the ray meets nothing) from the words
// Shade.band_planes.xyz; at Shade.band_planes.w the count of rays over the loop
// budget, then their pixels, traced again on the host. The buffer is
// mapped into host memory: these words are what the host reads.
layout(std430, binding = 2) buffer Pixels { uint words[]; };

#ifdef SBRT_TILE_LIST
// The boreholes' pass (SBRT_BOREHOLES): one work group a listed tile of
// 8 x 8 pixels of the band, listed on the GPU by shaders/tile_cull.comp
// (or every tile by the host): sbrt::GpuTileHead (word 3: box slots a
// tile, 0 without box lists; 4: the band's tile columns; 6: boxes; 7, 8,
// 9: where the list, the tiles' counts of boxes and their slots start),
// then the tiles x | y << 16, each tile's count, its boxes; and the boxes
// (sbrt::make_gpu_boxes): each box's local low and high corner. The model
// alone was shaded everywhere before.
layout(std430, binding = 12) readonly buffer Tiles { uint tiles[]; };
layout(std430, binding = 14) readonly buffer Boxes { float boxes[]; };
uvec2 work_group_tile()
{
    uint tile = tiles[tiles[7] + gl_WorkGroupID.x];
    return uvec2(tile & 0xffffu, tile >> 16);
}
#else
uvec2 work_group_tile() { return gl_WorkGroupID.xy; }
#endif
#if defined(SBRT_HIT_T) || defined(SBRT_TILE_LIST)
// The model's pass with boreholes drawn in a pass of their own: each
// pixel's t of its opaque hit, 1/0 where it has none, then each tile's
// farthest (binding 13)
layout(std430, binding = 13) buffer HitTs { float hit_ts[]; };
#endif

// What shading needs besides the view; mirrored by sbrt::GpuShade.
layout(std140, binding = 1) uniform Shade {
    vec4 light;            // xyz: towards the light (exaggerated map space,
                           // unit length); w: ambient share
    vec4 background;       // rgb: 0..255
    vec4 real_unit;        // xyz: real map length of a local unit per axis;
                           // w: elevation of local z = 0
    vec4 elevation_step;   // x: elevation per local z unit
    vec4 plane_normals[8]; // xyz: shading normal of each clip plane
    uvec4 outputs;         // x: words from an RGB row to the next; y: 1
                           // class id, 2 elevation, 4 depth
    uvec4 band_planes;     // where the class ids, elevations, depths and
                           // rays over the budget start (words)
    vec4 drape;            // SBRT_DRAPE: x: blend; y, z: the texture's
                           // cols and rows
    vec4 drape_map;        // the texture's (column, row) of local (x, y):
                           // (x * lx + y, z * ly + w), pixel centres whole
};

#ifdef SBRT_DRAPE
// The drape (lib/sbrt/shading/drape.hpp): the local z of each cell's
// surface (float bits, < 0 where empty; cells as the model's, rows from
// the north), then the texture's pixels from the north, r | g << 8 |
// b << 16 | a << 24 (a = 0 where the pixel holds no value).
layout(std430, binding = 7) readonly buffer Drape { uint drape_words[]; };
#endif

#ifdef SBRT_PAINT
// Colours by voxel (lib/sbrt/gpu/gpu_paint.hpp; a scene with a drape has
// none, so it takes the drape's binding): a head (where the entries and
// the colours start, fade values + 1 or 0, the no-value entry's colour),
// per cell its first entry and lo | hi << 16, the voxels' 16-bit entries,
// the colours as float bits r, g, b.
layout(std430, binding = 7) readonly buffer Paint { uint paint_words[]; };
// The View block's rays in double (sbrt::GpuViewDouble): a hit near a
// voxel's edge is placed on its face again as the CPU's tracer places it
layout(std140, binding = 3) uniform ViewDouble {
    dvec4 exact_origin; // xyz: the base, unrounded
    dvec4 exact_forward;
    dvec4 exact_du;
    dvec4 exact_dv;
    dvec4 exact_spread_u;
    dvec4 exact_spread_v;
};
#endif

// Per material: x: its colour r | g << 8 | b << 16; y: its class id.
layout(std430, binding = 5) readonly buffer Looks { uvec4 looks[]; };
#endif

// A hit record: what the ray of a pixel met.
struct PixelHit {
    vec3 point;         // local coordinates of the hit
    uint code;          // material | face << 16 | plane << 20 | over budget << 24
    vec4 veil;          // rgb: light of the translucent strata in front of
                        // the hit (premultiplied); a: transmittance
};
#ifndef SBRT_SHADE
// One record per pixel of the band, row-major from its top row.
layout(std430, binding = 2) writeonly buffer Hits { PixelHit hits[]; };
#endif

#ifdef SBRT_KERNEL
// The image-space kernel normals' passes (common/kernel.glsl), over the
// hit records of the whole image, row-major (binding 0), and its view
// depths (binding 1; written by the depth pass, kernel_depth.comp).
layout(std430, binding = 0) readonly buffer ImageHits { PixelHit image_hits[]; };
layout(std430, binding = 1) buffer Depths { float depths[]; };
// The kernel's cells (lib/sbrt/shading/kernel_normals.hpp): per cell two
// vec4: the unit vector from the centre and its offset along the view's
// forward axis; its offsets along du and dv. Then, with smoothing, the
// Gaussian's weights from -radius to radius, one a vec4 (x).
layout(std430, binding = 4) readonly buffer KernelCells { vec4 kernel_cells[]; };
// With smoothing: each pixel's kernel normal (w: 1 on a hit the kernels
// see, else 0), and the sums along its row (binding 6).
layout(std430, binding = 3) buffer KernelNormals { vec4 kernel_normals[]; };
layout(std430, binding = 6) buffer KernelAcross { vec4 kernel_across[]; };
// The camera in the kernel's terms; mirrored by sbrt::GpuKernel.
layout(std140, binding = 2) uniform Kernel {
    vec4 kernel_eye;     // xyz: the camera's origin from the model's corner
                         // (exaggerated map units); w: 1 = parallel rays
    vec4 kernel_forward; // xyz: unit view axis; w: the depth tolerance's
                         // part that does not grow with the depth
    vec4 kernel_du;      // xyz: du; w: du . du
    vec4 kernel_dv;      // xyz: dv; w: dv . dv
    vec4 kernel_voxel;   // xyz: exaggerated map units per local unit
    uvec4 kernel_counts; // x: cells; y: first image row of this dispatch;
                         // z: its rows; w: the smoothing's radius (pixels,
                         // 0: none)
};

// the smoothing's weight d pixels away (-radius <= d <= radius)
float smoothing_weight(int d)
{
    return kernel_cells[2u * kernel_counts.x + uint(d + int(kernel_counts.w))].x;
}
#endif

const uint FACE_NONE = 0u, FACE_WEST = 1u, FACE_EAST = 2u, FACE_SOUTH = 3u,
           FACE_NORTH = 4u, FACE_BOTTOM = 5u, FACE_TOP = 6u, FACE_PLANE = 7u,
           FACE_CYLINDER = 8u, FACE_FENCE = 9u, FACE_SPLIT = 10u;
const uint CODE_OVER_BUDGET = 1u << 24;
