/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   Writing the logs of the queried points: plain (a borehole log
 *            per point), json and csv (the same key names in both)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_WHAT_LOG_WRITERS_HPP
#define R3_SBRT_WHAT_LOG_WRITERS_HPP

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "measure/column_log.hpp"
#include "measure/column_voxels.hpp"
#include "what_request.hpp"

/// \brief A queried point and the log of its column; no log where the
/// point lies outside the model. Where the model has property channels,
/// the column's voxels with their values, top down.
struct PointLog {
    QueryPoint point;
    std::optional<sbrt::ColumnLog> log;
    std::vector<sbrt::VoxelValues> voxels;
};

/// \brief What the writers show: the model, the channels whose values
/// the points' voxels hold (none for a model without channels or where
/// they are not asked for), the unit of the heights and whether plain and
/// csv list the voxels (-v).
struct LogSource {
    const sbrt::Model &model;
    std::vector<sbrt::ChannelInfo> channels;
    std::string elevation_unit = "m"; ///< the location's: "m", "ft", "map units"
    bool voxel_rows = false;
    char separator = ','; ///< between csv fields (separator=)
};

/// The model's vertical datum ("NAP"), empty where it has none.
const std::string &vertical_datum(const LogSource &source);
/// The heights' unit with the datum: "m NAP"; "m" without a datum.
std::string elevation_reference(const LogSource &source);
/// The elevation of the point's surface: the top of the highest layer of
/// its column, which every depth is measured from; none outside the
/// model and in an empty column.
std::optional<double> surface_of(const PointLog &point);

/// What a point's column is: "outside" (the model), "empty" (a column
/// without layers) or "ok"; json's and csv's `status`.
const char *point_status(const PointLog &point);

/// A number as json and csv give it (a finite one): 15 significant digits, which keep
/// every decimal the model's float32 heights and the map's coordinates
/// hold without the binary noise of a 17-digit print (2.4, not
/// 2.4000000000000004).
std::string number_text(double value);

/// The class id and label of material `material` of `model`.
const sbrt::Material &material_of(const sbrt::Model &model, uint32_t material);

/// A number as csv gives it: number_text, `none` where it is none (nan,
/// +-inf: no number a reader of the file takes).
std::string value_text(double value, const char *none);

/// A readable log per point: a heading with the heights' unit and datum
/// and the surface, then top to bottom a line per layer (top, bottom,
/// thickness, the depths of top and bottom below the surface, class,
/// label) and per gap between layers; then, with voxel_rows and channels,
/// a line per voxel (top, bottom, class, each channel).
/// Labels and channel names printable: no control character of a model
/// of another mapset reaches the terminal.
void write_plain_logs(FILE *out, const LogSource &source, const std::vector<PointLog> &logs);
/// A json list of points, each with the heights' unit and datum, its
/// surface and its layers (gaps left out) with their depths and, with
/// channels, its voxels ("voxels": top, bottom, level, class, "values").
/// Valid JSON and UTF-8 whatever the model holds: null for a number that
/// is none (nan, +-inf), labels made valid UTF-8 and escaped.
void write_json_logs(FILE *out, const LogSource &source, const std::vector<PointLog> &logs);
/// A csv row per layer (gaps left out), one row for a point outside or an
/// empty column; a header row first. RFC 4180: fields parted by
/// `separator` (a comma unless separator= says otherwise), labels printable and
/// quoted where they hold the separator or a quote; an empty field for a number
/// that is none (nan, +-inf). The depths and the heights' unit and datum
/// follow thickness. With voxel_rows, the column "kind" (layer or voxel)
/// follows and, with channels, "level" and one column per channel, empty
/// on layer rows, and a row per voxel (level set, thickness the voxel's)
/// follows each point's layers.
void write_csv_logs(FILE *out, const LogSource &source, const std::vector<PointLog> &logs);

#endif
