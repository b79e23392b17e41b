/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench's modes, one file each (mode_<name>.cpp), and
 *            the table main dispatches on by name.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TRACE_BENCH_MODES_HPP
#define SBRT_TRACE_BENCH_MODES_HPP

#include <string>

#include "bench_common.hpp"

namespace trace_bench {

/// What main readies for a mode before calling it.
enum class Needs {
    nothing,      ///< the directory and the arguments only (format)
    camera,       ///< the camera; the mode loads the model itself, timed
    model_camera, ///< the model less hide= and the camera
};

struct Mode {
    const char *name;
    Needs needs;
    const char *repeat; ///< repeat='s default
    void (*run)(const Bench &bench);
};

void run_format(const Bench &bench);      // mode_format.cpp
void run_skipping(const Bench &bench);    // mode_skipping.cpp
void run_frame(const Bench &bench);       // mode_frame.cpp
void run_gpu_frame(const Bench &bench);   // mode_gpu_frame.cpp
void run_gpu_pages(const Bench &bench);   // mode_gpu_pages.cpp
void run_paint_frame(const Bench &bench); // mode_paint_frame.cpp
void run_error(const Bench &bench);       // mode_error.cpp
void run_compact(const Bench &bench);     // mode_compact.cpp
void run_row_order(const Bench &bench);   // mode_row_order.cpp

/// The modes in the usage line's order.
inline const Mode MODES[] = {
    {"format", Needs::nothing, "7", run_format},
    {"skipping", Needs::model_camera, "3", run_skipping},
    {"frame", Needs::camera, "3", run_frame},
    {"gpu_frame", Needs::camera, "3", run_gpu_frame},
    // the model read block by block: it opens it itself
    {"gpu_pages", Needs::nothing, "3", run_gpu_pages},
    {"paint_frame", Needs::camera, "3", run_paint_frame},
    {"error", Needs::model_camera, "3", run_error},
    {"compact", Needs::model_camera, "3", run_compact},
    {"row_order", Needs::model_camera, "3", run_row_order},
};

} // namespace trace_bench

#endif
