/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   RAII owners of GL buffers and programs (move-only)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_OBJECTS_HPP
#define SBRT_GL_OBJECTS_HPP

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gl_api.hpp"
#include "program_cache.hpp"

namespace sbrt_gl {

/// \brief A buffer object holding `bytes` bytes (copied from `data` when
/// given), bound to an indexed target by bind().
class GlBuffer {
public:
    GlBuffer(const GlApi &gl, GLenum target, size_t bytes,
             const void *data = nullptr);
    ~GlBuffer();
    GlBuffer(GlBuffer &&other) noexcept
        : gl_(other.gl_), target_(other.target_), name_(std::exchange(other.name_, 0)),
          bytes_(other.bytes_)
    {
    }
    GlBuffer(const GlBuffer &) = delete;
    GlBuffer &operator=(const GlBuffer &) = delete;
    GlBuffer &operator=(GlBuffer &&) = delete;

    void bind(GLuint index) const;
    void upload(const void *data, size_t bytes);
    /// Writes `bytes` bytes at byte `offset` (glBufferSubData).
    void write(size_t offset, const void *data, size_t bytes);
    /// Reads the first `bytes` bytes back.
    void download(void *data, size_t bytes) const;
    /// Reads `bytes` bytes from byte `offset` back.
    void download(size_t offset, void *data, size_t bytes) const;
    GLuint name() const { return name_; }
    size_t bytes() const { return bytes_; }

private:
    const GlApi *gl_;
    GLenum target_;
    GLuint name_ = 0;
    size_t bytes_;
};

/// \brief A storage buffer of `bytes` bytes mapped into host memory for
/// its whole life (glBufferStorage, MAP_PERSISTENT | MAP_COHERENT, read
/// and write, client storage: the GPU writes where the host reads). What
/// the GPU writes is there for the host once a fence after the writes
/// (and a GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT barrier) is signalled.
class MappedBuffer {
public:
    MappedBuffer(const GlApi &gl, size_t bytes);
    ~MappedBuffer();
    MappedBuffer(MappedBuffer &&other) noexcept
        : gl_(other.gl_), name_(std::exchange(other.name_, 0)), bytes_(other.bytes_),
          host_(std::exchange(other.host_, nullptr))
    {
    }
    MappedBuffer(const MappedBuffer &) = delete;
    MappedBuffer &operator=(const MappedBuffer &) = delete;
    MappedBuffer &operator=(MappedBuffer &&) = delete;

    void bind(GLuint index) const; ///< as a storage buffer
    uint8_t *host() const { return host_; }
    GLuint name() const { return name_; }
    size_t bytes() const { return bytes_; }

private:
    const GlApi *gl_;
    GLuint name_ = 0;
    size_t bytes_;
    uint8_t *host_ = nullptr;
};

/// \brief A fence after the commands queued so far (glFenceSync, flushed
/// so that the GPU starts on them).
class GlFence {
public:
    explicit GlFence(const GlApi &gl);
    ~GlFence();
    GlFence(GlFence &&other) noexcept
        : gl_(other.gl_), sync_(std::exchange(other.sync_, nullptr))
    {
    }
    GlFence(const GlFence &) = delete;
    GlFence &operator=(const GlFence &) = delete;
    GlFence &operator=(GlFence &&) = delete;

    /// Returns once the GPU has done the commands before the fence;
    /// throws sbrt::Error where the wait fails (a lost context).
    void wait() const;

private:
    const GlApi *gl_;
    GLsync sync_ = nullptr;
};

/// \brief A GL_TIME_ELAPSED query: the GPU time of the commands between
/// begin() and end() (one such query at a time).
class GlTimeQuery {
public:
    explicit GlTimeQuery(const GlApi &gl);
    ~GlTimeQuery();
    GlTimeQuery(GlTimeQuery &&other) noexcept
        : gl_(other.gl_), name_(std::exchange(other.name_, 0))
    {
    }
    GlTimeQuery(const GlTimeQuery &) = delete;
    GlTimeQuery &operator=(const GlTimeQuery &) = delete;
    GlTimeQuery &operator=(GlTimeQuery &&) = delete;

    void begin() const;
    void end() const;
    /// Milliseconds (waits for the result).
    double ms() const;

private:
    const GlApi *gl_;
    GLuint name_ = 0;
};

/// \brief An immutable 2D texture of one or two 32-bit unsigned integers
/// per texel (GL_R32UI or GL_RG32UI, one level, nearest texel), read by
/// texelFetch from a usampler2D; bind() puts it on a texture unit.
class GlUintTexture {
public:
    /// `texels` holds channels * cols * rows values, row 0 first.
    GlUintTexture(const GlApi &gl, int cols, int rows, const uint32_t *texels,
                  int channels = 2);
    ~GlUintTexture();
    GlUintTexture(GlUintTexture &&other) noexcept
        : gl_(other.gl_), name_(std::exchange(other.name_, 0))
    {
    }
    GlUintTexture(const GlUintTexture &) = delete;
    GlUintTexture &operator=(const GlUintTexture &) = delete;
    GlUintTexture &operator=(GlUintTexture &&) = delete;

    void bind(GLuint unit) const;

private:
    const GlApi *gl_;
    GLuint name_ = 0;
};

/// \brief A linked compute program from source strings concatenated in
/// order; throws sbrt::Error with the compiler's log.
class GlComputeProgram {
public:
    /// Compiles and links `sources`; with an enabled `cache`, loads the
    /// linked binary from it where the driver takes it back, else stores
    /// the one it links.
    GlComputeProgram(const GlApi &gl, const std::vector<const char *> &sources,
                     const ProgramCache *cache = nullptr);
    ~GlComputeProgram();
    GlComputeProgram(const GlComputeProgram &) = delete;
    GlComputeProgram &operator=(const GlComputeProgram &) = delete;

    GLuint name() const { return program_; }
    void use() const { gl_->UseProgram(program_); }
    /// Whether the program came from the cache (not compiled).
    bool from_cache() const { return from_cache_; }

private:
    /// The cached binary of `key` as the program; false (no program) where
    /// there is none or the driver refuses it.
    bool load(const ProgramCache &cache, const std::string &key);
    void compile(const std::vector<const char *> &sources, bool retrievable);

    const GlApi *gl_;
    GLuint program_ = 0;
    bool from_cache_ = false;
};

} // namespace sbrt_gl

#endif
