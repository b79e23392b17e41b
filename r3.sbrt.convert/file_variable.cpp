/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A file variable through GDAL's multidimensional API
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "file_variable.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>

#include "builders/cf_attributes.hpp"
#include "builders/flag_legend.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

void GdalDatasetCloser::operator()(GDALDataset *dataset) const
{
    GDALClose(GDALDataset::ToHandle(dataset));
}

namespace {

/// GDAL's messages are caught, not printed: what went wrong becomes part
/// of our own error (last_message()).
class QuietGdalErrors {
public:
    QuietGdalErrors()
    {
        CPLPushErrorHandler(CPLQuietErrorHandler);
        CPLErrorReset();
    }
    ~QuietGdalErrors() { CPLPopErrorHandler(); }
    QuietGdalErrors(const QuietGdalErrors &) = delete;
    QuietGdalErrors &operator=(const QuietGdalErrors &) = delete;

    static std::string last_message()
    {
        const char *m = CPLGetLastErrorMsg();
        return m && *m ? std::string(" (GDAL: ") + m + ")" : std::string();
    }
};

GdalDatasetPtr open_multidim(const std::string &path)
{
    GDALAllRegister();
    QuietGdalErrors quiet;
    GdalDatasetPtr dataset(
        GDALDataset::Open(path.c_str(), GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY));
    if (!dataset)
        sbrt::fail("file <", path, "> cannot be read as a multidimensional "
                   "file (NetCDF, HDF5, Zarr)", QuietGdalErrors::last_message(),
                   "; check that it exists, is complete and is not a plain raster "
                   "(import those with r.in.gdal)");
    if (!dataset->GetRootGroup())
        sbrt::fail("file <", path, "> has no multidimensional content");
    return dataset;
}

/// GDAL's name of a numeric type; "String" or "Compound" otherwise.
std::string type_name_of(const GDALExtendedDataType &type)
{
    if (type.GetClass() != GEDTC_NUMERIC)
        return type.GetClass() == GEDTC_STRING ? "String" : "Compound";
    return GDALGetDataTypeName(type.GetNumericDataType());
}

/// A text attribute as valid UTF-8 (labels, units and names enter here:
/// a file's bytes are not trusted to be text); "" where absent.
std::string string_attribute(const GDALIHasAttribute &holder, const char *key)
{
    const auto a = holder.GetAttribute(key);
    if (!a || a->GetDataType().GetClass() != GEDTC_STRING)
        return {};
    const char *s = a->ReadAsString();
    return s ? sbrt::valid_utf8(s) : "";
}

std::vector<double> numeric_attribute(const GDALIHasAttribute &holder,
                                      const char *key)
{
    const auto a = holder.GetAttribute(key);
    if (!a || a->GetDataType().GetClass() != GEDTC_NUMERIC)
        return {};
    return a->ReadAsDoubleArray();
}

/// An attribute as the file has it: numbers, text or something else.
sbrt::FileAttribute file_attribute(const GDALIHasAttribute &holder, const char *key)
{
    sbrt::FileAttribute out;
    QuietGdalErrors quiet;
    const auto a = holder.GetAttribute(key);
    if (!a)
        return out;
    out.present = true;
    const GDALExtendedDataType &type = a->GetDataType();
    if (type.GetClass() == GEDTC_NUMERIC &&
        !GDALDataTypeIsComplex(type.GetNumericDataType())) {
        out.numeric = true;
        out.values = a->ReadAsDoubleArray();
    }
    else if (type.GetClass() == GEDTC_STRING) {
        const char *s = a->ReadAsString();
        out.text = s ? s : "";
    }
    return out;
}

/// scale_factor or add_offset: the attribute's one value, checked; else
/// the driver's (`has`: whether there is one), which must be finite (and
/// a scale not 0); `none` where there is neither.
double packing_value(const GDALIHasAttribute &holder, const char *key, double driver,
                     bool &has, double none, const std::string &where,
                     const std::string &variable, const std::string &path)
{
    // the key held by a named string: GCC 14's -Wdangling-reference takes
    // a reference found from a temporary for one into it
    const std::string key_name = key;
    const sbrt::AttributeRule &rule = sbrt::attribute_rule(key_name);
    const sbrt::FileAttribute attribute = file_attribute(holder, key);
    if (attribute.present) {
        has = true;
        return sbrt::checked_numbers(attribute, rule, where, variable, path)[0];
    }
    if (!has)
        return none;
    sbrt::FileAttribute as_read;
    as_read.present = as_read.numeric = true;
    as_read.values = {driver};
    return sbrt::checked_numbers(as_read, rule, where, variable, path)[0];
}

/// Every array below `group`, by full name, in the file's order.
void collect_arrays(const std::shared_ptr<GDALGroup> &group,
                    std::vector<std::shared_ptr<GDALMDArray>> &out)
{
    for (const std::string &name : group->GetMDArrayNames())
        if (auto array = group->OpenMDArray(name))
            out.push_back(array);
    for (const std::string &name : group->GetGroupNames())
        if (auto sub = group->OpenGroup(name))
            collect_arrays(sub, out);
}

std::string names_of(const std::vector<std::shared_ptr<GDALMDArray>> &arrays)
{
    std::string s;
    for (const auto &a : arrays)
        if (a->GetDimensionCount() > 0)
            s += (s.empty() ? "" : ", ") + a->GetFullName();
    return s.empty() ? "none" : s;
}

std::shared_ptr<GDALMDArray> find_array(GDALDataset &dataset,
                                        const std::string &path,
                                        const std::string &name)
{
    std::vector<std::shared_ptr<GDALMDArray>> arrays;
    collect_arrays(dataset.GetRootGroup(), arrays);
    for (const auto &a : arrays)
        if (a->GetFullName() == name || a->GetName() == name)
            return a;
    sbrt::fail("file <", path, "> has no variable '", name,
               "'; its variables: ", names_of(arrays),
               " (r3.sbrt.convert -p file=", path, " lists them)");
}

sbrt::AxisClues clues_of(const GDALDimension &dim)
{
    sbrt::AxisClues c;
    c.name = dim.GetName();
    if (const auto coords = dim.GetIndexingVariable()) {
        c.axis = string_attribute(*coords, "axis");
        c.standard_name = string_attribute(*coords, "standard_name");
        c.positive = string_attribute(*coords, "positive");
        c.units = string_attribute(*coords, "units");
    }
    if (c.axis.empty()) {
        // GDAL's own reading of the CF conventions where the file has none
        if (dim.GetType() == GDAL_DIM_TYPE_HORIZONTAL_X)
            c.axis = "X";
        else if (dim.GetType() == GDAL_DIM_TYPE_HORIZONTAL_Y)
            c.axis = "Y";
        else if (dim.GetType() == GDAL_DIM_TYPE_VERTICAL)
            c.axis = "Z";
    }
    return c;
}

std::vector<double> coordinates_of(const GDALDimension &dim,
                                   const std::string &what)
{
    const auto coords = dim.GetIndexingVariable();
    if (!coords || coords->GetDimensionCount() != 1)
        sbrt::fail(what, ": has no coordinate variable, so the positions of "
                         "its cells are unknown; add one (CF: a 1D variable of "
                         "the dimension's name holding the cell centres)");
    std::vector<double> values(size_t(dim.GetSize()));
    if (values.empty())
        return values;
    QuietGdalErrors quiet;
    const GUInt64 start = 0;
    const size_t count = values.size();
    if (!coords->Read(&start, &count, nullptr, nullptr,
                      GDALExtendedDataType::Create(GDT_Float64), values.data()))
        sbrt::fail(what, ": its coordinates cannot be read",
                   QuietGdalErrors::last_message());
    return values;
}

/// GDAL's type of each sample type band decoding takes.
struct GdalSample {
    GDALDataType gdal;
    sbrt::SampleType sample;
};
constexpr GdalSample SAMPLE_TYPES[] = {
    {GDT_Byte, sbrt::SampleType::uint8},
#if GDAL_VERSION_NUM >= 3070000
    {GDT_Int8, sbrt::SampleType::int8},
#endif
    {GDT_Int16, sbrt::SampleType::int16},
    {GDT_UInt16, sbrt::SampleType::uint16},
    {GDT_Int32, sbrt::SampleType::int32},
    {GDT_UInt32, sbrt::SampleType::uint32},
    {GDT_Float32, sbrt::SampleType::float32},
    {GDT_Float64, sbrt::SampleType::float64},
};

GDALDataType gdal_type(sbrt::SampleType sample)
{
    for (const GdalSample &t : SAMPLE_TYPES)
        if (t.sample == sample)
            return t.gdal;
    return GDT_Float64;
}

std::shared_ptr<OGRSpatialReference> srs_from_text(const std::string &text)
{
    if (text.empty())
        return nullptr;
    auto srs = std::make_shared<OGRSpatialReference>();
    srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (srs->SetFromUserInput(text.c_str()) != OGRERR_NONE)
        return nullptr;
    return srs;
}

std::shared_ptr<OGRSpatialReference> srs_from_attributes(const GDALIHasAttribute &h)
{
    for (const char *key : {"spatial_ref", "crs_wkt", "epsg_code", "crs", "epsg"}) {
        std::string text = string_attribute(h, key);
        const std::vector<double> code = numeric_attribute(h, key);
        if (text.empty() && code.size() == 1)
            text = "EPSG:" + std::to_string(int(code[0]));
        else if (!text.empty() && text.find_first_not_of("0123456789") ==
                                      std::string::npos)
            text = "EPSG:" + text;
        if (auto srs = srs_from_text(text))
            return srs;
    }
    return nullptr;
}

} // namespace

std::vector<VariableSummary> list_file_variables(const std::string &path)
{
    const GdalDatasetPtr dataset = open_multidim(path);
    std::vector<std::shared_ptr<GDALMDArray>> arrays;
    collect_arrays(dataset->GetRootGroup(), arrays);
    std::vector<VariableSummary> out;
    for (const auto &a : arrays) {
        if (a->GetDimensionCount() == 0)
            continue;
        VariableSummary v;
        v.name = a->GetFullName();
        if (v.name.size() > 1 && v.name[0] == '/' &&
            v.name.find('/', 1) == std::string::npos)
            v.name.erase(0, 1); // plain names for variables of the root
        v.type = type_name_of(a->GetDataType());
        for (const auto &d : a->GetDimensions()) {
            v.dimensions.push_back(d->GetName());
            v.sizes.push_back(d->GetSize());
        }
        v.long_name = string_attribute(*a, "long_name");
        v.units = string_attribute(*a, "units");
        out.push_back(v);
    }
    return out;
}

FileVariable::FileVariable(const std::string &path, const std::string &name,
                           const SizeCheck &before_reading, bool packed_allowed)
    : path_(path), name_(name), dataset_(open_multidim(path))
{
    array_ = find_array(*dataset_, path, name);
    const std::string where = "variable '" + name + "' of <" + path + ">";
    const GDALExtendedDataType &type = array_->GetDataType();
    if (type.GetClass() != GEDTC_NUMERIC ||
        GDALDataTypeIsComplex(type.GetNumericDataType()))
        sbrt::fail(where, " is not numeric (", type_name(), ")");
    // packing: the file's own attributes, checked (GDAL takes the first of
    // several values and skips text), else what the driver reads (Zarr)
    bool has_scale = false, has_offset = false;
    scale_ = packing_value(*array_, "scale_factor", array_->GetScale(&has_scale),
                           has_scale, 1, where, base_name(), path);
    offset_ = packing_value(*array_, "add_offset", array_->GetOffset(&has_offset),
                            has_offset, 0, where, base_name(), path);
    if ((has_scale || has_offset) && !packed_allowed)
        sbrt::fail(where, " is packed (scale_factor/add_offset); unpack it "
                          "first, e.g. ncpdq -U");

    for (const GdalSample &t : SAMPLE_TYPES)
        if (t.gdal == type.GetNumericDataType())
            grid_.sample = t.sample;
    // GDAL's netCDF driver gives signed bytes as Byte with this hint
    if (type.GetNumericDataType() == GDT_Byte &&
        string_attribute(*array_, "_Unsigned") == "false")
        grid_.sample = sbrt::SampleType::float64;

    const auto &dims = array_->GetDimensions();
    std::string dim_list;
    for (const auto &d : dims)
        dim_list += (dim_list.empty() ? "" : ", ") + d->GetName() + "=" +
                    std::to_string(d->GetSize());
    if (dims.size() < 3)
        sbrt::fail(where, " has ", dims.size(), " dimension",
                   dims.size() == 1 ? "" : "s", " (", dim_list,
                   "): an SBRT needs a 3D variable (easting, northing, "
                   "vertical); import 2D grids with r.in.gdal");
    bool found[3] = {false, false, false};
    bool negate_vertical = false;
    for (size_t i = 0; i < dims.size(); ++i) {
        const GDALDimension &d = *dims[i];
        if (d.GetSize() == 0)
            sbrt::fail(where, ": dimension '", d.GetName(), "' has length 0");
        const sbrt::AxisClues clues = clues_of(d);
        const sbrt::AxisRole role = sbrt::axis_role(clues);
        if (role == sbrt::AxisRole::other) {
            if (d.GetSize() == 1)
                continue; // e.g. a single time step
            sbrt::fail(where, ": dimension '", d.GetName(), "' (length ",
                       d.GetSize(), ") is neither easting, northing nor "
                       "vertical; give its coordinate variable a CF 'axis' "
                       "attribute (X, Y or Z), or extract one of its steps "
                       "first");
        }
        const int axis = int(role);
        if (found[axis])
            sbrt::fail(where, ": two dimensions are ", sbrt::role_name(role),
                       " ('", dims[dim_of_axis_[axis]]->GetName(), "' and '",
                       d.GetName(), "'); give them CF 'axis' attributes");
        found[axis] = true;
        dim_of_axis_[axis] = i;
        if (role == sbrt::AxisRole::vertical)
            negate_vertical = sbrt::positive_down(clues);
    }
    for (int axis = 0; axis < 3; ++axis)
        if (!found[axis])
            sbrt::fail(where, " (", dim_list, ") has no ",
                       sbrt::role_name(sbrt::AxisRole(axis)),
                       " dimension; give its coordinate variable a CF 'axis' "
                       "attribute (X, Y or Z)");
    if (before_reading) {
        sbrt::ImportGrid size;
        size.cols = dims[dim_of_axis_[0]]->GetSize();
        size.rows = dims[dim_of_axis_[1]]->GetSize();
        size.depths = dims[dim_of_axis_[2]]->GetSize();
        size.sample_bytes = sbrt::sample_bytes(grid_.sample);
        before_reading(size, where);
    }
    for (int axis = 0; axis < 3; ++axis) {
        const GDALDimension &d = *dims[dim_of_axis_[axis]];
        const std::string what = where + ", dimension '" + d.GetName() + "'";
        sbrt::RegularAxis &target = axis == 0   ? grid_.easting
                                    : axis == 1 ? grid_.northing
                                                : grid_.vertical;
        target = sbrt::regular_axis(
            coordinates_of(d, what),
            axis == int(sbrt::AxisRole::vertical) && negate_vertical, what);
    }

    read_missing_values(where);
}

void FileVariable::read_missing_values(const std::string &where)
{
    auto numbers = [&](const char *key) {
        return sbrt::checked_numbers(file_attribute(*array_, key),
                                     sbrt::attribute_rule(key), where, base_name(),
                                     path_);
    };
    const std::vector<double> fill = numbers("_FillValue");
    bool has_fill = false;
    const double driver_fill = array_->GetNoDataValueAsDouble(&has_fill);
    if (!fill.empty())
        grid_.missing.exact.push_back(fill[0]);
    else if (has_fill) {
        // a fill the driver knows without the attribute (HDF5's own)
        if (std::isinf(driver_fill))
            sbrt::fail(where, ": its fill value is ", driver_fill,
                       "; give it a finite _FillValue attribute");
        grid_.missing.exact.push_back(driver_fill);
    }
    for (double v : numbers("missing_value"))
        grid_.missing.exact.push_back(v);
    const std::vector<double> range = numbers("valid_range");
    if (range.size() == 2) {
        if (range[0] > range[1])
            sbrt::fail(where, ": attribute valid_range runs from ", range[0], " down to ",
                       range[1], "; give the lowest valid value first");
        grid_.missing.valid_min = range[0];
        grid_.missing.valid_max = range[1];
    }
    const std::vector<double> vmin = numbers("valid_min");
    const std::vector<double> vmax = numbers("valid_max");
    if (vmin.size() == 1)
        grid_.missing.valid_min = vmin[0];
    if (vmax.size() == 1)
        grid_.missing.valid_max = vmax[0];
}

FileVariable::~FileVariable() = default;

std::string FileVariable::type_name() const
{
    return type_name_of(array_->GetDataType());
}

bool FileVariable::is_integer() const
{
    const GDALDataType t = array_->GetDataType().GetNumericDataType();
    return GDALDataTypeIsInteger(t) && !GDALDataTypeIsComplex(t);
}

sbrt::Frame FileVariable::frame() const
{
    sbrt::Frame f;
    f.west = easting().low_edge;
    f.east = easting().high_edge;
    f.south = northing().low_edge;
    f.north = northing().high_edge;
    f.bottom = vertical().low_edge;
    f.top = vertical().high_edge;
    f.cols = int(easting().size);
    f.rows = int(northing().size);
    f.depths = int(vertical().size);
    return f;
}

std::vector<std::pair<std::string, std::string>> FileVariable::global_attributes() const
{
    std::vector<std::pair<std::string, std::string>> out;
    const auto root = dataset_->GetRootGroup();
    if (!root)
        return out;
    for (const auto &a : root->GetAttributes())
        if (a && a->GetDataType().GetClass() == GEDTC_STRING) {
            const char *value = a->ReadAsString();
            out.emplace_back(sbrt::valid_utf8(a->GetName()),
                             value ? sbrt::valid_utf8(value) : "");
        }
    return out;
}

std::string FileVariable::base_name() const
{
    const std::string full = array_->GetName();
    const auto slash = full.find_last_of('/');
    return slash == std::string::npos ? full : full.substr(slash + 1);
}

std::string FileVariable::long_name() const
{
    return string_attribute(*array_, "long_name");
}

std::string FileVariable::units() const
{
    return string_attribute(*array_, "units");
}

std::vector<sbrt::Material> FileVariable::flag_labels() const
{
    return sbrt::flag_legend(numeric_attribute(*array_, "flag_values"),
                             string_attribute(*array_, "flag_meanings"));
}

std::shared_ptr<OGRSpatialReference> FileVariable::spatial_ref() const
{
    QuietGdalErrors quiet;
    if (auto srs = array_->GetSpatialRef())
        return std::make_shared<OGRSpatialReference>(*srs);
    // a grid mapping variable GDAL did not take, or attributes of the
    // variable, of a variable named crs or spatial_ref, of its coordinate
    // variables, or of the file
    const auto root = dataset_->GetRootGroup();
    const std::string mapping = string_attribute(*array_, "grid_mapping");
    for (const std::string &holder : {mapping, std::string("crs"),
                                      std::string("spatial_ref")})
        if (!holder.empty())
            if (const auto var = root->OpenMDArray(holder))
                if (auto srs = srs_from_attributes(*var))
                    return srs;
    if (auto srs = srs_from_attributes(*array_))
        return srs;
    // GeoTOP writes `epsg = "7415"` on its coordinate variables x, y, z
    const auto dims = array_->GetDimensions();
    for (const size_t axis : dim_of_axis_)
        if (const auto coords = dims[axis]->GetIndexingVariable())
            if (auto srs = srs_from_attributes(*coords))
                return srs;
    return srs_from_attributes(*root);
}

size_t FileVariable::band_size(size_t max_bytes, size_t chunk_bytes) const
{
    const size_t row_bytes = easting().size * vertical().size * sample_bytes();
    size_t rows = std::max<size_t>(1, max_bytes / row_bytes);
    const std::vector<GUInt64> blocks = array_->GetBlockSize();
    const size_t chunk = size_t(blocks[dim_of_axis_[1]]);
    if (chunk > 1 && chunk * row_bytes <= chunk_bytes)
        rows = std::max(chunk, rows / chunk * chunk);
    return std::min(rows, northing().size);
}

sbrt::BandStrides FileVariable::read_band(size_t first, size_t count,
                                                  void *values) const
{
    const size_t n = array_->GetDimensionCount();
    std::vector<GUInt64> start(n, 0);
    std::vector<size_t> counts(n, 1);
    counts[dim_of_axis_[0]] = easting().size;
    start[dim_of_axis_[1]] = first;
    counts[dim_of_axis_[1]] = count;
    counts[dim_of_axis_[2]] = vertical().size;
    // the slab's own C order: the last dimension varies fastest
    std::vector<GPtrDiff_t> strides(n, 0);
    size_t stride = 1;
    for (size_t d = n; d-- > 0;) {
        strides[d] = GPtrDiff_t(stride);
        stride *= counts[d];
    }
    QuietGdalErrors quiet;
    if (!array_->Read(start.data(), counts.data(), nullptr, strides.data(),
                      GDALExtendedDataType::Create(gdal_type(grid_.sample)),
                      values))
        sbrt::fail("variable '", name_, "' of <", path_,
                   ">: reading northing indices ", first + 1, "-", first + count,
                   " failed", QuietGdalErrors::last_message(),
                   "; the file may be truncated or damaged");
    return {size_t(strides[dim_of_axis_[0]]), size_t(strides[dim_of_axis_[1]]),
            size_t(strides[dim_of_axis_[2]])};
}
