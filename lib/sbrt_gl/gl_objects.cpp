/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   GL buffers and programs
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gl_objects.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "util/error.hpp"

namespace sbrt_gl {

GlBuffer::GlBuffer(const GlApi &gl, GLenum target, size_t bytes, const void *data)
    : gl_(&gl), target_(target), bytes_(bytes)
{
    gl.GenBuffers(1, &name_);
    gl.BindBuffer(target_, name_);
    // a zero-sized store cannot be bound: keep at least 16 bytes
    gl.BufferData(target_, GLsizeiptr(bytes ? bytes : 16), data,
                  target == GL_UNIFORM_BUFFER ? GL_DYNAMIC_DRAW : GL_STATIC_DRAW);
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR) {
        gl.DeleteBuffers(1, &name_);
        sbrt::fail("OpenGL: cannot allocate a buffer of ", bytes, " bytes (error 0x",
                   std::hex, error, ")");
    }
}

GlBuffer::~GlBuffer()
{
    if (name_)
        gl_->DeleteBuffers(1, &name_);
}

void GlBuffer::bind(GLuint index) const
{
    gl_->BindBufferBase(target_, index, name_);
}

void GlBuffer::upload(const void *data, size_t bytes)
{
    SBRT_CHECK_EQ(bytes, bytes_, "GlBuffer::upload");
    gl_->BindBuffer(target_, name_);
    gl_->BufferData(target_, GLsizeiptr(bytes), data, GL_DYNAMIC_DRAW);
}

void GlBuffer::write(size_t offset, const void *data, size_t bytes)
{
    if (offset + bytes > bytes_)
        sbrt::fail("GlBuffer::write: ", bytes, " bytes at ", offset, " into a buffer of ", bytes_);
    gl_->BindBuffer(target_, name_);
    gl_->BufferSubData(target_, GLintptr(offset), GLsizeiptr(bytes), data);
}

void GlBuffer::download(size_t offset, void *data, size_t bytes) const
{
    if (offset + bytes > bytes_)
        sbrt::fail("GlBuffer::download: ", bytes, " bytes at ", offset, " from a buffer of ",
                   bytes_);
    gl_->BindBuffer(target_, name_);
    gl_->GetBufferSubData(target_, GLintptr(offset), GLsizeiptr(bytes), data);
    check_gl(*gl_, "reading a buffer back");
}

void GlBuffer::download(void *data, size_t bytes) const
{
    if (bytes > bytes_)
        sbrt::fail("GlBuffer::download: ", bytes, " bytes from a buffer of ", bytes_);
    gl_->BindBuffer(target_, name_);
    gl_->GetBufferSubData(target_, 0, GLsizeiptr(bytes), data);
    check_gl(*gl_, "reading a buffer back");
}

MappedBuffer::MappedBuffer(const GlApi &gl, size_t bytes) : gl_(&gl), bytes_(bytes)
{
    const GLbitfield access =
        GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    gl.GenBuffers(1, &name_);
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, name_);
    const GLsizeiptr size = GLsizeiptr(bytes ? bytes : 16);
    gl.BufferStorage(GL_SHADER_STORAGE_BUFFER, size, nullptr, access | GL_CLIENT_STORAGE_BIT);
    if (gl.GetError() == GL_NO_ERROR)
        host_ = static_cast<uint8_t *>(
            gl.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, size, access));
    const GLenum error = gl.GetError();
    if (!host_ || error != GL_NO_ERROR) {
        gl.DeleteBuffers(1, &name_);
        sbrt::fail("OpenGL: cannot map a buffer of ", bytes, " bytes into host memory (error 0x",
                   std::hex, error, ")");
    }
}

MappedBuffer::~MappedBuffer()
{
    if (!name_)
        return;
    gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, name_);
    gl_->UnmapBuffer(GL_SHADER_STORAGE_BUFFER);
    gl_->DeleteBuffers(1, &name_);
}

void MappedBuffer::bind(GLuint index) const
{
    gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, index, name_);
}

GlFence::GlFence(const GlApi &gl)
    : gl_(&gl), sync_(gl.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0))
{
    if (!sync_)
        sbrt::fail("OpenGL: glFenceSync failed (error 0x", std::hex, gl.GetError(), ")");
    gl.Flush();
}

GlFence::~GlFence()
{
    if (sync_)
        gl_->DeleteSync(sync_);
}

void GlFence::wait() const
{
    // a second at a time: a large band on a software renderer takes long
    const GLuint64 second = 1000000000;
    for (;;) {
        const GLenum status = gl_->ClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, second);
        if (status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED)
            return;
        if (status != GL_TIMEOUT_EXPIRED)
            sbrt::fail("OpenGL: waiting for the GPU failed (glClientWaitSync error 0x",
                       std::hex, gl_->GetError(), ")");
    }
}

GlTimeQuery::GlTimeQuery(const GlApi &gl) : gl_(&gl)
{
    gl.GenQueries(1, &name_);
}

GlTimeQuery::~GlTimeQuery()
{
    if (name_)
        gl_->DeleteQueries(1, &name_);
}

void GlTimeQuery::begin() const
{
    gl_->BeginQuery(GL_TIME_ELAPSED, name_);
}

void GlTimeQuery::end() const
{
    gl_->EndQuery(GL_TIME_ELAPSED);
}

double GlTimeQuery::ms() const
{
    GLuint64 ns = 0;
    gl_->GetQueryObjectui64v(name_, GL_QUERY_RESULT, &ns);
    return double(ns) / 1e6;
}

GlUintTexture::GlUintTexture(const GlApi &gl, int cols, int rows,
                             const uint32_t *texels, int channels)
    : gl_(&gl)
{
    gl.GenTextures(1, &name_);
    gl.BindTexture(GL_TEXTURE_2D, name_);
    gl.TexStorage2D(GL_TEXTURE_2D, 1, channels == 1 ? GL_R32UI : GL_RG32UI,
                    std::max(cols, 1), std::max(rows, 1));
    // integer textures are complete with nearest filtering only
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (cols > 0 && rows > 0)
        gl.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, cols, rows,
                         channels == 1 ? GL_RED_INTEGER : GL_RG_INTEGER, GL_UNSIGNED_INT,
                         texels);
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR) {
        gl.DeleteTextures(1, &name_);
        sbrt::fail("OpenGL: cannot make a texture of ", cols, " x ", rows,
                   " texels (error 0x", std::hex, error, ")");
    }
}

GlUintTexture::~GlUintTexture()
{
    if (name_)
        gl_->DeleteTextures(1, &name_);
}

void GlUintTexture::bind(GLuint unit) const
{
    gl_->ActiveTexture(GL_TEXTURE0 + unit);
    gl_->BindTexture(GL_TEXTURE_2D, name_);
}

namespace {

/// The info log of a shader or program (getters glGet*iv, glGet*InfoLog).
template <typename GetInteger, typename GetLog>
std::string info_log(GetInteger get_integer, GetLog get_log, GLuint object)
{
    GLint length = 0;
    get_integer(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    get_log(object, GLsizei(log.size()), nullptr, log.data());
    return log.c_str();
}

} // namespace

GlComputeProgram::GlComputeProgram(const GlApi &gl,
                                   const std::vector<const char *> &sources,
                                   const ProgramCache *cache)
    : gl_(&gl)
{
    if (!cache || !cache->enabled()) {
        compile(sources, false);
        return;
    }
    const auto text = [&](GLenum name) {
        const GLubyte *value = gl.GetString(name);
        return value ? std::string(reinterpret_cast<const char *>(value)) : std::string();
    };
    const std::string key = ProgramCache::key(
        text(GL_VENDOR) + '\n' + text(GL_RENDERER) + '\n' + text(GL_VERSION), sources);
    // an error of an earlier step is reported as such, not taken for a
    // refused binary below
    check_gl(gl, "before loading or storing a program binary");
    if (load(*cache, key)) {
        from_cache_ = true;
        return;
    }
    compile(sources, true);
    GLint length = 0;
    gl.GetProgramiv(program_, GL_PROGRAM_BINARY_LENGTH, &length);
    ProgramBinary binary;
    binary.bytes.resize(size_t(std::max(length, 0)));
    GLsizei written = 0;
    if (length > 0)
        gl.GetProgramBinary(program_, length, &written, &binary.format, binary.bytes.data());
    if (gl.GetError() == GL_NO_ERROR && written == length && length > 0)
        cache->store(key, binary); // a failed write only costs the next run a compile
}

bool GlComputeProgram::load(const ProgramCache &cache, const std::string &key)
{
    const std::optional<ProgramBinary> binary = cache.load(key);
    if (!binary)
        return false;
    program_ = gl_->CreateProgram();
    gl_->ProgramBinary(program_, binary->format, binary->bytes.data(),
                       GLsizei(binary->bytes.size()));
    GLint ok = 0;
    gl_->GetProgramiv(program_, GL_LINK_STATUS, &ok);
    // a binary of another driver build, or damaged: compiled again (the
    // errors it raised cleared; none was pending before: checked)
    for (int k = 0; k < 16 && gl_->GetError() != GL_NO_ERROR; ++k)
        ok = 0;
    if (!ok) {
        gl_->DeleteProgram(program_);
        program_ = 0;
    }
    return ok != 0;
}

void GlComputeProgram::compile(const std::vector<const char *> &sources, bool retrievable)
{
    const GlApi &gl = *gl_;
    const GLuint shader = gl.CreateShader(GL_COMPUTE_SHADER);
    gl.ShaderSource(shader, GLsizei(sources.size()), sources.data(), nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = info_log(gl.GetShaderiv, gl.GetShaderInfoLog, shader);
        gl.DeleteShader(shader);
        sbrt::fail("OpenGL: the compute shader does not compile: ", log);
    }
    program_ = gl.CreateProgram();
    if (retrievable)
        gl.ProgramParameteri(program_, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
    gl.AttachShader(program_, shader);
    gl.LinkProgram(program_);
    gl.DeleteShader(shader); // stays alive while attached
    gl.GetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log =
            info_log(gl.GetProgramiv, gl.GetProgramInfoLog, program_);
        gl.DeleteProgram(program_);
        sbrt::fail("OpenGL: the compute program does not link: ", log);
    }
}

GlComputeProgram::~GlComputeProgram()
{
    gl_->DeleteProgram(program_);
}

} // namespace sbrt_gl
