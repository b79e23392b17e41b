/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The backend of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "backend_part.hpp"
#include "module_options.hpp"


void BackendPart::define(OptionTable &table)
{
    table.define_choice(
        "backend", _("Renderer"), _("Settings"), "auto", "auto,egl,osmesa,cpu",
        _("auto;GPU through EGL, else OSMesa, else (or where the only "
          "OpenGL is a slower software one) the CPU ray caster;"
          "egl;OpenGL compute shader, headless EGL context;"
          "osmesa;OpenGL compute shader, OSMesa context (Mesa < 25.1);"
          "cpu;Exact multithreaded CPU ray caster"));
    table.define_choice(
        "layout", _("How the GPU holds the model (OpenGL backends)"), _("Settings"), "ssbo",
        "ssbo,textures",
        _("ssbo;two storage buffers, cell offsets and intervals (5-SSBO);"
          "textures;an index texture over the grid and the intervals packed "
          "into a 2D texture (1-Textures; grids up to the largest texture)"));
    Option *gpu_memory = table.define(
        "gpu_memory", TYPE_INTEGER,
        _("GPU memory (in MB) for a model the GPU takes block by block as its rays reach "
          "them: its empty-space pyramid, columns' tops and blocks (OpenGL, layout=ssbo)"),
        _("Settings"), "1024");
    gpu_memory->options = "1-1048576";
    Option *nprocs = table.add(sbrt_grass::define_nprocs());
    nprocs->guisection = _("Settings");
    table.define_flag('e',
                      _("Walk every cell: no empty-space skipping (the same image, "
                        "slower; for benchmarks)"),
                      _("Settings"));
}

void BackendPart::read(const Answers &a)
{
    backend = a.text("backend", "auto");
    gpu_layout = a.text("layout", "ssbo");
    gpu_memory_bytes = uint64_t(a.number("gpu_memory")) << 20;
    walk_every_cell = a.flag('e');
    threads = int(sbrt_grass::read_nprocs(a.text("nprocs", "0")));
}

std::string BackendPart::key() const
{
    return backend + ' ' + gpu_layout + ' ' + std::to_string(gpu_memory_bytes) + ' ' +
           std::to_string(threads) + ' ' +
           std::to_string(int(walk_every_cell));
}
