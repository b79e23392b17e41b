/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   properties= of input=: 3D raster maps as property channels of
 *            the SBRT made from a class map (issue 29, item 2), read row
 *            by row over the solid spans of the model's columns in the
 *            current 3D region
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include <cmath>
#include <memory>

#include "format/byte_sink.hpp"
#include "format/channels_file.hpp"
#include "format/format_v2.hpp"
#include "grass.hpp"
#include "model/property_channel.hpp"
#include "util/safe_text.hpp"

namespace {

/// \brief A property map open in the current 3D region (resampled where
/// the map's own grid differs), closed on destruction.
class PropertyMap {
public:
    PropertyMap(const std::string &name, RASTER3D_Region &window) : name_(name)
    {
        const char *mapset = G_find_raster3d(name.c_str(), "");
        if (!mapset)
            G_fatal_error(_("properties=%s: 3D raster map <%s> not found"), name.c_str(),
                          name.c_str());
        // rows are read one after another: a cache of one plane of tiles
        map_ = static_cast<RASTER3D_Map *>(Rast3d_open_cell_old(
            name.c_str(), mapset, &window, DCELL_TYPE, RASTER3D_USE_CACHE_XZ));
        if (!map_)
            G_fatal_error(_("Unable to open 3D raster map <%s>"), name.c_str());
        info_.name = name.substr(0, name.find('@'));
        const char *unit = Rast3d_get_unit(map_);
        info_.unit = unit && std::string(unit) != "none"
                         ? sbrt::fit_bytes(sbrt::valid_utf8(unit), sbrt::MAX_CHANNEL_TEXT)
                         : "";
        // the title (r3.support title=) is kept in the map's history
        struct History history;
        if (Rast3d_read_history(name.c_str(), mapset, &history) >= 0) {
            const char *title = Rast_get_history(&history, HIST_TITLE);
            if (title && std::string(title) != name.substr(0, name.find('@')))
                info_.long_name =
                    sbrt::fit_bytes(sbrt::valid_utf8(title), sbrt::MAX_CHANNEL_TEXT);
            Rast_free_history(&history);
        }
        choose_fill();
    }
    ~PropertyMap() { Rast3d_close(map_); }
    PropertyMap(const PropertyMap &) = delete;
    PropertyMap &operator=(const PropertyMap &) = delete;

    const sbrt::ChannelInfo &info() const { return info_; }

    /// The value at a voxel as the channel stores it: the fill for null;
    /// a value a float32 does not hold exactly, or one equal to the fill
    /// (a range file older than the map), is an error.
    float value(int col, int row, int depth) const
    {
        DCELL v;
        Rast3d_get_value(map_, col, row, depth, &v, DCELL_TYPE);
        if (Rast3d_is_null_value_num(&v, DCELL_TYPE))
            return info_.fill;
        if (std::isinf(v))
            G_fatal_error(_("3D raster map <%s>, row %d, column %d, depth %d: holds "
                            "%s; a channel's values must be finite (views colour them "
                            "by their range): make them null first, e.g. r3.mapcalc "
                            "\"%s_f = if(abs(%s) < 1e30, %s, null())\""),
                          name_.c_str(), row + 1, col + 1, depth + 1,
                          v > 0 ? "Infinity" : "-Infinity", info_.name.c_str(),
                          name_.c_str(), name_.c_str());
        const float f = float(v);
        if (double(f) != v)
            G_fatal_error(_("3D raster map <%s>, row %d, column %d, depth %d: %.17g is "
                            "not exact in a property channel (float32); round the map "
                            "first, e.g. r3.mapcalc \"%s_r = float(%s)\""),
                          name_.c_str(), row + 1, col + 1, depth + 1, v,
                          info_.name.c_str(), name_.c_str());
        if (f == info_.fill)
            G_fatal_error(_("3D raster map <%s> holds %g outside its range file's "
                            "[%g, %g]; rebuild its range (r3.support) and convert again"),
                          name_.c_str(), v, min_, max_);
        return f;
    }

private:
    /// Nulls become a fill just outside the map's range, an integer where
    /// the range is (so integer maps keep the smallest integer type), NaN
    /// where no such value is exact.
    void choose_fill()
    {
        info_.has_fill = true;
        info_.fill = NAN;
        min_ = max_ = NAN;
        if (Rast3d_range_load(map_) != 1)
            return;
        Rast3d_range_min_max(map_, &min_, &max_);
        if (!std::isfinite(min_) || !std::isfinite(max_))
            return;
        const double fill = min_ >= 0 ? std::floor(max_) + 1 : std::floor(min_) - 1;
        if (std::fabs(fill) < 16777216.0) // 2^24: every integer exact in float32
            info_.fill = float(fill);
    }

    std::string name_;
    RASTER3D_Map *map_ = nullptr;
    sbrt::ChannelInfo info_;
    double min_ = NAN, max_ = NAN;
};

} // namespace

void raster3d_channels(const std::vector<std::string> &properties, const char *input,
                       const sbrt::Model &model, const std::string &channels_file,
                       unsigned threads)
{
    RASTER3D_Region window;
    Rast3d_get_window(&window);
    const sbrt::Frame &frame = model.frame();
    std::vector<std::unique_ptr<PropertyMap>> maps;
    std::vector<sbrt::ChannelInfo> infos;
    for (const std::string &name : properties) {
        maps.push_back(std::make_unique<PropertyMap>(name, window));
        for (const sbrt::ChannelInfo &taken : infos)
            if (taken.name == maps.back()->info().name)
                G_fatal_error(_("properties= names '%s' twice"), taken.name.c_str());
        if (maps.back()->info().name == std::string(input).substr(0, std::string(input).find('@')))
            G_fatal_error(_("properties=%s names the class map itself"), name.c_str());
        infos.push_back(maps.back()->info());
    }
    sbrt::FileSink sink(channels_file);
    sbrt::ChannelsWriter writer(sink, frame.rows, frame.cols,
                                sbrt::StacksV2Options{}.block_size, infos, threads);
    G_message(_("Reading %zu property channels (%s%s) over the columns' solid spans..."),
              maps.size(), infos[0].name.c_str(), maps.size() > 1 ? ", ..." : "");
    std::vector<sbrt::ColumnSpan> spans(size_t(frame.cols));
    std::vector<std::vector<float>> values(maps.size());
    for (int row = 0; row < frame.rows; ++row) {
        G_percent(row, frame.rows, 2);
        for (int col = 0; col < frame.cols; ++col)
            spans[size_t(col)] = sbrt::solid_span(model, model.cell_index(row, col));
        std::vector<const float *> rows;
        for (size_t c = 0; c < maps.size(); ++c) {
            std::vector<float> &out = values[c];
            out.clear();
            for (int col = 0; col < frame.cols; ++col)
                for (uint32_t level = spans[size_t(col)].lo; level < spans[size_t(col)].hi;
                     ++level)
                    out.push_back(maps[c]->value(col, row, int(level)));
            rows.push_back(out.data());
        }
        writer.add_row(spans.data(), rows);
    }
    G_percent(1, 1, 1);
    writer.finish();
    sink.finish();
}
