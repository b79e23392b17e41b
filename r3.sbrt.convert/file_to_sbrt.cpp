/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A variable of a multidimensional file (NetCDF, HDF5, Zarr)
 *            -> SBRT, streamed band by band of rows; -p on a file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include <algorithm>
#include <future>
#include <type_traits>

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

/// Value -> class of one band's type. 8- and 16-bit integers without rules
/// are classes as they are, looked up in a table that has the missing
/// values already; everything else goes through the classifier (range
/// checks, rules).
template <typename T>
class BandClasses {
public:
    BandClasses(const sbrt::MissingValues &missing, sbrt::Classifier &classifier)
        : missing_(missing), classifier_(classifier)
    {
        if constexpr (TABLED) {
            if (classifier.has_rules())
                return;
            table_.resize(size_t(1) << (8 * sizeof(T)));
            for (size_t u = 0; u < table_.size(); ++u) {
                const T value = T(u);
                table_[u] = missing.is_missing(double(value)) ? sbrt::NULL_CLASS
                                                              : int32_t(value);
            }
        }
    }

    int32_t operator()(T value)
    {
        if constexpr (TABLED) {
            if (!table_.empty())
                return table_[std::make_unsigned_t<T>(value)];
        }
        const double v = double(value);
        return missing_.is_missing(v) ? sbrt::NULL_CLASS : classifier_.classify(v);
    }

private:
    static constexpr bool TABLED = std::is_integral_v<T> && sizeof(T) <= 2;
    const sbrt::MissingValues &missing_;
    sbrt::Classifier &classifier_;
    std::vector<int32_t> table_;
};

/// \brief Bands of a file variable into a ColumnStackBuilder: rows north
/// to south, columns west to east, depths bottom up, whatever the order of
/// the file's indices.
class BandImport {
public:
    BandImport(const FileVariable &variable, sbrt::Classifier &classifier,
               sbrt::ColumnStackBuilder &builder)
        : variable_(variable), classifier_(classifier), builder_(builder)
    {
    }

    /// Rows [row0, row0 + rows) of a band, read as variable.sample(),
    /// whose first northing index is `first`.
    void add(const void *values, const FileVariable::BandStrides &step,
             size_t row0, size_t rows, size_t first)
    {
        using Sample = FileVariable::Sample;
        auto as = [&](auto *type) {
            using T = std::remove_pointer_t<decltype(type)>;
            add_typed(static_cast<const T *>(values), step, row0, rows, first);
        };
        switch (variable_.sample()) {
        case Sample::int8:
            return as(static_cast<int8_t *>(nullptr));
        case Sample::uint8:
            return as(static_cast<uint8_t *>(nullptr));
        case Sample::int16:
            return as(static_cast<int16_t *>(nullptr));
        case Sample::uint16:
            return as(static_cast<uint16_t *>(nullptr));
        case Sample::int32:
            return as(static_cast<int32_t *>(nullptr));
        case Sample::uint32:
            return as(static_cast<uint32_t *>(nullptr));
        case Sample::float32:
            return as(static_cast<float *>(nullptr));
        case Sample::float64:
            return as(static_cast<double *>(nullptr));
        }
    }

    /// Voxels with a value no rule covered (they became empty).
    uint64_t unmatched() const { return unmatched_; }

private:
    template <typename T>
    void add_typed(const T *values, const FileVariable::BandStrides &step,
                   size_t row0, size_t rows, size_t first)
    {
        const sbrt::RegularAxis &x = variable_.easting(),
                                &y = variable_.northing(), &z = variable_.vertical();
        const size_t nx = x.size, ny = y.size, nz = z.size;
        const sbrt::MissingValues &missing = variable_.missing();
        BandClasses<T> class_of(missing, classifier_);
        // runs of equal values: a value is classified once per run
        std::vector<sbrt::ColumnStackBuilder::ClassRun> runs;
        runs.reserve(nz);
        const ptrdiff_t dz =
            z.ascending ? ptrdiff_t(step.vertical) : -ptrdiff_t(step.vertical);
        for (size_t row = row0; row < row0 + rows; ++row) {
            const size_t yi = (y.ascending ? ny - 1 - row : row) - first;
            for (size_t col = 0; col < nx; ++col) {
                const size_t xi = x.ascending ? col : nx - 1 - col;
                // index of the bottom voxel; depth d is at bottom + d * dz
                const ptrdiff_t bottom =
                    ptrdiff_t(yi * step.northing + xi * step.easting +
                              (z.ascending ? 0 : (nz - 1) * step.vertical));
                runs.clear();
                size_t d = 0;
                try {
                    while (d < nz) {
                        const T value = values[bottom + ptrdiff_t(d) * dz];
                        size_t top = d + 1;
                        while (top < nz && values[bottom + ptrdiff_t(top) * dz] == value)
                            ++top;
                        const int32_t id = class_of(value);
                        if (id == sbrt::NULL_CLASS && classifier_.has_rules() &&
                            !missing.is_missing(double(value)))
                            unmatched_ += top - d;
                        runs.push_back({id, uint32_t(top)});
                        d = top;
                    }
                }
                catch (const sbrt::Error &e) {
                    sbrt::fail("row ", row + 1, ", column ", col + 1, ", depth ",
                               d + 1, " (from the bottom): ", e.what());
                }
                builder_.add_runs(runs.data(), runs.size());
            }
        }
    }

    const FileVariable &variable_;
    sbrt::Classifier &classifier_;
    sbrt::ColumnStackBuilder &builder_;
    uint64_t unmatched_ = 0;
};

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
    BandImport import(variable, classifier, builder);
    std::future<FileVariable::BandStrides> pending = read(0, buffers[0]);
    for (size_t row0 = 0, b = 0; row0 < ny; row0 += band, b ^= 1) {
        G_percent(row0, ny, 2);
        const FileVariable::BandStrides step = pending.get();
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
