/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   RGB PNG file through libpng, row by row
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "output/png_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <fcntl.h>

#include <cerrno>
#include <csetjmp>
#include <cstdlib>
#include <cstring>

#include <png.h>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// libpng's error callback: keeps the message, returns through setjmp.
void on_png_error(png_structp png, png_const_charp message)
{
    *static_cast<std::string *>(png_get_error_ptr(png)) = message;
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

/// The process's umask, read once (umask() both reads and sets it; read at
/// static initialisation, before any thread could create a file).
mode_t read_umask()
{
    const mode_t mask = umask(022);
    umask(mask);
    return mask;
}
const mode_t initial_umask = read_umask();

mode_t process_umask() { return initial_umask; }

} // namespace

PngFile::PngFile(const std::string &path, int rows, int cols)
    : path_(path), rows_(rows), cols_(cols)
{
    if (rows <= 0 || cols <= 0)
        fail("PNG <", path, ">: an image of ", cols, " x ", rows, " pixels");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error_,
                                              on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    png_ = png;
    info_ = info;
    if (!info) {
        discard();
        fail("PNG <", path, ">: libpng could not start");
    }
    open_temporary();
    if (setjmp(png_jmpbuf(png))) {
        discard(); // no destructor runs for a constructor that throws
        fail("PNG <", path, ">: ", error_);
    }
    png_init_io(png, file_);
    png_set_IHDR(png, info, png_uint_32(cols), png_uint_32(rows), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // rendered images: large flat areas; level 3 is close to 6 in size
    // and about twice as fast
    // zlib level 1 with the SUB filter alone encodes several times as fast
    // as level 3 with adaptive filtering, for files a few per cent larger
    // (docs/performance.md): an animation's frames are written while the
    // next ones trace on the same cores
    png_set_compression_level(png, 1);
    png_set_filter(png, 0, PNG_FILTER_SUB);
    png_write_info(png, info);
}

PngFile::~PngFile()
{
    discard();
}

void PngFile::discard()
{
    png_structp png = static_cast<png_structp>(png_);
    png_infop info = static_cast<png_infop>(info_);
    if (png)
        png_destroy_write_struct(&png, info ? &info : nullptr);
    png_ = info_ = nullptr;
    if (file_) {
        std::fclose(file_);
        std::remove(temp_.c_str());
        file_ = nullptr;
    }
}

void PngFile::write_rows(const uint8_t *rgb, int rows)
{
    if (written_ + rows > rows_)
        fail("PNG <", path_, ">: more than its ", rows_, " rows");
    png_structp png = static_cast<png_structp>(png_);
    if (setjmp(png_jmpbuf(png)))
        fail("PNG <", path_, ">: ", error_);
    for (int r = 0; r < rows; ++r)
        png_write_row(png, rgb + size_t(r) * size_t(cols_) * 3);
    written_ += rows;
}

void PngFile::finish()
{
    if (written_ != rows_)
        fail("PNG <", path_, ">: ", written_, " of its ", rows_, " rows written");
    png_structp png = static_cast<png_structp>(png_);
    if (setjmp(png_jmpbuf(png)))
        fail("PNG <", path_, ">: ", error_);
    png_write_end(png, nullptr);
    const bool closed = std::fclose(file_) == 0;
    const int close_error = errno;
    file_ = nullptr;
    if (!closed) {
        std::remove(temp_.c_str());
        fail("cannot write PNG file <", path_, ">: ", std::strerror(close_error));
    }
    // the last of several writers of one path wins, each with a whole file
    if (std::rename(temp_.c_str(), path_.c_str()) != 0) {
        const int error = errno;
        std::remove(temp_.c_str());
        fail("cannot write PNG file <", path_, ">: ", std::strerror(error));
    }
}

void PngFile::open_temporary()
{
    // a name of its own in the folder of the file (rename() stays in one
    // file system): processes writing one path never share a temporary
    temp_ = path_ + ".XXXXXX.tmp";
    const int fd = mkostemps(temp_.data(), 4, O_CLOEXEC);
    if (fd < 0) {
        const int error = errno;
        discard();
        fail("cannot write PNG file <", path_, ">: cannot create a file beside it: ",
             std::strerror(error));
    }
    // as fopen() would make it: 0666 less the umask (mkstemp makes 0600)
    file_ = fchmod(fd, 0666 & ~process_umask()) == 0 ? fdopen(fd, "wb") : nullptr;
    if (!file_) {
        const int error = errno;
        close(fd);
        std::remove(temp_.c_str());
        discard();
        fail("cannot write PNG file <", path_, ">: ", std::strerror(error));
    }
}

} // namespace sbrt
