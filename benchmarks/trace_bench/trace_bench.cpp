/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   In-process timings on an SBRT file, best of `repeat`, one
 *            mode a file (mode_<name>.cpp) over bench_common:
 *              skipping  the exact tracer with and without empty-space
 *                        skipping, and with skipping but without the
 *                        coarse first pass (and on the GPU where a
 *                        context opens)
 *              frame     the streamed pipeline in process: load, prepare
 *                        (Renderer), a whole frame (trace, shade, the RGB
 *                        bands handed to a sink), warm, on threads= (0:
 *                        all cores); beside it the whole-image reference
 *                        (trace_image, then shade), and the first frame
 *                        on its own (first_frame_ms)
 *              gpu_frame the streamed frame on the GPU (gpu=, default
 *                        egl): the model uploaded once; traced, shaded
 *                        (face, then kernel normals) and the RGB read back,
 *                        warm, each kind back to back (the GPU's after 0.3 s
 *                        of frames: its clocks fall between short frames);
 *                        beside them the CPU's frame (threads=), and the
 *                        pixels of the GPU's image apart from the CPU's
 *              paint_frame the class view against a property (property=
 *                        a+b: their sum through a ramp) and a fade
 *                        (fade=c, 0..100) on the GPU (gpu=) and the CPU:
 *                        each kind's first frame of a fresh GPU renderer
 *                        and channels (the colours by voxel made and
 *                        uploaded; and coloured on the host at the GPU's
 *                        hits instead), its warm frame, whether the GPU shaded
 *                        it, and the pixels whose colour differs from the
 *                        CPU's by more than one level
 *              row_order on one thread, the rows in the order one of
 *                        as_threads= (16) threads meets them, a row a take,
 *                        in runs (ROWS_PER_TAKE) and in runs traced block
 *                        by block (COLS_PER_BLOCK), against the image's
 *                        own order
 *              format    the stacks file in format 1 and 2: bytes, bytes
 *                        per interval, load (warm) and write times
 *              error     time against error: the exact method, the sampled
 *                        one (steps 1..1/16 cell, adaptive), kernel
 *                        normals k = 3..11, each against the exact CPU
 *                        reference with face normals
 *              compact   the model held compact (4-byte intervals) against
 *                        wide (8 bytes): bytes, and one view's trace time
 *                        on the CPU and the GL path
 *            Scripts parse the output lines (device_run.sh and the
 *            *_benchmark.sh scripts beside this folder): their words and
 *            field names are an interface.
 * USAGE:     trace_bench format SBRT_DIR [repeat=7] [label=name]
 *            trace_bench skipping|frame|gpu_frame|paint_frame|error|compact|row_order
 *            SBRT_DIR position=x,y,z
 *            target=x,y,z [fov=25] [zexag=1] [cols=1056] [rows=884]
 *            [repeat=3] [hide=id,id] [label=name] [gpu=egl|osmesa|none]
 *            [threads=N] [classes=FILE: error writes the reference's class
 *            ids, int32] [boreholes=N radius=R: gpu_frame with N boreholes]
 *            [property=a+b fade=c: paint_frame] [cpu=0: gpu_frame without
 *            the CPU's frames] [reference=0: frame without the whole-image
 *            reference] [paged=MB: the model opened paged within MB, as
 *            the modules open it; frame's first_frame_ms decodes its
 *            blocks] [as_threads=16: row_order]; instead of position=,
 *            azimuth= and elevation= (degrees) frame the whole model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>
#include <exception>
#include <string>

#include "format/format.hpp"
#include "modes.hpp"
#include "util/error.hpp"

using namespace trace_bench;

namespace {

const Mode *find_mode(const std::string &name)
{
    for (const Mode &mode : MODES)
        if (name == mode.name)
            return &mode;
    return nullptr;
}

/// What `mode` needs of the command line: the model (less hide=) and the
/// camera, in the order the single-file trace_bench read them (its
/// failures come in the same order).
Bench ready(const Mode &mode, const std::string &dir, Args args)
{
    Bench bench;
    bench.dir = dir;
    bench.args = std::move(args);
    if (mode.needs == Needs::model_camera)
        bench.model = load(dir, bench.args);
    bench.zexag = std::stod(bench.args.get("zexag", "1"));
    bench.repeat = std::stoi(bench.args.get("repeat", mode.repeat));
    if (mode.needs == Needs::camera) // the mode loads it itself, timed
        bench.camera = camera_of(bench.args, sbrt::read_sbrt(dir), bench.zexag);
    else if (mode.needs == Needs::model_camera)
        bench.camera = camera_of(bench.args, bench.model, bench.zexag);
    return bench;
}

} // namespace

int main(int argc, char *argv[])
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s format|skipping|frame|gpu_frame|gpu_pages|paint_frame|error|compact|row_order SBRT_DIR key=value...\n", argv[0]);
        return 2;
    }
    try {
        Args args = parse_args(argc, argv, 3);
        const Mode *mode = find_mode(argv[1]);
        if (!mode)
            sbrt::fail("unknown mode ", argv[1]);
        mode->run(ready(*mode, argv[2], std::move(args)));
    }
    catch (const std::exception &e) {
        std::fprintf(stderr, "trace_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
