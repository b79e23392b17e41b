/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   Slice reader of 3D raster maps
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "raster3d_slices.hpp"

#include <cmath>

namespace {

bool same_region(const RASTER3D_Region &a, const RASTER3D_Region &b)
{
    auto close = [](double x, double y, double res) {
        return std::fabs(x - y) <= 1e-9 * std::max(1.0, std::fabs(res));
    };
    return a.rows == b.rows && a.cols == b.cols && a.depths == b.depths &&
           close(a.north, b.north, a.ns_res) &&
           close(a.south, b.south, a.ns_res) &&
           close(a.east, b.east, a.ew_res) &&
           close(a.west, b.west, a.ew_res) &&
           close(a.top, b.top, a.tb_res) &&
           close(a.bottom, b.bottom, a.tb_res);
}

} // namespace

Raster3dSlices::Raster3dSlices(const char *name, const char *mapset,
                               RASTER3D_Region window)
    : window_(window), name_(name)
{
    RASTER3D_Region native;
    Rast3d_read_region_map(name, mapset, &native);
    tiles_ = same_region(native, window_);
    if (tiles_) {
        // no cache: Rast3d_get_block then copies whole tiles
        map_ = static_cast<RASTER3D_Map *>(Rast3d_open_cell_old(
            name, mapset, &native, RASTER3D_TILE_SAME_AS_FILE,
            RASTER3D_NO_CACHE));
    }
    else {
        map_ = static_cast<RASTER3D_Map *>(
            Rast3d_open_cell_old(name, mapset, &window_, DCELL_TYPE,
                                 RASTER3D_USE_CACHE_XY));
    }
    if (!map_)
        G_fatal_error(_("Unable to open 3D raster map <%s>"), name);
    slice_.resize(size_t(window_.rows) * window_.cols);
    if (tiles_) {
        int tx, ty, tz;
        Rast3d_get_tile_dimensions_map(map_, &tx, &ty, &tz);
        type_ = Rast3d_tile_type_map(map_);
        slab_depths_ = std::max(1, tz);
        slab_.resize(slice_.size() * slab_depths_ *
                     (type_ == FCELL_TYPE ? sizeof(FCELL) : sizeof(DCELL)));
    }
}

Raster3dSlices::~Raster3dSlices()
{
    if (map_)
        Rast3d_close(map_);
}

void Raster3dSlices::read_slab(int first_depth)
{
    const int depths = std::min(slab_depths_, window_.depths - first_depth);
    Rast3d_get_block(map_, 0, 0, first_depth, window_.cols, window_.rows,
                     depths, slab_.data(), type_);
    slab_first_ = first_depth;
}

const double *Raster3dSlices::read(int depth)
{
    const size_t cells = slice_.size();
    if (!tiles_) {
        for (int row = 0; row < window_.rows; ++row)
            for (int col = 0; col < window_.cols; ++col) {
                DCELL v;
                Rast3d_get_value(map_, col, row, depth, &v, DCELL_TYPE);
                slice_[size_t(row) * window_.cols + col] =
                    Rast3d_is_null_value_num(&v, DCELL_TYPE) ? NAN : v;
            }
        return slice_.data();
    }
    if (slab_first_ < 0 || depth >= slab_first_ + slab_depths_)
        read_slab(depth - depth % slab_depths_);
    const size_t at = size_t(depth - slab_first_) * cells;
    // GRASS 3D nulls are NaN bit patterns in both FCELL and DCELL
    if (type_ == FCELL_TYPE) {
        const FCELL *src = reinterpret_cast<const FCELL *>(slab_.data()) + at;
        for (size_t i = 0; i < cells; ++i)
            slice_[i] = double(src[i]);
    }
    else {
        const DCELL *src = reinterpret_cast<const DCELL *>(slab_.data()) + at;
        for (size_t i = 0; i < cells; ++i)
            slice_[i] = src[i];
    }
    return slice_.data();
}
