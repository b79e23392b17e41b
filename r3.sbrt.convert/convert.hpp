/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   The conversions the module offers, one file each
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_CONVERT_HPP
#define R3_SBRT_CONVERT_HPP

#include <string>
#include <vector>

#include "builders/classifier.hpp"
#include "format/format.hpp"
#include "model/model.hpp"
#include "output_format.hpp"

/// 3D raster (current 3D region) -> SBRT.
sbrt::Model voxels_to_sbrt(const char *input, sbrt::Classifier &classifier);

/// 3D raster maps `properties` (current 3D region) as the property
/// channels of `model` (made from class map `input`), written into the new
/// file `channels_file`.
void raster3d_channels(const std::vector<std::string> &properties, const char *input,
                       const sbrt::Model &model, const std::string &channels_file,
                       unsigned threads);

/// The rules' classes with their labels, as a legend.
std::vector<sbrt::Material> rule_legend(const sbrt::Classifier &classifier);

/// A 3D variable of a NetCDF/HDF5/Zarr file -> SBRT in the file's own grid
/// (the CRS checked against the location's unless `override_crs`), read in
/// bands of about `band_bytes`. `preset` (preset=): "auto" applies the
/// survey preset the file identifies itself as, "none" none, else the
/// preset of that name.
/// `properties` (variables on the same grid) become property channels,
/// streamed into the new file `channels_file` in the same pass. Writes
/// SBRT `output` band by band of rows as they are converted (the model
/// is never held whole: a model larger than memory imports) and returns
/// its frame.
struct NewSbrt {
    const char *name;
    std::string path; ///< sbrt_grass::new_sbrt_path
};
sbrt::Frame file_to_sbrt(const char *file, const char *variable, const NewSbrt &output,
                         sbrt::Classifier &classifier, bool override_crs,
                         size_t band_bytes, const char *preset,
                         const std::vector<std::string> &properties = {},
                         const std::string &channels_file = {}, unsigned threads = 0);

/// The other 3D variables of `file` on the grid of `variable` (-a).
std::vector<std::string> same_grid_variables(const char *file, const char *variable);

/// Applies the survey preset `name` to `model` with a message; classes keep
/// the labels and colours they have (rules=, the file's flag_meanings).
void apply_preset(const std::string &name, sbrt::Model &model);
void apply_preset(const std::string &name, std::vector<sbrt::Material> &materials);

/// Lists the variables of a file (plain or key=value).
void print_file_variables(const char *file, bool shell);

/// Stacked horizon rasters (top to bottom) -> SBRT with continuous heights.
sbrt::Model horizons_to_sbrt(const std::vector<std::string> &horizons,
                             const std::vector<int> &materials,
                             const char *bottom);

/// SBRT -> 3D raster in the current 3D region, with colours and labels.
void sbrt_to_voxels(const char *input, const char *output, unsigned threads);

/// One property channel of an SBRT -> 3D raster in the current 3D region:
/// its values as stored (times scale plus offset where the source packed
/// them), the fill and voxels outside the spans null.
void channel_to_voxels(const char *input, const char *channel, const char *output,
                       unsigned threads);

/// Sets the current region, 2D and 3D (as g.region raster_3d= does), to
/// the grid `frame` of SBRT `name`, in the mapset and in this process.
void set_region_to(const char *name, const sbrt::Frame &frame);

/// Whether two frames have the same grid (counts, and edges within 1e-6
/// of a cell).
bool same_grid(const sbrt::Frame &a, const sbrt::Frame &b);

/// A warning, with both grids and the one-step way to set the region,
/// where the region's 3D grid is not the SBRT's.
void warn_if_other_grid(const char *name, const sbrt::Frame &model,
                        const sbrt::Frame &region);

/// Prints the metadata and Table 1 figures (plain, shell: key=value, or
/// json): the papers' Table 1 figures in memory and the stacks file on
/// disk. With `channels`, the property channels after them.
void print_report(const char *name, const sbrt::Model &model,
                  const sbrt::StacksFileInfo &file, sbrt_grass::OutputFormat format,
                  const sbrt::PropertyChannels *channels = nullptr);
/// print_report's json: -g's keys and the classes and channels.
void print_report_json(const char *name, const sbrt::Model &model,
                       const sbrt::StacksFileInfo &file,
                       const sbrt::PropertyChannels *channels);
/// The variables of a file as a json list (print_file_variables' fields).
void print_file_variables_json(const char *file);
/// -l in json: the SBRTs of the search path, each with name, mapset and
/// fullname as g.list writes them.
void print_sbrt_list_json();

#endif
