/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A variable of a multidimensional file (NetCDF, HDF5, Zarr)
 *            -> SBRT, streamed band by band of rows; -p on a file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include <algorithm>

#include "column_builder.hpp"
#include "error.hpp"
#include "file_crs.hpp"
#include "file_variable.hpp"
#include "grass.hpp"

namespace {

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
    const size_t band = variable.band_size(band_bytes);
    std::vector<double> values(band * nx * nz);
    std::vector<int32_t> column(nz);
    const sbrt::MissingValues &missing = variable.missing();
    // rows go north to south, columns west to east, depths bottom up,
    // whatever the order of the file's indices
    for (size_t row0 = 0; row0 < ny; row0 += band) {
        G_percent(row0, ny, 2);
        const size_t rows = std::min(band, ny - row0);
        const size_t first = y.ascending ? ny - row0 - rows : row0;
        variable.read_band(first, rows, values.data());
        for (size_t row = row0; row < row0 + rows; ++row) {
            const size_t yi = (y.ascending ? ny - 1 - row : row) - first;
            for (size_t col = 0; col < nx; ++col) {
                const size_t xi = x.ascending ? col : nx - 1 - col;
                const double *v = values.data() + (yi * nx + xi) * nz;
                size_t d = 0;
                try {
                    for (; d < nz; ++d) {
                        const double value = v[z.ascending ? d : nz - 1 - d];
                        column[d] = missing.is_missing(value)
                                        ? sbrt::NULL_CLASS
                                        : classifier.classify(value);
                    }
                }
                catch (const sbrt::Error &e) {
                    G_fatal_error(_("Variable '%s' of <%s>, row %zu, column "
                                    "%zu, depth %zu (from the bottom): %s"),
                                  name, file, row + 1, col + 1, d + 1, e.what());
                }
                builder.add_column(column.data());
            }
        }
    }
    G_percent(1, 1, 1);
    if (classifier.unmatched())
        G_warning(_("%llu voxels matched no rule and became empty"),
                  (unsigned long long)classifier.unmatched());
    sbrt::Model model = builder.finish(
        classifier.has_rules() ? rule_legend(classifier) : variable.flag_labels());
    if (model.stats().solid_intervals == 0)
        G_fatal_error(_("Variable '%s' of <%s> holds only missing values"), name,
                      file);
    G_verbose_message(_("For -r, set the 3D region to the SBRT's: g.region "
                        "n=%.15g s=%.15g e=%.15g w=%.15g t=%.15g b=%.15g "
                        "rows=%d cols=%d depths=%d"),
                      frame.north, frame.south, frame.east, frame.west,
                      frame.top, frame.bottom, frame.rows, frame.cols,
                      frame.depths);
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
