/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A variable of a multidimensional file (NetCDF, HDF5, Zarr)
 *            -> SBRT, streamed band by band of rows; -p on a file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include <algorithm>
#include <cmath>
#include <future>

#include "builders/band_import.hpp"
#include "builders/cf_attributes.hpp"
#include "builders/channel_bands.hpp"
#include "builders/column_builder.hpp"
#include "util/error.hpp"
#include "builders/import_memory.hpp"
#include "sbrt_map_writer.hpp"
#include "file_checks.hpp"
#include "util/available_memory.hpp"
#include "file_crs.hpp"
#include "file_variable.hpp"
#include "grass.hpp"
#include "util/safe_text.hpp"
#include "util/unfilled_allocator.hpp"
#include "model/legend_rules.hpp"
#include "model/survey_presets.hpp"

namespace {

/// Larger bands bring nothing but page clearing (16 MiB bands import
/// faster than 300 MiB ones: docs/performance.md).
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

/// Whether two variables have the same cells (axes of the same size,
/// direction and edges).
bool same_axes(const FileVariable &a, const FileVariable &b)
{
    auto same = [](const sbrt::RegularAxis &p, const sbrt::RegularAxis &q) {
        return p.size == q.size && p.ascending == q.ascending &&
               p.low_edge == q.low_edge && p.high_edge == q.high_edge;
    };
    return same(a.easting(), b.easting()) && same(a.northing(), b.northing()) &&
           same(a.vertical(), b.vertical());
}

/// The property variables, opened and checked against the classes' grid.
std::vector<std::unique_ptr<FileVariable>>
open_properties(const char *file, const FileVariable &classes,
                const std::vector<std::string> &names)
{
    std::vector<std::unique_ptr<FileVariable>> out;
    for (const std::string &name : names) {
        if (name == classes.name())
            G_fatal_error(_("properties=%s names the class variable itself"),
                          name.c_str());
        for (const auto &taken : out)
            if (taken->name() == name)
                G_fatal_error(_("properties= names '%s' twice"), name.c_str());
        try {
            out.push_back(std::make_unique<FileVariable>(file, name,
                                                         FileVariable::SizeCheck{}, true));
        }
        catch (const sbrt::Error &e) {
            G_fatal_error(_("Property %s"), e.what());
        }
        const FileVariable &p = *out.back();
        if (!same_axes(p, classes))
            G_fatal_error(_("Property '%s' of <%s> lies on other cells (%zu x %zu x %zu) "
                            "than the classes '%s' (%zu x %zu x %zu): a property "
                            "channel needs one value per voxel of the classes' grid"),
                          name.c_str(), file, p.easting().size, p.northing().size,
                          p.vertical().size, classes.name().c_str(),
                          classes.easting().size, classes.northing().size,
                          classes.vertical().size);
    }
    return out;
}

/// A channel's name and legend from its variable's CF attributes.
sbrt::ChannelInfo channel_info(const FileVariable &v)
{
    sbrt::ChannelInfo c;
    c.name = sbrt::valid_utf8(v.base_name());
    // a file's attributes may be longer than a channel keeps: cut
    c.long_name = sbrt::fit_bytes(v.long_name(), sbrt::MAX_CHANNEL_TEXT);
    c.unit = sbrt::fit_bytes(v.units(), sbrt::MAX_CHANNEL_TEXT);
    c.scale = v.scale();
    c.offset = v.offset();
    // the voxels the missing values mark are stored as the fill, or as NaN
    // where the fill is not exact in float32 (it could be a value)
    if (!v.missing().exact.empty()) {
        const double fill = v.missing().exact[0];
        c.has_fill = true;
        c.fill = double(float(fill)) == fill ? float(fill) : NAN;
    }
    return c;
}

/// A probability or percentage imported as classes gives a class per
/// value (a legend of dozens of "classes"): say how to keep it instead.
void warn_if_probability(const FileVariable &v, const sbrt::Classifier &classifier,
                         size_t classes)
{
    if (classifier.has_rules())
        return; // classes made on purpose
    const std::string why =
        sbrt::probability_hint(v.base_name(), v.long_name(), v.units(), classes);
    if (!why.empty())
        G_warning(_("Variable %s looks like a probability (%s): import it as a "
                    "property channel with properties=%s beside a class variable"),
                  sbrt::printable(v.name()).c_str(), sbrt::printable(why).c_str(),
                  sbrt::printable(v.name()).c_str());
}

/// The kinds (and units, where the file gave none) that the survey's
/// preset gives the property channels (issue 51: GeoTOP delivers its
/// kans_* without units).
void apply_preset_channels(const std::string &survey, std::vector<sbrt::ChannelInfo> &infos)
{
    const sbrt::SurveyPreset &preset = sbrt::find_preset(survey);
    if (sbrt::apply_channel_rules(preset, infos) == 0)
        return;
    std::string kinds;
    for (const sbrt::ChannelInfo &c : infos)
        if (c.kind != sbrt::ChannelKind::unset)
            kinds += (kinds.empty() ? "" : ", ") + sbrt::printable(c.name) + " " +
                     sbrt::channel_kind_name(c.kind) +
                     (c.unit.empty() ? "" : " in " + sbrt::printable(c.unit));
    G_message(_("Preset %s says what the property channels are: %s (change it with "
                "r3.sbrt.support channel= unit= kind=)"),
              preset.name.c_str(), kinds.c_str());
}

} // namespace

std::vector<std::string> same_grid_variables(const char *file, const char *variable)
{
    const FileVariable classes(file, variable);
    std::vector<std::string> names;
    for (const VariableSummary &v : list_file_variables(file)) {
        if (v.dimensions.size() < 3 || v.name == classes.name() ||
            v.name == classes.base_name())
            continue;
        try {
            const FileVariable other(file, v.name, {}, true);
            if (same_axes(other, classes))
                names.push_back(v.name);
        }
        catch (const sbrt::Error &) {
            // not a 3D numeric variable on the classes' grid
        }
    }
    return names;
}

void apply_preset(const std::string &name, sbrt::Model &model)
{
    apply_preset(name, model.materials());
}

void apply_preset(const std::string &name, std::vector<sbrt::Material> &materials)
{
    const sbrt::SurveyPreset &preset = sbrt::find_preset(name);
    const size_t set = sbrt::apply_styles(materials, preset.classes, true);
    G_message(_("Preset %s applied (%s, labels and colours from %s): %zu of %zu "
                "classes; change them with r3.sbrt.support"),
              preset.name.c_str(), preset.title.c_str(), preset.reference.c_str(), set,
              materials.size() - 1);
}

sbrt::Frame file_to_sbrt(const char *file, const char *name, const NewSbrt &output,
                         sbrt::Classifier &classifier, bool override_crs,
                         size_t band_bytes, const char *preset,
                         const std::vector<std::string> &properties,
                         const std::string &channels_file, unsigned threads)
{
    // a classic file's length first: the netCDF library reads what a
    // truncated one lacks as zeros
    check_classic_netcdf(file);
    // every variable's band in the memory given
    const size_t max_band =
        std::min(band_bytes, MAX_BAND_BYTES) / (1 + properties.size());
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
    const std::vector<std::unique_ptr<FileVariable>> props =
        open_properties(file, variable, properties);
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
    // the model written as its rows come: a band of it held, not the model
    sbrt_grass::SbrtMapWriter writer(output.name, output.path, frame, threads);
    sbrt::ColumnStackBuilder builder(frame);
    // bands of whole chunks: a chunk cut by two bands would be decompressed
    // twice (with eleven channels of a national model a band of the
    // memory's share is one row, and every chunk was read 16 times); a
    // chunk's rows of every variable, twice, within 1/8 of the memory
    // available and 256 MB each
    const size_t chunk_bytes = std::max(
        4 * max_band, std::min(size_t(available / (16.0 * double(1 + props.size()))),
                               size_t(256) << 20));
    const size_t band = variable.band_size(max_band, chunk_bytes);
    // the next band is read (one thread) while this one is converted;
    // doubles keep every sample type aligned; the classes' first, then
    // each property's
    std::vector<const FileVariable *> sources = {&variable};
    for (const auto &p : props)
        sources.push_back(p.get());
    std::vector<Buffer> buffers[2];
    for (std::vector<Buffer> &set : buffers)
        for (const FileVariable *v : sources)
            set.emplace_back((band * nx * nz * v->sample_bytes() + 7) / 8);
    // the channels, streamed to a file of the mapset beside the import
    std::unique_ptr<sbrt::FileSink> channel_sink;
    std::unique_ptr<sbrt::ChannelsWriter> channel_writer;
    std::unique_ptr<sbrt::ChannelBands> channel_bands;
    std::vector<sbrt::ColumnSpan> spans;
    if (!props.empty()) {
        std::vector<sbrt::ChannelInfo> infos;
        std::vector<sbrt::BandGrid> grids;
        std::vector<std::string> names;
        for (const auto &p : props) {
            infos.push_back(channel_info(*p));
            grids.push_back(p->band_grid());
            names.push_back(p->name());
        }
        if (survey != "none")
            apply_preset_channels(survey, infos);
        channel_sink = std::make_unique<sbrt::FileSink>(channels_file);
        channel_writer = std::make_unique<sbrt::ChannelsWriter>(
            *channel_sink, frame.rows, frame.cols, sbrt::StacksV2Options{}.block_size,
            infos, threads);
        channel_bands = std::make_unique<sbrt::ChannelBands>(grids, names, *channel_writer);
        G_message(_("With %zu property channels: %s%s"), props.size(),
                  props[0]->name().c_str(), props.size() > 1 ? ", ..." : "");
    }
    // a band's rows and the first northing index they read (the file's
    // northing may run south to north)
    struct Rows {
        size_t count, first;
    };
    auto rows_of = [&](size_t row0) {
        // bands start on the file's chunks: a northing that runs south to
        // north has its first chunk in the south, so the first band (the
        // northmost) takes what is left over
        const size_t lead = y.ascending ? ny % band : 0;
        const size_t count = row0 == 0 && lead ? lead : std::min(band, ny - row0);
        return Rows{count, y.ascending ? ny - row0 - count : row0};
    };
    auto read = [&](size_t row0, std::vector<Buffer> &set) {
        const Rows rows = rows_of(row0);
        return std::async(std::launch::async, [&sources, &set, rows] {
            std::vector<sbrt::BandStrides> steps;
            for (size_t v = 0; v < sources.size(); ++v)
                steps.push_back(sources[v]->read_band(rows.first, rows.count,
                                                      set[v].data()));
            return steps;
        });
    };
    sbrt::BandImport import(variable.band_grid(), classifier, builder);
    if (channel_bands)
        import.record_spans(&spans);
    std::future<std::vector<sbrt::BandStrides>> pending = read(0, buffers[0]);
    for (size_t row0 = 0, b = 0; row0 < ny; row0 += rows_of(row0).count, b ^= 1) {
        G_percent(row0, ny, 1);
        const std::vector<sbrt::BandStrides> steps = pending.get();
        const Rows rows = rows_of(row0);
        if (row0 + rows.count < ny)
            pending = read(row0 + rows.count, buffers[b ^ 1]);
        try {
            import.add(buffers[b][0].data(), steps[0], row0, rows.count, rows.first);
            // the blocks' rows that are whole, compressed now
            const int ready = builder.rows_ready() / writer.block_rows() * writer.block_rows();
            if (ready > 0)
                writer.add_rows(builder.take_rows(ready));
            if (channel_bands) {
                std::vector<const void *> bands;
                for (size_t v = 1; v < sources.size(); ++v)
                    bands.push_back(buffers[b][v].data());
                channel_bands->add(spans, bands,
                                   std::vector<sbrt::BandStrides>(steps.begin() + 1,
                                                                  steps.end()),
                                   row0, rows.count, rows.first);
            }
        }
        catch (const sbrt::Error &e) {
            if (pending.valid())
                pending.wait(); // no read left running past the error
            G_fatal_error(_("Variable '%s' of <%s>, %s"), name, file, e.what());
        }
    }
    G_percent(1, 1, 1);
    if (channel_writer) {
        channel_writer->finish();
        channel_sink->finish();
    }
    if (import.unmatched())
        G_warning(_("%llu voxels matched no rule and became empty"),
                  (unsigned long long)import.unmatched());
    try {
        if (builder.rows_ready() > 0)
            writer.add_rows(builder.take_rows(builder.rows_ready()));
    }
    catch (const sbrt::Error &e) {
        G_fatal_error(_("Variable '%s' of <%s>, %s"), name, file, e.what());
    }
    if (writer.solid_intervals() == 0)
        G_fatal_error(_("Variable '%s' of <%s> holds only missing values"), name,
                      file);
    sbrt::SbrtWriter::Legend result{builder.materials(legend), vertical_datum(variable)};
    warn_if_probability(variable, classifier, result.materials.size() - 1);
    if (survey != "none")
        apply_preset(survey, result.materials);
    if (!result.vertical_datum.empty())
        G_verbose_message(_("Heights of <%s> are relative to %s"), file,
                          result.vertical_datum.c_str());
    writer.finish(result, std::string("file ") + file + " variable " + name, channels_file);
    return frame;
}

void print_file_variables(const char *file, bool shell)
{
    const std::vector<VariableSummary> variables = list_file_variables(file);
    if (!shell)
        fprintf(stdout, "Variables of <%s>:\n", sbrt::printable(file).c_str());
    for (const VariableSummary &v : variables) {
        std::string dims, sizes;
        for (size_t i = 0; i < v.dimensions.size(); ++i) {
            dims += (i ? "," : "") + v.dimensions[i];
            sizes += (i ? "," : "") + std::to_string(v.sizes[i]);
        }
        if (shell)
            fprintf(stdout, "variable=%s\n",
                    sbrt::shell_word(sbrt::record_field(v.name) + "|type=" +
                                     sbrt::record_field(v.type) + "|dimensions=" +
                                     sbrt::record_field(dims) + "|sizes=" + sizes +
                                     "|long_name=" + sbrt::record_field(v.long_name) +
                                     "|units=" + sbrt::record_field(v.units))
                        .c_str());
        else
            fprintf(stdout, "  %-16s %-8s (%s) = (%s)%s%s%s\n",
                    sbrt::printable(v.name).c_str(), sbrt::printable(v.type).c_str(),
                    sbrt::printable(dims).c_str(), sizes.c_str(),
                    v.long_name.empty() ? "" : "  ", sbrt::printable(v.long_name).c_str(),
                    v.units.empty() ? "" : (" [" + sbrt::printable(v.units) + "]").c_str());
    }
}
