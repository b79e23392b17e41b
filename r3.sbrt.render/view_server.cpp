/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The view server of g.gui.sbrt
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "view_server.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <new>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "format/block_summary.hpp"
#include "format/format_v2.hpp"
#include "frame/fitting_exaggeration.hpp"
#include "material_colors.hpp"
#include "sbrt_store.hpp"
#include "image_memory.hpp"
#include "reply_lines.hpp"
#include "model/material_table.hpp"
#include "property_colors.hpp"
#include "render_session.hpp"
#include "request_line.hpp"
#include "request_error.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace {

/// The longest request line read whole: anything longer is answered with
/// an error and skipped (a frame request is a few hundred bytes).
constexpr size_t MAX_LINE = 1 << 16;

/// \brief The server's session and the replies it writes.
class ViewServer {
public:
    explicit ViewServer(FILE *out) : out_(out) {}

    void render(RenderRequest request);
    void classes(const RenderRequest &request);
    void pick(RenderRequest request, int row, int col);
    void error(const std::string &message);

private:
    FILE *out_;
    RenderSession session_;
};

void ViewServer::render(RenderRequest request)
{
    const auto start = std::chrono::steady_clock::now();
    struct Cell_head region;
    G_get_window(&region); // a top view's, as g.region set it now
    session_.load(request, region);
    const sbrt::Camera camera = session_.cameras(request, region).front();
    const int rows = camera.rows(), cols = camera.cols();
    // the frame is kept whole for the reply
    sbrt::ImageNeeds needs;
    needs.kernel_normals = request.normals == sbrt::Normals::kernel;
    needs.whole_image_bytes_per_pixel = 3;
    sbrt::check_image_fits(rows, cols, needs);
    session_.prepare(request, camera, false);
    std::vector<uint8_t> rgb(size_t(rows) * size_t(cols) * 3);
    session_.render(camera, sbrt::Outputs{}, [&](const sbrt::Band &band) {
        for (int r = 0; r < band.rows; ++r)
            std::copy_n(band.rgb.row(r), size_t(cols) * 3,
                        rgb.begin() + long(band.first_row + r) * cols * 3);
    });
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();

    // the camera as azimuth=, elevation=, distance= and target=: the point
    // of its axis nearest the model's centre (what a framed view looks at)
    const sbrt::CoordinateFrame &frame = session_.frame();
    const glm::dvec3 eye = camera.origin(), forward = camera.forward();
    const glm::dvec3 at = eye + forward * glm::dot(frame.centre() - eye, forward);
    const glm::dvec3 target = frame.map_from_exaggerated(at);
    double azimuth = std::atan2(-forward.x, -forward.y) * 180 / M_PI;
    if (azimuth < 0)
        azimuth += 360;
    azimuth += 0.0; // never -0
    const double elevation = std::asin(std::clamp(-forward.z, -1.0, 1.0)) * 180 / M_PI;
    std::fprintf(out_, "frame %d %d %.3f %.17g %.17g %.17g %.17g %.17g %.17g", cols, rows,
                 ms, azimuth, elevation, glm::length(at - eye), target.x, target.y,
                 target.z);
    // a property view's legend: the ramp's ends and the unit, as the PNG's
    // colour bar shows them (the unit last: it may hold spaces)
    const sbrt::PropertyPaint *property = session_.property();
    if (property && !request.property.empty()) {
        const sbrt::ColorRamp &ramp = property->ramp();
        std::fprintf(out_, " property %.17g %.17g %s", ramp.low(), ramp.high(),
                     sbrt::record_field(property_unit(property->channels(),
                                                      property->summed()))
                         .c_str());
    }
    std::fputc('\n', out_);
    std::fwrite(rgb.data(), 1, rgb.size(), out_);
    std::fflush(out_);
}

/// \brief What the classes reply says of a model: its extent, the
/// exaggeration a request without zexag= gets, whether every top lies on
/// a voxel boundary (stairs that kernel normals smooth), its materials as
/// a render colours them.
struct ModelDescription {
    sbrt::Frame frame;
    double zexag = 1;
    bool voxels = false;
    std::vector<sbrt::Material> materials; ///< EMPTY first
};

/// The description of `request`'s SBRT from its block summaries, no block
/// decoded; nothing where it has none (format before 2.1) or has property
/// channels (their report checks them against the decoded model).
std::optional<ModelDescription> described_from_summaries(const RenderRequest &request)
{
    std::optional<sbrt::ModelSummary> summary =
        sbrt_grass::read_sbrt_summary_map(request.input.c_str());
    if (!summary || summary->has_channels)
        return std::nullopt;
    ModelDescription out;
    out.frame = summary->frame;
    out.zexag = request.zexag_fitted
                    ? sbrt::fitting_exaggeration(out.frame, summary->highest_top_local())
                    : request.zexag;
    out.voxels = summary->tops == sbrt::TopEncoding::VoxelBoundaries;
    out.materials = std::move(summary->materials);
    apply_color_option(request, out.materials);
    return out;
}

void ViewServer::classes(const RenderRequest &request)
{
    // from the summaries where it can: the viewer asks this first, and a
    // national model's decode of every block would hold its first frame
    // 1.3-1.9 s (issue 49)
    std::optional<ModelDescription> model = described_from_summaries(request);
    const sbrt::PropertyChannels *channels = nullptr;
    if (!model) {
        struct Cell_head region;
        G_get_window(&region);
        RenderRequest whole = request; // every block, whatever the view
        whole.view.kind = sbrt::ViewKind::perspective;
        whole.coarse = false; // the exact model's extent, classes and channels
        session_.load(whole, region);
        const sbrt::Model &loaded = session_.model();
        model = ModelDescription{loaded.frame(), whole.zexag,
                                 sbrt::widths_for(loaded).tops ==
                                     sbrt::TopEncoding::VoxelBoundaries,
                                 loaded.materials()};
        channels = session_.stored_channels(whole);
    }
    const sbrt::Frame &f = model->frame;
    std::fprintf(out_, "model %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d\n", f.north,
                 f.south, f.east, f.west, f.bottom, f.top, model->zexag, int(model->voxels));
    const std::vector<sbrt::Material> &materials = model->materials;
    std::fprintf(out_, "classes %zu\n", materials.size());
    // the colours a render draws (the palette's where a class has none),
    // by class id (a GeoTOP file lists its classes in its own order)
    std::vector<uint32_t> by_id(materials.size());
    for (uint32_t i = 0; i < by_id.size(); ++i)
        by_id[i] = i;
    std::stable_sort(by_id.begin(), by_id.end(), [&](uint32_t a, uint32_t b) {
        return materials[a].id < materials[b].id;
    });
    for (const uint32_t i : by_id)
        std::fputs(class_reply_line(materials[i], sbrt::material_color(materials, i)).c_str(),
                   out_);
    // the property channels: least and greatest value as meant, then
    // name|unit|long name
    const size_t count = channels ? channels->size() : 0;
    std::fprintf(out_, "channels %zu\n", count);
    for (size_t c = 0; c < count; ++c)
        std::fputs(channel_reply_line(channels->info(c)).c_str(), out_);
    std::fflush(out_);
}

void ViewServer::pick(RenderRequest request, int row, int col)
{
    // what the pixel hits, not how it is lit: kernel normals need the whole
    // image, and the pick traces one pixel of it
    request.normals = sbrt::Normals::face;
    request.smooth = 0;
    request.coarse = false; // what the exact model holds there
    struct Cell_head region;
    G_get_window(&region);
    session_.load(request, region);
    const sbrt::Camera camera = session_.cameras(request, region).front();
    if (row >= camera.rows() || col >= camera.cols())
        bad_request(_("pick: pixel (%d, %d) is outside the %d x %d view"), row, col,
                    camera.cols(), camera.rows());
    // that pixel alone, with the very ray it has in the whole view
    const sbrt::Camera pixel = camera.window(row, 1, col, 1);
    session_.prepare(request, pixel, false);
    sbrt::Outputs outputs;
    outputs.material = outputs.elevation = outputs.depth = true;
    outputs.value = !request.property.empty();
    int32_t material = sbrt::NULL_CLASS;
    double depth = NAN, value = NAN;
    session_.render(pixel, outputs, [&](const sbrt::Band &band) {
        material = band.material.row(0)[0];
        depth = band.depth.row(0)[0];
        if (!band.value.empty())
            value = band.value.row(0)[0];
    });
    if (material == sbrt::NULL_CLASS || !std::isfinite(depth)) {
        std::fprintf(out_, "hit none\n");
        std::fflush(out_);
        return;
    }
    // the hit in map coordinates: along the ray, unexaggerated
    const sbrt::CoordinateFrame &frame = session_.frame();
    const sbrt::Ray ray = camera.ray(row, col);
    const glm::dvec3 origin = frame.map_from_exaggerated(ray.origin);
    const glm::dvec3 along =
        glm::normalize(frame.map_from_exaggerated(ray.origin + ray.direction) - origin);
    const glm::dvec3 hit = origin + along * depth;
    std::fprintf(out_, "hit %.17g %.17g %.17g %d %.17g\n", hit.x, hit.y, hit.z, material,
                 value);
    std::fflush(out_);
}

void ViewServer::error(const std::string &message)
{
    std::fputs(error_reply_line(message).c_str(), out_);
    std::fflush(out_);
}

} // namespace

void serve_views(const OptionTable &options, FILE *in, FILE *out)
{
    RequestLineReader reader(options);
    ViewServer server(out);
    std::string text;
    for (;;) {
        // one line, read whole up to MAX_LINE bytes; the rest of a longer
        // one is skipped
        text.clear();
        bool too_long = false;
        int c;
        while ((c = std::fgetc(in)) != EOF && c != '\n') {
            if (text.size() < MAX_LINE)
                text.push_back(char(c));
            else
                too_long = true;
        }
        if (c == EOF && text.empty())
            break;
        if (!text.empty() && text.back() == '\r')
            text.pop_back();
        try {
            if (too_long)
                bad_request(_("the request line is longer than %zu bytes"), MAX_LINE);
            const RequestLine request = reader.read(text);
            if (request.verb == RequestLine::Verb::quit)
                break;
            if (request.verb == RequestLine::Verb::render)
                server.render(request.request);
            else if (request.verb == RequestLine::Verb::pick)
                server.pick(request.request, request.pick_row, request.pick_col);
            else
                server.classes(request.request);
        }
        catch (const std::bad_alloc &) {
            server.error(_("out of memory: ask for a smaller image (size=)"));
        }
        catch (const std::exception &e) {
            // answered, and the server goes on
            server.error(e.what());
        }
        if (c == EOF)
            break;
    }
}
