/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A file's bytes and the machine's memory, read for the
 *            library's checks (lib/sbrt/builders/netcdf_classic,
 *            import_memory)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "file_checks.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <vector>

#include "builders/netcdf_classic.hpp"
#include "util/error.hpp"

namespace {

/// A header longer than this is no header this module reads.
constexpr uint64_t MAX_HEADER_BYTES = uint64_t(64) << 20;

/// The first `bytes` of `path` (fewer where it is shorter).
std::vector<uint8_t> prefix_of(const std::string &path, uint64_t bytes)
{
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> data(bytes);
    in.read(reinterpret_cast<char *>(data.data()), std::streamsize(bytes));
    data.resize(size_t(std::max<std::streamsize>(in.gcount(), 0)));
    return data;
}

} // namespace

void check_classic_netcdf(const std::string &path)
{
    struct stat st;
    if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        return; // GDAL says what is wrong (a Zarr directory is fine)
    const uint64_t file_bytes = uint64_t(st.st_size);
    const std::string what = "file <" + path + ">";
    for (uint64_t bytes = 1 << 20;; bytes *= 8) {
        const std::vector<uint8_t> head = prefix_of(path, std::min(bytes, file_bytes));
        if (!sbrt::is_classic_netcdf(head.data(), head.size()))
            return;
        if (head.size() < std::min(bytes, file_bytes))
            sbrt::fail(what, ": cannot be read (", head.size(), " of ", file_bytes,
                       " bytes)");
        try {
            if (const auto layout =
                    sbrt::read_classic_layout(head.data(), head.size(), file_bytes)) {
                sbrt::check_classic_length(*layout, file_bytes, what);
                return;
            }
        }
        catch (const sbrt::Error &e) {
            sbrt::fail(what, " cannot be read as a multidimensional file: it is "
                             "a damaged classic netCDF file (",
                       e.what(), ")");
        }
        if (bytes >= MAX_HEADER_BYTES)
            sbrt::fail(what, ": its netCDF header goes on past ", MAX_HEADER_BYTES >> 20,
                       " MiB; no netCDF file this module reads has one that long");
    }
}
