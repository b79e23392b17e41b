/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench format: the stacks file in format 1 and 2 of the
 *            model in SBRT_DIR (whatever its own format): bytes, bytes per
 *            interval, load (warm) and write times.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>

#include "format/atomic_dir.hpp"
#include "format/format.hpp"
#include "modes.hpp"

using namespace sbrt;

namespace trace_bench {

/// Format 1 against format 2: both written to temporary directories
/// beside SBRT_DIR, each read and written `repeat` times in turns.
void run_format(const Bench &bench)
{
    const std::string &directory = bench.dir;
    const Model model = read_sbrt(directory);
    const std::string v1 = directory + ".bench_v1", v2 = directory + ".bench_v2";
    const auto write_v1 = [&] {
        AtomicDirectory out(v1);
        out.write_file("stacks", encode_stacks_v1(model));
        out.commit();
    };
    write_v1();
    write_sbrt(v2, model, "bench");
    size_t sink = 0;
    const std::vector<double> ms = best_ms_in_turns(
        bench.repeat, {[&] { sink += read_sbrt(v1).intervals().size(); },
                       [&] { sink += read_sbrt(v2).intervals().size(); }, write_v1,
                       [&] { write_sbrt(v2, model, "bench"); }});
    const double v1_bytes = double(read_file_bytes(v1 + "/stacks").size());
    const double v2_bytes = double(read_file_bytes(v2 + "/stacks").size());
    const double intervals = double(model.intervals().size());
    std::printf("format label=%s intervals=%.0f cells=%llu v1_bytes=%.0f v2_bytes=%.0f "
                "v1_per_interval=%.2f v2_per_interval=%.2f v1/v2=%.1f "
                "load_v1_ms=%.1f load_v2_ms=%.1f write_v1_ms=%.1f write_v2_ms=%.1f (%zu)\n",
                bench.args.get("label", directory).c_str(), intervals,
                (unsigned long long)model.frame().cells(), v1_bytes, v2_bytes,
                v1_bytes / intervals, v2_bytes / intervals, v1_bytes / v2_bytes, ms[0], ms[1],
                ms[2], ms[3], sink);
    remove_tree(v1);
    remove_tree(v2);
}

} // namespace trace_bench
