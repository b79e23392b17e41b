/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Linked program binaries kept on disk between runs
 *            (GL_ARB_get_program_binary, core since 4.1), so that a second
 *            run loads its shaders instead of compiling them again
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_PROGRAM_CACHE_HPP
#define SBRT_GL_PROGRAM_CACHE_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <GL/glcorearb.h>

namespace sbrt_gl {

/// A linked program as the driver gives it back: its format and bytes.
struct ProgramBinary {
    GLenum format = 0;
    std::vector<uint8_t> bytes;
};

/// \brief A directory of program binaries, one file per program, named
/// after a 64-bit hash of the GL's vendor, renderer and version and of the
/// program's sources (a driver update or a changed shader is another
/// file). A file is read as untrusted (magic, sizes, CRC-32; anything
/// wrong is a miss) and written atomically (a temporary sibling renamed
/// into place); a binary the driver refuses is compiled again and the file
/// replaced (GlComputeProgram). Every failure to read or write is a miss,
/// never an error: the cache only saves time.
class ProgramCache {
public:
    /// No cache.
    ProgramCache() = default;
    /// Files in `directory` (made when first written); "" is no cache.
    explicit ProgramCache(std::string directory) : directory_(std::move(directory)) {}

    /// SBRT_PROGRAM_CACHE where set ("" or "off": no cache), else
    /// $XDG_CACHE_HOME/r3.sbrt/programs, else $HOME/.cache/r3.sbrt/programs,
    /// else none.
    static ProgramCache from_environment();

    bool enabled() const { return !directory_.empty(); }
    const std::string &directory() const { return directory_; }

    /// The key of a program: its GL (vendor, renderer, version) and
    /// sources, hashed (FNV-1a, 64 bits) into 16 hexadecimal digits.
    static std::string key(const std::string &gl_identity,
                           const std::vector<const char *> &sources);
    std::string path_of(const std::string &key) const;

    /// The binary stored under `key`; none where there is none, or the
    /// file is not a whole, intact cache file.
    std::optional<ProgramBinary> load(const std::string &key) const;
    /// Stores `binary` under `key`; false where it could not be written.
    bool store(const std::string &key, const ProgramBinary &binary) const;

private:
    std::string directory_;
};

} // namespace sbrt_gl

#endif
