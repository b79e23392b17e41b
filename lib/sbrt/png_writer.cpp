/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   PNG files of images
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "png_writer.hpp"

#include <cstdio>
#include <fstream>

#include <zlib.h>

#include "error.hpp"

namespace sbrt {

namespace {

void put_u32(std::string &out, uint32_t v)
{
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(char((v >> shift) & 0xff));
}

/// A chunk: length, type, data, CRC of type and data.
void put_chunk(std::string &out, const char type[4], const std::string &data)
{
    put_u32(out, uint32_t(data.size()));
    const std::string body = std::string(type, 4) + data;
    out += body;
    put_u32(out, uint32_t(crc32(0, reinterpret_cast<const Bytef *>(body.data()),
                                uInt(body.size()))));
}

} // namespace

void write_png(const std::string &path, int rows, int cols,
               const std::vector<uint8_t> &rgb)
{
    SBRT_CHECK_EQ(rgb.size(), size_t(rows) * size_t(cols) * 3, "write_png");
    if (rows <= 0 || cols <= 0)
        fail("PNG <", path, ">: an image of ", cols, " x ", rows, " pixels");
    // each row: filter type 0 (none), then its pixels
    std::string raw;
    raw.reserve(size_t(rows) * (size_t(cols) * 3 + 1));
    for (int r = 0; r < rows; ++r) {
        raw.push_back('\0');
        raw.append(reinterpret_cast<const char *>(rgb.data()) + size_t(r) * cols * 3,
                   size_t(cols) * 3);
    }
    uLongf packed_size = compressBound(uLong(raw.size()));
    std::string packed(packed_size, '\0');
    if (compress2(reinterpret_cast<Bytef *>(&packed[0]), &packed_size,
                  reinterpret_cast<const Bytef *>(raw.data()), uLong(raw.size()),
                  6) != Z_OK)
        fail("PNG <", path, ">: compressing the image failed");
    packed.resize(packed_size);

    std::string png("\x89PNG\r\n\x1a\n", 8);
    std::string header;
    put_u32(header, uint32_t(cols));
    put_u32(header, uint32_t(rows));
    header += std::string("\x08\x02\x00\x00\x00", 5); // 8-bit RGB, no interlace
    put_chunk(png, "IHDR", header);
    put_chunk(png, "IDAT", packed);
    put_chunk(png, "IEND", "");

    const std::string temp = path + ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(png.data(), std::streamsize(png.size()));
        out.close();
        if (!out)
            fail("cannot write PNG file <", temp, ">");
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        std::remove(temp.c_str());
        fail("cannot rename <", temp, "> to <", path, ">");
    }
}

} // namespace sbrt
