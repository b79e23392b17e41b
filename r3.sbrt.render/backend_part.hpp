/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's backend: renderer, GPU layout, threads (the
 *            GL context and the prepared scene key on it)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_BACKEND_PART_HPP
#define R3_SBRT_BACKEND_PART_HPP

#include <cstdint>
#include <string>

#include "option_table.hpp"

/// \brief backend=, layout=, gpu_memory=, nprocs=, -e.
struct BackendPart {
    std::string backend = "auto";
    std::string gpu_layout = "ssbo"; ///< layout=: ssbo or textures
    /// gpu_memory=: the GPU's atlas of a model read block by block
    uint64_t gpu_memory_bytes = uint64_t(1024) << 20;
    int threads = 0;
    bool walk_every_cell = false; ///< -e: no empty-space skipping

    static void define(OptionTable &table);
    void read(const Answers &answers);
    std::string key() const;
};

#endif
