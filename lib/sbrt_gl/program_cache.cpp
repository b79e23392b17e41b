/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Program binaries on disk between runs
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "program_cache.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "format/byte_io.hpp"

namespace sbrt_gl {

namespace {

/// The file: magic, format, byte count, CRC-32 of the bytes, the bytes.
constexpr char MAGIC[8] = {'S', 'B', 'R', 'T', 'P', 'R', 'G', '1'};
constexpr size_t HEADER_BYTES = 8 + 4 + 8 + 4;
/// Larger than any program binary of ours (tens of kilobytes on Mesa).
constexpr uint64_t MAX_FILE_BYTES = 64ull << 20;

/// mkdir -p, each level 0755; false where the directory is not there after.
bool make_directories(const std::string &path)
{
    for (size_t at = 1; at <= path.size(); ++at) {
        if (at < path.size() && path[at] != '/')
            continue;
        const std::string part = path.substr(0, at);
        if (mkdir(part.c_str(), 0755) != 0 && errno != EEXIST)
            return false;
    }
    struct stat info;
    return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

} // namespace

ProgramCache ProgramCache::from_environment()
{
    if (const char *set = std::getenv("SBRT_PROGRAM_CACHE")) {
        const std::string directory = set;
        return ProgramCache(directory == "off" ? std::string() : directory);
    }
    if (const char *xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return ProgramCache(std::string(xdg) + "/r3.sbrt/programs");
    if (const char *home = std::getenv("HOME"); home && *home)
        return ProgramCache(std::string(home) + "/.cache/r3.sbrt/programs");
    return ProgramCache();
}

std::string ProgramCache::key(const std::string &gl_identity,
                              const std::vector<const char *> &sources)
{
    uint64_t hash = 14695981039346656037ull; // FNV-1a
    const auto add = [&](const char *text, size_t size) {
        for (size_t i = 0; i < size; ++i) {
            hash ^= uint8_t(text[i]);
            hash *= 1099511628211ull;
        }
        hash ^= 0xff; // a separator no text holds
        hash *= 1099511628211ull;
    };
    add(gl_identity.data(), gl_identity.size());
    for (const char *source : sources)
        add(source, std::strlen(source));
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

std::string ProgramCache::path_of(const std::string &key) const
{
    return directory_ + "/" + key + ".bin";
}

std::optional<ProgramBinary> ProgramCache::load(const std::string &key) const
{
    if (!enabled())
        return std::nullopt;
    // an untrusted file: a size no program binary has is a miss, unread
    struct stat info;
    const std::string path = path_of(key);
    if (stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) ||
        uint64_t(info.st_size) > MAX_FILE_BYTES)
        return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return std::nullopt;
    const std::vector<uint8_t> file((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    if (file.size() < HEADER_BYTES || std::memcmp(file.data(), MAGIC, 8) != 0)
        return std::nullopt;
    sbrt::ByteReader header(file.data() + 8, HEADER_BYTES - 8, "program cache");
    ProgramBinary binary;
    binary.format = header.u32();
    const uint64_t size = header.u64();
    const uint32_t crc = header.u32();
    if (size != file.size() - HEADER_BYTES ||
        sbrt::crc32_of(file.data() + HEADER_BYTES, size_t(size)) != crc)
        return std::nullopt;
    binary.bytes.assign(file.begin() + long(HEADER_BYTES), file.end());
    return binary;
}

bool ProgramCache::store(const std::string &key, const ProgramBinary &binary) const
{
    if (!enabled() || !make_directories(directory_))
        return false;
    sbrt::ByteWriter out;
    out.raw(MAGIC, 8);
    out.u32(binary.format);
    out.u64(binary.bytes.size());
    out.u32(sbrt::crc32_of(binary.bytes.data(), binary.bytes.size()));
    out.raw(binary.bytes.data(), binary.bytes.size());
    // a temporary sibling of its own (mkstemp: two writers never share
    // one), renamed into place: a reader sees the old file or the new one,
    // never half of one
    const std::string path = path_of(key);
    std::string temporary = path + ".tmp.XXXXXX";
    const int fd = mkstemp(temporary.data());
    if (fd < 0)
        return false;
    fchmod(fd, 0644);
    const std::vector<uint8_t> &bytes = out.bytes();
    size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = write(fd, bytes.data() + written, bytes.size() - written);
        if (n <= 0)
            break;
        written += size_t(n);
    }
    const bool ok = written == bytes.size() && fsync(fd) == 0;
    if (close(fd) != 0 || !ok || std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        return false;
    }
    return true;
}

} // namespace sbrt_gl
