/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   An RGB PNG file written row by row through libpng, as the
 *            bands of a render arrive; atomic (a temporary sibling of a
 *            name unique to this writer, renamed into place by finish(),
 *            removed if the image is not finished): several processes
 *            writing one path each write a whole file, the last one stays
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PNG_FILE_HPP
#define SBRT_PNG_FILE_HPP

#include <cstdint>
#include <cstdio>
#include <string>

namespace sbrt {

/// \brief 8-bit RGB, rows top first. Every failure throws sbrt::Error.
class PngFile {
public:
    PngFile(const std::string &path, int rows, int cols);
    ~PngFile(); ///< an unfinished file is removed
    PngFile(const PngFile &) = delete;
    PngFile &operator=(const PngFile &) = delete;

    /// The next `rows` rows, 3 bytes per pixel.
    void write_rows(const uint8_t *rgb, int rows);
    /// Ends the image (all rows written) and moves it into place.
    void finish();

private:
    /// Creates the temporary file (a unique name beside path_) as file_.
    void open_temporary();
    /// Frees libpng's state; removes the temporary file if still open.
    void discard();

    std::string path_, temp_;
    int rows_, cols_, written_ = 0;
    std::FILE *file_ = nullptr;
    void *png_ = nullptr, *info_ = nullptr; ///< png_structp, png_infop
    std::string error_; ///< libpng's message of the failure
};

} // namespace sbrt

#endif
