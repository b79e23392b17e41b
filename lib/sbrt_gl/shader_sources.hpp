/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The GLSL sources of shaders/, embedded at build time by
 *            tools/embed_shaders.sh (shader_sources.cpp is generated)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_SHADER_SOURCES_HPP
#define SBRT_GL_SHADER_SOURCES_HPP

namespace sbrt_gl {

extern const char *const SHADER_COMMON_LAYOUT; ///< shaders/common/layout.glsl
extern const char *const SHADER_COMMON_SHADE;  ///< shaders/common/shade.glsl
extern const char *const SHADER_COMMON_RAY;    ///< shaders/common/ray.glsl
extern const char *const SHADER_COMMON_OVERLAYS; ///< shaders/common/overlays.glsl
extern const char *const SHADER_COMMON_CLIP;   ///< shaders/common/clip.glsl
extern const char *const SHADER_COMMON_WALK;   ///< shaders/common/walk.glsl
extern const char *const SHADER_COMMON_TRACE_PIXEL; ///< shaders/common/trace_pixel.glsl
extern const char *const SHADER_RECORDS;       ///< shaders/records.comp
extern const char *const SHADER_SHADE;         ///< shaders/shade.comp
extern const char *const SHADER_COMMON_KERNEL; ///< shaders/common/kernel.glsl
extern const char *const SHADER_COMMON_KERNEL_NORMAL; ///< shaders/common/kernel_normal.glsl
extern const char *const SHADER_KERNEL_DEPTH;  ///< shaders/kernel_depth.comp
extern const char *const SHADER_KERNEL_NORMALS; ///< shaders/kernel_normals.comp
extern const char *const SHADER_KERNEL_ACROSS; ///< shaders/kernel_across.comp
extern const char *const SHADER_KERNEL_SHADE;  ///< shaders/kernel_shade.comp
extern const char *const SHADER_FIRST_PASS;    ///< shaders/first_pass.comp
extern const char *const SHADER_TILE_CULL;     ///< shaders/tile_cull.comp

} // namespace sbrt_gl

#endif
