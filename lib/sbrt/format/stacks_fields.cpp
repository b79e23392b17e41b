/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The frame and material records of every `stacks` format
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/stacks_fields.hpp"

#include <climits>

#include "util/error.hpp"

namespace sbrt {

void write_frame(ByteWriter &out, const Frame &f)
{
    for (double v : {f.north, f.south, f.east, f.west, f.bottom, f.top})
        out.f64(v);
    out.u32(uint32_t(f.rows));
    out.u32(uint32_t(f.cols));
    out.u32(uint32_t(f.depths));
    out.i32(f.proj);
    out.i32(f.zone);
}

Frame read_frame(ByteReader &in, const std::string &what)
{
    Frame f;
    f.north = in.f64();
    f.south = in.f64();
    f.east = in.f64();
    f.west = in.f64();
    f.bottom = in.f64();
    f.top = in.f64();
    const uint32_t rows = in.u32(), cols = in.u32(), depths = in.u32();
    if (rows == 0 || cols == 0 || depths == 0 || rows > INT32_MAX ||
        cols > INT32_MAX || depths > INT32_MAX)
        fail(what, ": bad grid size ", rows, "x", cols, "x", depths);
    f.rows = int(rows);
    f.cols = int(cols);
    f.depths = int(depths);
    f.proj = in.i32();
    f.zone = in.i32();
    f.validate(what.c_str());
    return f;
}

void write_materials(ByteWriter &out, const std::vector<Material> &materials)
{
    for (const Material &m : materials) {
        out.i32(m.id);
        out.u8(m.red);
        out.u8(m.green);
        out.u8(m.blue);
        out.u8(m.has_color ? 1 : 0);
    }
}

std::vector<Material> read_materials(ByteReader &in, uint32_t count)
{
    std::vector<Material> materials(count);
    for (Material &m : materials) {
        m.id = in.i32();
        m.red = in.u8();
        m.green = in.u8();
        m.blue = in.u8();
        m.has_color = (in.u8() & 1) != 0;
    }
    if (!materials.empty())
        materials[0].label = "EMPTY";
    return materials;
}

Model validated_model(const Frame &frame, std::vector<Material> materials,
                      StackIndex index, IntervalArray intervals,
                      const std::string &what)
{
    try {
        Model model(frame, std::move(materials), std::move(index), std::move(intervals));
        model.validate();
        return model;
    }
    catch (const Error &e) {
        fail(what, ": ", e.what());
    }
}

} // namespace sbrt
