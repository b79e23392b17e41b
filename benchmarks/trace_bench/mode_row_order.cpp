/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench row_order: on one thread, the rows of the image
 *            traced in the order one of as_threads= (16) threads meets
 *            them (thread k's takes, then thread k+1's), a row a take, in
 *            runs of ROWS_PER_TAKE and in runs traced block by block
 *            (COLS_PER_BLOCK), against the image's own order: what a
 *            thread's cache loses when its rows lie apart (issue 32: at 16
 *            threads the workers' busy time summed to 1.1-1.5 times one
 *            thread's), measured without the cores it needs.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cstdio>

#include "modes.hpp"
#include "tracing/cpu_tracing.hpp"
#include "util/parallel.hpp"

using namespace sbrt;

namespace trace_bench {

void run_row_order(const Bench &bench)
{
    const Camera &camera = bench.camera;
    const Tracer tracer(bench.model, bench.zexag);
    CpuRowTracer rows(tracer, camera, 1, true);
    HitImage hits(static_cast<size_t>(camera.cols()));
    const int image_rows = camera.rows();
    const unsigned as_threads = unsigned(std::stoi(bench.args.get("as_threads", "16")));
    // the takes of `run` rows one of `threads` threads meets, each row
    // traced whole or, `in_blocks`, the take block by block
    // (for_each_block, as the renderer does)
    const auto order = [&](unsigned threads, int run, bool in_blocks = false) {
        return [&, threads, run, in_blocks] {
            const int takes = (image_rows + run - 1) / run;
            for (unsigned t = 0; t < threads; ++t)
                for (int k = int(t); k < takes; k += int(threads)) {
                    const int first = k * run, end = std::min(image_rows, (k + 1) * run);
                    if (!in_blocks) {
                        for (int r = first; r < end; ++r)
                            rows.trace_row(r, hits.data());
                        continue;
                    }
                    for_each_block(first, end, camera.cols(), [&](int row, int c0, int c1) {
                        rows.trace_span(row, c0, c1, hits.data());
                    });
                }
        };
    };
    const int run = ROWS_PER_TAKE;
    const std::vector<double> ms = best_ms_in_turns(
        bench.repeat, {order(1, image_rows), order(as_threads, 1), order(as_threads, run),
                       order(as_threads, run, true)});
    std::printf("row_order label=%s cols=%d rows=%d as_threads=%u image_order_ms=%.1f "
                "a_row_a_take_ms=%.1f (%.2fx) runs_of_%d_ms=%.1f (%.2fx) "
                "runs_in_blocks_of_%d_ms=%.1f (%.2fx)\n",
                bench.args.get("label", "view").c_str(), camera.cols(), image_rows, as_threads,
                ms[0], ms[1], ms[1] / ms[0], run, ms[2], ms[2] / ms[0], COLS_PER_BLOCK, ms[3],
                ms[3] / ms[0]);
}

} // namespace trace_bench
