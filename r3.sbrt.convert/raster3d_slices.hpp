/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   Reads a 3D raster map one horizontal slice at a time, bottom up,
 *            in the current 3D region; whole tiles at a time when the region
 *            is the map's own, per-voxel resampling otherwise
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_RASTER3D_SLICES_HPP
#define R3_SBRT_RASTER3D_SLICES_HPP

#include <vector>

#include "grass.hpp"

/// \brief Owns an open 3D raster map; closes it on destruction.
class Raster3dSlices {
public:
    Raster3dSlices(const char *name, const char *mapset,
                   RASTER3D_Region window);
    ~Raster3dSlices();
    Raster3dSlices(const Raster3dSlices &) = delete;
    Raster3dSlices &operator=(const Raster3dSlices &) = delete;

    /// Values of slice `depth` (0 = bottom) as doubles, NaN for null,
    /// row 0 north. Slices must be read in increasing order.
    const double *read(int depth);
    /// True when whole tiles are copied (window == the map's region).
    bool reads_tiles() const { return tiles_; }

private:
    void read_slab(int first_depth);

    RASTER3D_Map *map_ = nullptr;
    RASTER3D_Region window_;
    bool tiles_ = false;
    int type_ = DCELL_TYPE;
    int slab_depths_ = 1;
    int slab_first_ = -1;
    std::vector<unsigned char> slab_;
    std::vector<double> slice_;
    const char *name_;
};

#endif
