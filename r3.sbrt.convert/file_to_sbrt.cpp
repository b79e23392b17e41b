/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A variable of a multidimensional file (NetCDF, HDF5, Zarr)
 *            -> SBRT, streamed band by band of rows; -p on a file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include <algorithm>
#include <future>

#include "builders/band_import.hpp"
#include "builders/column_builder.hpp"
#include "util/error.hpp"
#include "file_crs.hpp"
#include "file_variable.hpp"
#include "grass.hpp"
#include "util/unfilled_allocator.hpp"

namespace {

/// Larger bands bring nothing but page clearing (measured: 16 MiB bands
/// import 1.5x faster than 300 MiB ones).
constexpr size_t MAX_BAND_BYTES = size_t(16) << 20;

using Buffer = std::vector<double, sbrt::UnfilledAllocator<double>>;

/// The file's frame in the current location (its proj and zone).
sbrt::Frame located_frame(const FileVariable &variable)
{
    sbrt::Frame frame = variable.frame();
    struct Cell_head window;
    G_get_window(&window);
    frame.proj = window.proj;
    frame.zone = window.zone;
    return frame;
}

} // namespace

sbrt::Model file_to_sbrt(const char *file, const char *name,
                         sbrt::Classifier &classifier, bool override_crs,
                         size_t band_bytes)
{
    const FileVariable variable(file, name);
    if (!variable.is_integer() && !classifier.has_rules())
        G_fatal_error(_("Variable '%s' of <%s> holds %s values: give rules= to "
                        "say which value ranges make which class"),
                      name, file, variable.type_name().c_str());
    check_file_crs(variable, file, override_crs);
    const sbrt::Frame frame = located_frame(variable);
    const sbrt::RegularAxis &x = variable.easting(), &y = variable.northing(),
                            &z = variable.vertical();
    const size_t nx = x.size, ny = y.size, nz = z.size;
    G_message(_("Converting variable '%s' of <%s> (%zu x %zu x %zu voxels, "
                "%s)..."),
              name, file, nx, ny, nz, variable.type_name().c_str());

    sbrt::ColumnStackBuilder builder(frame);
    const size_t band = variable.band_size(std::min(band_bytes, MAX_BAND_BYTES));
    // the next band is read (one thread) while this one is converted;
    // doubles keep every sample type aligned
    const size_t doubles = (band * nx * nz * variable.sample_bytes() + 7) / 8;
    Buffer buffers[2] = {Buffer(doubles), Buffer(doubles)};
    // a band's rows and the first northing index they read (the file's
    // northing may run south to north)
    struct Rows {
        size_t count, first;
    };
    auto rows_of = [&](size_t row0) {
        const size_t count = std::min(band, ny - row0);
        return Rows{count, y.ascending ? ny - row0 - count : row0};
    };
    auto read = [&](size_t row0, Buffer &buffer) {
        const Rows rows = rows_of(row0);
        return std::async(std::launch::async, [&variable, &buffer, rows] {
            return variable.read_band(rows.first, rows.count, buffer.data());
        });
    };
    sbrt::BandImport import(variable.band_grid(), classifier, builder);
    std::future<sbrt::BandStrides> pending = read(0, buffers[0]);
    for (size_t row0 = 0, b = 0; row0 < ny; row0 += band, b ^= 1) {
        G_percent(row0, ny, 2);
        const sbrt::BandStrides step = pending.get();
        if (row0 + band < ny)
            pending = read(row0 + band, buffers[b ^ 1]);
        const Rows rows = rows_of(row0);
        try {
            import.add(buffers[b].data(), step, row0, rows.count, rows.first);
        }
        catch (const sbrt::Error &e) {
            if (pending.valid())
                pending.wait(); // no read left running past the error
            G_fatal_error(_("Variable '%s' of <%s>, %s"), name, file, e.what());
        }
    }
    G_percent(1, 1, 1);
    if (import.unmatched())
        G_warning(_("%llu voxels matched no rule and became empty"),
                  (unsigned long long)import.unmatched());
    sbrt::Model model = builder.finish(
        classifier.has_rules() ? rule_legend(classifier) : variable.flag_labels());
    if (model.stats().solid_intervals == 0)
        G_fatal_error(_("Variable '%s' of <%s> holds only missing values"), name,
                      file);
    G_verbose_message(_("For -r, set the 3D region to the SBRT's: g.region "
                        "n=%.15g s=%.15g e=%.15g w=%.15g t=%.15g b=%.15g "
                        "rows=%d cols=%d tbres=%.15g"),
                      frame.north, frame.south, frame.east, frame.west,
                      frame.top, frame.bottom, frame.rows, frame.cols,
                      frame.tb_res());
    return model;
}

void print_file_variables(const char *file, bool shell)
{
    const std::vector<VariableSummary> variables = list_file_variables(file);
    if (!shell)
        fprintf(stdout, "Variables of <%s>:\n", file);
    for (const VariableSummary &v : variables) {
        std::string dims, sizes;
        for (size_t i = 0; i < v.dimensions.size(); ++i) {
            dims += (i ? "," : "") + v.dimensions[i];
            sizes += (i ? "," : "") + std::to_string(v.sizes[i]);
        }
        if (shell)
            fprintf(stdout, "variable=%s|type=%s|dimensions=%s|sizes=%s|"
                            "long_name=%s|units=%s\n",
                    v.name.c_str(), v.type.c_str(), dims.c_str(), sizes.c_str(),
                    v.long_name.c_str(), v.units.c_str());
        else
            fprintf(stdout, "  %-16s %-8s (%s) = (%s)%s%s%s\n", v.name.c_str(),
                    v.type.c_str(), dims.c_str(), sizes.c_str(),
                    v.long_name.empty() ? "" : "  ", v.long_name.c_str(),
                    v.units.empty() ? "" : (" [" + v.units + "]").c_str());
    }
}
