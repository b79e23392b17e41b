/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A file's CRS against the current location's
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_FILE_CRS_HPP
#define R3_SBRT_FILE_CRS_HPP

#include <string>

#include "file_variable.hpp"

/// A fatal error when the file names a CRS other than the location's
/// (a warning with `override_check`); a file without one passes.
void check_file_crs(const FileVariable &variable, const std::string &file,
                    bool override_check);

/// The datum of the file's heights where its CRS is compound, named as
/// geologists write it ("NAP" for EPSG:7415's "NAP height"); empty where
/// the file names no vertical CRS.
std::string vertical_datum(const FileVariable &variable);

#endif
