/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   One variable of a multidimensional file (NetCDF, HDF5, Zarr)
 *            read through GDAL's multidimensional API: its axes, missing
 *            values, labels and CRS, and its voxels band by band
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_FILE_VARIABLE_HPP
#define R3_SBRT_FILE_VARIABLE_HPP

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "builders/band_import.hpp"
#include "builders/grid_axes.hpp"
#include "builders/import_memory.hpp"
#include "builders/missing_values.hpp"
#include "model/model.hpp"

class GDALDataset;
class GDALMDArray;
class OGRSpatialReference;

/// Closes a dataset the way GDAL wants (GDALClose).
struct GdalDatasetCloser {
    void operator()(GDALDataset *dataset) const;
};
using GdalDatasetPtr = std::unique_ptr<GDALDataset, GdalDatasetCloser>;

/// \brief A summary line of one variable (for -p on a file).
struct VariableSummary {
    std::string name;     ///< full name, "/group/var" below the root
    std::string type;     ///< GDAL's name of the data type
    std::vector<std::string> dimensions;
    std::vector<uint64_t> sizes;
    std::string long_name;
    std::string units;
};

/// Every array of the file with at least one dimension.
std::vector<VariableSummary> list_file_variables(const std::string &path);

/// \brief A 3D (easting, northing, vertical) variable, checked when opened.
/// Other dimensions are allowed only with length 1. Throws sbrt::Error with
/// what was wrong and what to do.
class FileVariable {
public:
    /// Calls `before_reading` (which may throw) with the variable's size
    /// once its axes are known, before any value (coordinates included)
    /// is read.
    using SizeCheck = std::function<void(const sbrt::ImportGrid &, const std::string &)>;
    /// `packed_allowed`: a variable with scale_factor/add_offset is read
    /// as stored (a property channel keeps them); else it is refused.
    FileVariable(const std::string &path, const std::string &name,
                 const SizeCheck &before_reading = {}, bool packed_allowed = false);
    ~FileVariable();
    FileVariable(const FileVariable &) = delete;
    FileVariable &operator=(const FileVariable &) = delete;

    const std::string &name() const { return name_; }
    std::string type_name() const;
    bool is_integer() const;
    /// The grid of the cell centres: rows north to south, depth 0 bottom.
    sbrt::Frame frame() const;
    const sbrt::RegularAxis &easting() const { return grid_.easting; }
    const sbrt::RegularAxis &northing() const { return grid_.northing; }
    const sbrt::RegularAxis &vertical() const { return grid_.vertical; }
    const sbrt::MissingValues &missing() const { return grid_.missing; }
    /// Axes, missing values and sample type, as band decoding takes them.
    const sbrt::BandGrid &band_grid() const { return grid_; }
    /// Labels by value from `flag_values` and `flag_meanings` ('_' -> ' ');
    /// throws sbrt::Error when they do not pair (sbrt::flag_legend).
    std::vector<sbrt::Material> flag_labels() const;
    /// The file's global string attributes (title, institution, source,
    /// ...): what a survey's file says about itself.
    std::vector<std::pair<std::string, std::string>> global_attributes() const;
    /// The variable's own name, without its group ("lithok").
    std::string base_name() const;
    /// CF attributes: long_name, units ("" where absent), scale_factor
    /// and add_offset (1 and 0 where absent).
    std::string long_name() const;
    std::string units() const;
    double scale() const { return scale_; }
    double offset() const { return offset_; }
    /// The file's CRS (grid mapping, or `crs`/`spatial_ref`/`epsg`
    /// attributes of the variable, a crs variable, the coordinate
    /// variables or the file); nullptr when the file names none. May be a
    /// compound CRS (GeoTOP's EPSG:7415, RD New + NAP height).
    std::shared_ptr<OGRSpatialReference> spatial_ref() const;

    /// Northing index count per read that keeps a band near `max_bytes`,
    /// a multiple of the file's chunk where a chunk's rows take at most
    /// `chunk_bytes` (a chunk cut by two bands is decompressed twice).
    size_t band_size(size_t max_bytes, size_t chunk_bytes) const;
    /// The type values are read in: the file's own where listed (GDAL then
    /// copies without converting), else float64.
    sbrt::SampleType sample() const { return grid_.sample; }
    /// Bytes of one value read.
    size_t sample_bytes() const { return sbrt::sample_bytes(grid_.sample); }
    /// Reads northing indices [first, first + count) as sample() values
    /// into `values` in the file's own index order; returns where each
    /// index steps.
    sbrt::BandStrides read_band(size_t first, size_t count, void *values) const;

private:
    /// _FillValue, missing_value and the valid range, each checked.
    void read_missing_values(const std::string &where);

    std::string path_, name_;
    GdalDatasetPtr dataset_;
    std::shared_ptr<GDALMDArray> array_;
    size_t dim_of_axis_[3] = {0, 0, 0}; ///< array dimension of each axis
    sbrt::BandGrid grid_;
    double scale_ = 1, offset_ = 0;
};

#endif
