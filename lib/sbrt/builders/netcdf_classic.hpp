/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The length a classic netCDF file (CDF-1, CDF-2, CDF-5) must
 *            have by its header, read as untrusted bytes: the netCDF
 *            library gives zeros for what a truncated file lacks
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_NETCDF_CLASSIC_HPP
#define SBRT_NETCDF_CLASSIC_HPP

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace sbrt {

/// \brief What the header of a classic netCDF file declares.
struct ClassicLayout {
    int version = 0;           ///< 1 (classic), 2 (64-bit offset), 5 (64-bit data)
    uint64_t header_bytes = 0; ///< where the header ends
    uint64_t numrecs = 0;      ///< records (streaming: as many as the file holds)
    bool streaming = false;    ///< numrecs not written (0xFF...)
    /// The length the file needs for the data of every variable (at least
    /// header_bytes); UINT64_MAX where that overflows 64 bits.
    uint64_t declared_bytes = 0;
    std::string last_variable; ///< the variable whose data ends last
};

/// Whether `data` starts with the magic of a classic netCDF file
/// ("CDF" and version 1, 2 or 5).
bool is_classic_netcdf(const uint8_t *data, size_t size);

/// \brief Parses the header of a classic netCDF file from its first `size`
/// bytes (the file has `file_bytes`), as the netCDF classic format
/// specification defines it, every count and length checked against the
/// bytes there are. Returns nothing when the header goes on past `size`
/// bytes while the file is longer (read more and call again). Throws
/// sbrt::Error for a malformed header and for a file that ends inside its
/// header.
std::optional<ClassicLayout> read_classic_layout(const uint8_t *data, size_t size,
                                                 uint64_t file_bytes);

/// Throws sbrt::Error ("`what`: file is truncated: header declares N bytes,
/// file has M; ...") when the file is shorter than its header declares.
void check_classic_length(const ClassicLayout &layout, uint64_t file_bytes,
                          const std::string &what);

} // namespace sbrt

#endif
