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
#include "builders/import_memory.hpp"
#include "file_checks.hpp"
#include "util/available_memory.hpp"
#include "file_crs.hpp"
#include "file_variable.hpp"
#include "grass.hpp"
#include "util/unfilled_allocator.hpp"
#include "model/legend_rules.hpp"
#include "model/survey_presets.hpp"

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

void apply_preset(const std::string &name, sbrt::Model &model)
{
    const sbrt::SurveyPreset &preset = sbrt::find_preset(name);
    const size_t set = sbrt::apply_styles(model.materials(), preset.classes, true);
    G_message(_("Preset %s applied (%s, labels and colours from %s): %zu of %zu "
                "classes; change them with r3.sbrt.support"),
              preset.name.c_str(), preset.title.c_str(), preset.reference.c_str(), set,
              model.materials().size() - 1);
}

sbrt::Model file_to_sbrt(const char *file, const char *name,
                         sbrt::Classifier &classifier, bool override_crs,
                         size_t band_bytes, const char *preset)
{
    // a classic file's length first: the netCDF library reads what a
    // truncated one lacks as zeros
    check_classic_netcdf(file);
    const size_t max_band = std::min(band_bytes, MAX_BAND_BYTES);
    const double available = sbrt::available_memory();
    double needed = 0;
    const FileVariable variable(
        file, name, [&](const sbrt::ImportGrid &grid, const std::string &where) {
            sbrt::check_import_fits(grid, max_band, available, where);
            needed = sbrt::import_bytes_at_least(grid, max_band);
        });
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
                "%s; at least %.2f GB of memory, %.1f GB available)..."),
              name, file, nx, ny, nz, variable.type_name().c_str(), needed / 1e9,
              available / 1e9);

    // labels before the long part: a warning now, not after the import
    std::vector<sbrt::Material> legend;
    if (classifier.has_rules())
        legend = rule_legend(classifier);
    else {
        try {
            legend = variable.flag_labels();
        }
        catch (const sbrt::Error &e) {
            G_warning(_("Variable '%s' of <%s>: %s. The classes get no labels; "
                        "give rules= with labels, or mend the attributes (e.g. "
                        "ncatted -a flag_meanings,%s,o,c,\"...\")"),
                      name, file, e.what(), name);
        }
    }
    // the survey the file says it is (global title, institution, source)
    std::string survey = preset;
    if (survey == "auto") {
        const sbrt::SurveyPreset *found =
            sbrt::identify_preset(variable.base_name(), variable.global_attributes());
        survey = found ? found->name : "none";
        if (found)
            G_message(_("File <%s> identifies itself as %s (variable '%s'): preset %s "
                        "(preset=none turns this off)"),
                      file, found->title.c_str(), name, found->name.c_str());
    }
    sbrt::ColumnStackBuilder builder(frame);
    const size_t band = variable.band_size(max_band);
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
        G_percent(row0, ny, 1);
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
    sbrt::Model model = builder.finish(legend);
    if (model.stats().solid_intervals == 0)
        G_fatal_error(_("Variable '%s' of <%s> holds only missing values"), name,
                      file);
    if (survey != "none")
        apply_preset(survey, model);
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
