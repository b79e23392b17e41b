/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   SBRT file format: writer and validating reader
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/format.hpp"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "format/atomic_dir.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"
#include "format/mapped_file.hpp"
#include "format/member_dir.hpp"
#include "format/paged_stacks.hpp"
#include "format/stacks_fields.hpp"
#include "format/sbrt_writer.hpp"
#include "format/stacks_v2_layout.hpp"

namespace sbrt {

Model decode_stacks(const uint8_t *data, size_t size, const std::string &what,
                    std::shared_ptr<const void> keep, const ReadOptions &options)
{
    const uint16_t major = stacks_major_version(data, size);
    if (major == 0)
        fail(what, ": not an SBRT stacks file (bad magic number)");
    if (major == FORMAT_V1_VERSION) {
        if (options.rows) // read in place, whole: never a band of rows
            fail(what, ": a format 1 stacks file is read whole, not by rows; "
                 "convert its source again to get format 2");
        if (options.report)
            *options.report = ReadReport{};
        return decode_stacks_v1(data, size, what, std::move(keep));
    }
    if (major == FORMAT_V2_MAJOR)
        return decode_stacks_v2(data, size, what, options);
    fail(what, ": format version ", major, " is not supported (this build "
         "reads versions 1 and 2; a newer r3.sbrt wrote it)");
}

std::string encode_cats(const Model &model)
{
    return encode_cats(model.materials());
}

std::string encode_cats(const std::vector<Material> &materials)
{
    std::ostringstream out;
    for (size_t i = 1; i < materials.size(); ++i) {
        std::string label = materials[i].label;
        for (char &ch : label)
            if (ch == '\n' || ch == '\r')
                ch = ' ';
        out << materials[i].id << ':' << label << '\n';
    }
    return out.str();
}

void decode_cats(const std::string &text, Model &model, const std::string &what)
{
    decode_cats(text, model.materials(), what);
}

namespace {

/// Material index whose class id is `id` (EMPTY excluded), or -1: as
/// Model::find_material.
int64_t find_material(const std::vector<Material> &materials, int32_t id)
{
    for (size_t i = 1; i < materials.size(); ++i)
        if (materials[i].id == id)
            return int64_t(i);
    return -1;
}

} // namespace

void decode_cats(const std::string &text, std::vector<Material> &materials,
                 const std::string &what)
{
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.empty())
            continue;
        const auto colon = line.find(':');
        char *end = nullptr;
        const long id = std::strtol(line.c_str(), &end, 10);
        if (colon == std::string::npos || end != line.c_str() + colon ||
            id < INT32_MIN || id > INT32_MAX)
            fail(what, " line ", number, ": expected id:label");
        const int64_t m = find_material(materials, int32_t(id));
        if (m > 0)
            materials[size_t(m)].label = valid_utf8(line.substr(colon + 1));
    }
}

std::string encode_colors(const Model &model)
{
    return encode_colors(model.materials());
}

std::string encode_colors(const std::vector<Material> &materials)
{
    std::ostringstream out;
    for (size_t i = 1; i < materials.size(); ++i)
        if (materials[i].has_color)
            out << materials[i].id << ' ' << int(materials[i].red) << ':'
                << int(materials[i].green) << ':' << int(materials[i].blue) << '\n';
    return out.str();
}

void decode_colors(const std::string &text, Model &model, const std::string &what)
{
    decode_colors(text, model.materials(), what);
}

void decode_colors(const std::string &text, std::vector<Material> &materials,
                   const std::string &what)
{
    for (Material &m : materials)
        m.has_color = false;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.empty())
            continue;
        long id = 0;
        int r = -1, g = -1, b = -1, used = 0;
        if (std::sscanf(line.c_str(), "%ld %d:%d:%d%n", &id, &r, &g, &b, &used) != 4 ||
            size_t(used) != line.size() || id < INT32_MIN || id > INT32_MAX || r < 0 ||
            r > 255 || g < 0 || g > 255 || b < 0 || b > 255)
            fail(what, " line ", number, ": expected id red:green:blue");
        const int64_t m = find_material(materials, int32_t(id));
        if (m > 0) {
            Material &material = materials[size_t(m)];
            material.red = uint8_t(r);
            material.green = uint8_t(g);
            material.blue = uint8_t(b);
            material.has_color = true;
        }
    }
}

namespace {

/// A vertical datum as the datum member holds it: one line of printable,
/// valid UTF-8, at most MAX_DATUM_CHARS bytes; else throws naming `what`.
void check_datum(const std::string &datum, const std::string &what)
{
    if (datum.size() > MAX_DATUM_CHARS)
        fail(what, ": a vertical datum of more than ", MAX_DATUM_CHARS, " characters");
    if (printable(datum) != datum)
        fail(what, ": the vertical datum is not one line of printable text");
}

} // namespace

std::string encode_datum(const Model &model)
{
    return encode_datum(model.vertical_datum());
}

std::string encode_datum(const std::string &datum)
{
    // what the reader would refuse is never written (an import would
    // leave an SBRT nothing can read)
    check_datum(datum, "the vertical datum");
    return datum + "\n";
}

namespace {

/// The datum member's one line, checked (throws naming `what`).
std::string datum_of(const std::string &text, const std::string &what)
{
    std::string datum = text;
    while (!datum.empty() && (datum.back() == '\n' || datum.back() == '\r'))
        datum.pop_back();
    check_datum(datum, what);
    return datum;
}

} // namespace

void decode_datum(const std::string &text, Model &model, const std::string &what)
{
    model.set_vertical_datum(datum_of(text, what));
}

std::string encode_header(const Model &model, size_t channels)
{
    return encode_header(model.frame(), model.materials().size(), model.stats().intervals,
                         channels);
}

std::string encode_header(const Frame &f, size_t materials, uint64_t intervals,
                          size_t channels)
{
    char text[1024];
    std::snprintf(text, sizeof text,
                  "format:      sbrt\nversion:     %u.%u\n"
                  "compression: zstd blocks\n"
                  "proj:        %d\nzone:        %d\n"
                  "north:       %.17g\nsouth:       %.17g\n"
                  "east:        %.17g\nwest:        %.17g\n"
                  "top:         %.17g\nbottom:      %.17g\n"
                  "rows:        %d\ncols:        %d\ndepths:      %d\n"
                  "materials:   %zu\nintervals:   %llu\n",
                  unsigned(FORMAT_V2_MAJOR), unsigned(FORMAT_V2_MINOR), f.proj, f.zone, f.north, f.south, f.east,
                  f.west, f.top, f.bottom, f.rows, f.cols, f.depths,
                  materials - 1, (unsigned long long)intervals);
    std::string header = text;
    if (channels)
        header += "channels:    " + std::to_string(channels) + "\n";
    return header;
}

StacksFileInfo stacks_file_info(const std::string &directory)
{
    const MemberDirectory dir(directory);
    const std::string path = dir.member_path("stacks");
    const MappedFile file(dir.open_regular("stacks"), path, MappedFile::Pages::on_demand);
    StacksFileInfo info;
    info.bytes = file.size();
    info.major = stacks_major_version(file.data(), file.size());
    if (info.major == 0 || file.size() < 12)
        fail(path, ": not an SBRT stacks file (bad magic number)");
    if (info.major >= FORMAT_V2_MAJOR)
        info.minor = uint16_t(file.data()[10] | file.data()[11] << 8);
    return info;
}

std::vector<uint8_t> read_file_bytes(const std::string &path)
{
    return read_all(open_regular_file(path), path);
}

void write_sbrt(const std::string &directory, const Model &model,
                const std::string &history, const StacksV2Options &options,
                const std::string &channels_file, const Model *coarse)
{
    model.validate();
    SbrtWriter writer(directory, model.frame(), options);
    writer.add_rows(model);
    writer.finish({model.materials(), model.vertical_datum()}, history, channels_file, coarse);
}

void rewrite_legend(const std::string &directory, const Model &model,
                    const std::string &history)
{
    const MemberDirectory dir(directory);
    AtomicDirectory out(directory);
    const std::string hist = stage_other_members(dir, out, {"cats", "colors"});
    out.write_file("cats", encode_cats(model));
    out.write_file("colors", encode_colors(model));
    out.write_file("hist", hist + history);
    out.commit();
}

std::shared_ptr<const PropertyChannels> read_channels(const std::string &directory,
                                                      const Model &model)
{
    const MemberDirectory dir(directory);
    const auto member = dir.open_regular_if_present("channels");
    if (!member)
        return nullptr;
    const std::string path = dir.member_path("channels");
    return std::make_shared<const PropertyChannels>(
        std::make_shared<const MappedFile>(*member, path), path, model);
}

namespace {

/// The labels and colours of `cats` and `colors` into `materials`, and
/// the vertical datum of `datum`, where the SBRT directory has them.
void read_legend_members(const MemberDirectory &dir, std::vector<Material> &materials,
                         std::string &datum_text)
{
    if (const auto cats = dir.open_regular_if_present("cats")) {
        const std::string cats_path = dir.member_path("cats");
        const std::vector<uint8_t> bytes = read_all(*cats, cats_path);
        decode_cats(std::string(bytes.begin(), bytes.end()), materials, cats_path);
    }
    if (const auto colors = dir.open_regular_if_present("colors")) {
        const std::string colors_path = dir.member_path("colors");
        const std::vector<uint8_t> bytes = read_all(*colors, colors_path);
        decode_colors(std::string(bytes.begin(), bytes.end()), materials, colors_path);
    }
    if (const auto datum = dir.open_regular_if_present("datum")) {
        const std::string datum_path = dir.member_path("datum");
        const std::vector<uint8_t> bytes = read_all(*datum, datum_path);
        if (bytes.size() > 2 * MAX_DATUM_CHARS)
            fail(datum_path, ": a vertical datum of more than ", MAX_DATUM_CHARS, " characters");
        datum_text = datum_of(std::string(bytes.begin(), bytes.end()), datum_path);
    }
}

} // namespace

Model read_sbrt(const std::string &directory, const ReadOptions &options)
{
    // members relative to the directory: no links, no FIFOs (issue 28)
    const MemberDirectory dir(directory);
    const std::string stacks_path = dir.member_path("stacks");
    // a read of a part (an area, points, rows) touches the blocks it needs
    const bool whole = !options.area && !options.points && !options.rows;
    const auto file = std::make_shared<const MappedFile>(
        dir.open_regular("stacks"), stacks_path,
        whole ? MappedFile::Pages::populated : MappedFile::Pages::on_demand);
    Model model =
        decode_stacks(file->data(), file->size(), stacks_path, file, options);
    std::string datum;
    read_legend_members(dir, model.materials(), datum);
    model.set_vertical_datum(datum);
    return model;
}

std::optional<Model> read_sbrt_paged(const std::string &directory, const Paging &paging)
{
    const MemberDirectory dir(directory);
    const std::string stacks_path = dir.member_path("stacks");
    // blocks are read as the view reaches them
    const auto file = std::make_shared<const MappedFile>(dir.open_regular("stacks"),
                                                         stacks_path, MappedFile::Pages::on_demand);
    std::vector<uint8_t> ranges_bytes, tops_bytes;
    // a member's bytes into `bytes`, where the SBRT has it
    const auto read_member = [&dir](const char *name, std::vector<uint8_t> &bytes) {
        StoredMember member;
        if (const auto file = dir.open_regular_if_present(name)) {
            member.what = dir.member_path(name);
            bytes = read_all(*file, member.what);
            member.bytes = &bytes;
        }
        return member;
    };
    const StoredRanges stored{read_member("ranges", ranges_bytes),
                              read_member("tops", tops_bytes)};
    std::optional<Model> model =
        open_paged_model(file->data(), file->size(), stacks_path, file, paging, stored, file.get());
    if (!model)
        return std::nullopt;
    std::string datum;
    read_legend_members(dir, model->materials(), datum);
    model->set_vertical_datum(datum);
    return model;
}

int CoarseLevel::factor() const
{
    const double rows = double(exact.rows) / model.frame().rows;
    const double cols = double(exact.cols) / model.frame().cols;
    return int(std::lround(std::max(rows, cols)));
}

std::optional<CoarseLevel> read_sbrt_lod(const std::string &directory)
{
    const MemberDirectory dir(directory);
    const auto member = dir.open_regular_if_present("stacks_lod");
    if (!member)
        return std::nullopt;
    const std::string path = dir.member_path("stacks_lod");
    CoarseLevel level;
    {
        const std::string stacks_path = dir.member_path("stacks");
        const MappedFile file(dir.open_regular("stacks"), stacks_path, MappedFile::Pages::on_demand);
        if (stacks_major_version(file.data(), file.size()) != FORMAT_V2_MAJOR)
            fail(path, ": a coarse level beside stacks of format 1");
        if (const auto summary = read_stacks_summary(file.data(), file.size(), stacks_path)) {
            level.exact = summary->frame;
            level.exact_top_local = summary->highest_top_local();
        }
        else
            level.exact = open_stacks_v2(file.data(), file.size(), stacks_path).header.frame;
    }
    const Frame &exact = level.exact;
    const auto file = std::make_shared<const MappedFile>(*member, path);
    Model model = decode_stacks(file->data(), file->size(), path, file);
    const Frame &f = model.frame();
    if (f.north != exact.north || f.south != exact.south || f.east != exact.east ||
        f.west != exact.west || f.bottom != exact.bottom || f.top != exact.top ||
        f.depths != exact.depths || f.rows > exact.rows || f.cols > exact.cols)
        fail(path, ": its extent (", f.rows, " x ", f.cols, " cells) is not that of the "
             "stacks (", exact.rows, " x ", exact.cols, ")");
    // the labels, colours and datum of the exact model's members
    std::string datum;
    read_legend_members(dir, model.materials(), datum);
    model.set_vertical_datum(datum);
    level.model = std::move(model);
    return level;
}

std::optional<ModelSummary> read_sbrt_summary(const std::string &directory)
{
    const MemberDirectory dir(directory);
    const std::string stacks_path = dir.member_path("stacks");
    std::optional<ModelSummary> summary;
    {
        const MappedFile file(dir.open_regular("stacks"), stacks_path, MappedFile::Pages::on_demand);
        summary = read_stacks_summary(file.data(), file.size(), stacks_path);
    }
    if (!summary)
        return summary;
    read_legend_members(dir, summary->materials, summary->vertical_datum);
    summary->has_channels = dir.open_regular_if_present("channels").has_value();
    return summary;
}

} // namespace sbrt
