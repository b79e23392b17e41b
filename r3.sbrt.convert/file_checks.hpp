/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   Checks of a file to import made before GDAL reads its values:
 *            a classic netCDF file's length against its header, and the
 *            memory this process can still have
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_FILE_CHECKS_HPP
#define R3_SBRT_FILE_CHECKS_HPP

#include <string>

/// Throws sbrt::Error when `path` is a classic netCDF file (CDF-1, CDF-2,
/// CDF-5) shorter than its header declares, or whose header is malformed;
/// other files pass (GDAL reads and checks them).
void check_classic_netcdf(const std::string &path);


#endif
