/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench compact: the same model held compact (as read:
 *            4-byte intervals where its tops are voxel boundaries) and
 *            wide (8 bytes, a view as a v1 file gives): bytes in memory
 *            and on the GPU, and the trace time of one view on the CPU and
 *            the GL path, taken in turns.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>

#include "gpu_tracer.hpp"
#include "modes.hpp"
#include "tracing/cpu_tracing.hpp"

using namespace sbrt;

namespace trace_bench {

namespace {

/// Both models on the GL path (ssbo layout): bytes per interval and per
/// cell, and the trace times.
void gl_compact(sbrt_gl::GlContext &context, const Tracer &compact_tracer,
                const Tracer &wide_tracer, const Bench &bench, double n, double cells)
{
    const std::string label = bench.args.get("label", "view");
    sbrt_gl::GpuTracer gpu_compact(context, compact_tracer, GpuLayout::ssbo);
    sbrt_gl::GpuTracer gpu_wide(context, wide_tracer, GpuLayout::ssbo);
    const std::vector<double> gl_ms =
        best_ms_in_turns(bench.repeat, {[&] { gpu_compact.trace_image(bench.camera); },
                                        [&] { gpu_wide.trace_image(bench.camera); }});
    const GpuMemory &c = gpu_compact.memory(), &w = gpu_wide.memory();
    std::printf("compact view=%s backend=%s renderer=\"%s\" gpu_interval_bytes_per_interval=%.2f "
                "gpu_index_bytes_per_cell=%.3f wide_gpu_interval_bytes_per_interval=%.2f "
                "gl_compact_ms=%.1f gl_wide_ms=%.1f wide/compact=%.3f\n",
                label.c_str(), context.name().c_str(), gpu_compact.gl_renderer().c_str(),
                double(c.interval_bytes) / n, double(c.index_bytes) / cells,
                double(w.interval_bytes) / n, gl_ms[0], gl_ms[1], gl_ms[1] / gl_ms[0]);
}

} // namespace

void run_compact(const Bench &bench)
{
    const Model &read = bench.model;
    const std::string label = bench.args.get("label", "view");
    Intervals owned(read.intervals().size());
    auto wide_records = std::make_shared<std::vector<Interval>>(read.intervals().size());
    for (size_t i = 0; i < wide_records->size(); ++i)
        owned[i] = (*wide_records)[i] = read.intervals()[i];
    const Model wide(read.frame(), read.materials(), read.index(),
                     IntervalArray(wide_records, wide_records->data(), wide_records->size()));
    // owned intervals are packed where exact (a v1 file's view is not)
    const Model model(read.frame(), read.materials(), read.index(), std::move(owned));
    const Tracer compact_tracer(model, bench.zexag), wide_tracer(wide, bench.zexag);
    const std::vector<double> ms =
        best_ms_in_turns(bench.repeat, {[&] { trace_image(compact_tracer, bench.camera); },
                                        [&] { trace_image(wide_tracer, bench.camera); }});
    const Stats s = model.stats();
    const double cells = double(model.frame().cells()), n = double(s.intervals);
    std::printf("compact view=%s intervals=%.0f cells=%.0f compact=%s "
                "interval_bytes_per_interval=%.2f index_bytes_per_cell=%.3f "
                "v1_memory_per_interval=8.00 v1_index_per_cell=4.00 "
                "cpu_compact_ms=%.1f cpu_wide_ms=%.1f wide/compact=%.3f\n",
                label.c_str(), n, cells, model.intervals().is_compact() ? "yes" : "no",
                double(s.interval_bytes) / n, double(s.index_bytes) / cells, ms[0], ms[1],
                ms[1] / ms[0]);
    if (std::unique_ptr<sbrt_gl::GlContext> context = gl_context(bench.args))
        gl_compact(*context, compact_tracer, wide_tracer, bench, n, cells);
}

} // namespace trace_bench
