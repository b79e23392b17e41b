/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The view server of g.gui.sbrt
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "view_server.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "backend.hpp"
#include "util/error.hpp"
#include "material_colors.hpp"
#include "option_answers.hpp"
#include "prepared_scene.hpp"
#include "sbrt_store.hpp"
#include "scene_camera.hpp"
#include "scene_setup.hpp"
#include "texture_input.hpp"

namespace {

/// Options that move the camera, light the scene or name outputs: the
/// prepared scene does not depend on them (sections face the camera: their
/// planes are compared as computed; the shading is set for every frame).
const std::set<std::string> camera_keys = {
    "size", "position", "target", "azimuth", "elevation", "distance", "fov",
    "ortho_height", "view", "output", "material", "hit_elevation", "depth", "png", "-n",
    "light", "ambient", "background", "normals", "kernel", "smooth"};

/// The words of a request that shape its scene, in one string.
std::string scene_words(const std::vector<std::string> &words)
{
    std::vector<std::string> kept;
    for (const std::string &word : words)
        if (!camera_keys.count(word.substr(0, word.find('='))))
            kept.push_back(word);
    std::sort(kept.begin(), kept.end());
    std::string key;
    for (const std::string &word : kept)
        key += word + '\n';
    return key;
}

/// The planes and split direction the camera gives the scene, in one
/// string (exact: hexadecimal floats).
std::string camera_dependent_scene(const RenderRequest &request, const sbrt::Camera &camera)
{
    std::ostringstream key;
    key << std::hexfloat;
    for (const sbrt::ClipPlane &p : clip_planes(request, camera))
        key << p.point.x << ' ' << p.point.y << ' ' << p.point.z << ' ' << p.normal.x
            << ' ' << p.normal.y << ' ' << p.normal.z << '\n';
    if (request.split_logs)
        key << camera.du().x << ' ' << camera.du().y << '\n';
    return key.str();
}

/// \brief The server's state: the model as read, the framing tracer, the
/// drape and the prepared renderer, each rebuilt only when what it
/// depends on changes.
class ViewServer {
public:
    explicit ViewServer(FILE *out) : out_(out) {}

    void render(const RenderRequest &request, const std::vector<std::string> &words);
    void classes(const RenderRequest &request);

private:
    void load(const RenderRequest &request);
    void prepare(const RenderRequest &request, const sbrt::Camera &camera,
                 const std::string &key);

    FILE *out_;
    struct Cell_head region_;
    std::string model_key_;
    std::unique_ptr<sbrt::Model> model_; ///< as read, colours applied
    double framing_zexag_ = 0;
    std::unique_ptr<sbrt::Tracer> framing_; ///< its box only
    std::string drape_key_;
    std::unique_ptr<sbrt::Drape> drape_;
    std::string context_key_;
    std::unique_ptr<sbrt_gl::GlContext> context_;
    // the prepared scene: the backend refers to the request and renderer
    std::string scene_key_;
    std::unique_ptr<RenderRequest> scene_request_;
    std::unique_ptr<sbrt::Renderer> renderer_;
    std::unique_ptr<Backend> backend_;
};

void ViewServer::load(const RenderRequest &request)
{
    const std::string key = request.input + '\n' + request.color + '\n' + request.rules;
    if (model_ && key == model_key_)
        return;
    backend_.reset();
    renderer_.reset();
    drape_.reset();
    framing_.reset();
    scene_key_.clear();
    drape_key_.clear();
    model_ = std::make_unique<sbrt::Model>(sbrt_grass::read_sbrt_map(request.input.c_str()));
    apply_color_option(request, *model_);
    model_key_ = key;
}

void ViewServer::prepare(const RenderRequest &request, const sbrt::Camera &camera,
                         const std::string &key)
{
    backend_.reset();
    renderer_.reset();
    std::ostringstream drape_key;
    drape_key << std::hexfloat << request.texture_blend;
    for (const std::string &map : request.texture)
        drape_key << ',' << map;
    if (drape_key.str() != drape_key_) {
        drape_.reset();
        drape_key_.clear();
        if (!request.texture.empty())
            drape_ = std::make_unique<sbrt::Drape>(*model_, read_texture(request.texture),
                                                   request.texture_blend);
        drape_key_ = drape_key.str();
    }
    PreparedScene prepared = prepare_scene(request, *model_, camera);
    if (request.backend != context_key_) {
        context_.reset(); // before another on the same display
        context_key_.clear();
        context_ = choose_gl_context(request);
        context_key_ = request.backend;
    }
    scene_request_ = std::make_unique<RenderRequest>(request);
    renderer_ = std::make_unique<sbrt::Renderer>(
        std::move(prepared.model), request.zexag, std::move(prepared.scene),
        make_shading(request, drape_.get()),
        sbrt::RenderSettings{unsigned(request.threads), true, 0});
    backend_ = std::make_unique<Backend>(*scene_request_, *renderer_, context_.get());
    scene_key_ = key;
}

void ViewServer::render(const RenderRequest &request, const std::vector<std::string> &words)
{
    load(request);
    if (!framing_ || framing_zexag_ != request.zexag) {
        // the camera frames the model as read, whatever is hidden or cut
        sbrt::Scene box_only;
        box_only.skip_empty_space = false;
        framing_ = std::make_unique<sbrt::Tracer>(*model_, request.zexag, box_only);
        framing_zexag_ = request.zexag;
    }
    const auto start = std::chrono::steady_clock::now();
    G_get_window(&region_); // a top view's, as g.region set it now
    const sbrt::Camera camera = make_camera(request, *framing_, region_);
    const std::string key = scene_words(words) + camera_dependent_scene(request, camera);
    if (!renderer_ || key != scene_key_)
        prepare(request, camera, key);
    renderer_->set_shading(make_shading(request, drape_.get()));

    const int rows = camera.rows(), cols = camera.cols();
    std::vector<uint8_t> rgb(size_t(rows) * size_t(cols) * 3);
    backend_->render(camera, sbrt::Outputs{}, [&](const sbrt::Band &band) {
        std::copy(band.rgb.begin(), band.rgb.end(),
                  rgb.begin() + long(band.first_row) * cols * 3);
    });
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();

    // the camera as azimuth=, elevation=, distance= and target=: the point
    // of its axis nearest the model's centre (what a framed view looks at)
    const glm::dvec3 eye = camera.origin(), forward = camera.forward();
    const glm::dvec3 at = eye + forward * glm::dot(framing_->centre() - eye, forward);
    const glm::dvec3 target = framing_->unexaggerate(at);
    double azimuth = std::atan2(-forward.x, -forward.y) * 180 / M_PI;
    if (azimuth < 0)
        azimuth += 360;
    azimuth += 0.0; // never -0
    const double elevation = std::asin(std::clamp(-forward.z, -1.0, 1.0)) * 180 / M_PI;
    std::fprintf(out_, "frame %d %d %.3f %.17g %.17g %.17g %.17g %.17g %.17g\n", cols, rows,
                 ms, azimuth, elevation, glm::length(at - eye), target.x, target.y,
                 target.z);
    std::fwrite(rgb.data(), 1, rgb.size(), out_);
    std::fflush(out_);
}

void ViewServer::classes(const RenderRequest &request)
{
    load(request);
    const sbrt::Frame &f = model_->frame();
    std::fprintf(out_, "model %.17g %.17g %.17g %.17g %.17g %.17g\n", f.north, f.south,
                 f.east, f.west, f.bottom, f.top);
    std::fprintf(out_, "classes %zu\n", model_->materials().size());
    for (const sbrt::Material &m : model_->materials()) {
        std::string label = m.label;
        std::replace(label.begin(), label.end(), '\n', ' ');
        std::fprintf(out_, "%d %d %d %d %s\n", m.id, m.red, m.green, m.blue, label.c_str());
    }
    std::fflush(out_);
}

} // namespace

void serve_views(const RenderOptions &options, FILE *in, FILE *out)
{
    OptionAnswers answers(options.input, options.plain_png);
    ViewServer server(out);
    char *line = nullptr;
    size_t capacity = 0;
    while (getline(&line, &capacity, in) > 0) {
        std::vector<std::string> words;
        try {
            std::string text = line;
            while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
                text.pop_back();
            words = split_words(text);
            if (words.empty())
                continue;
            if (words[0] == "quit")
                break;
            if (words[0] != "render" && words[0] != "classes")
                sbrt::fail("unknown request <" + words[0] + ">: render, classes or quit");
            const std::string verb = words[0];
            words.erase(words.begin());
            answers.answer(words);
            if (!options.input->answer)
                sbrt::fail("the request names no input=");
            const RenderRequest request = read_render_options(options);
            // one frame of a view: what makes sequences and tiles, and
            // rules from stdin (the requests' stream), is the command line's
            if (request.frames != 1 || request.tile || request.rules == "-")
                sbrt::fail("frames=, tile= and rules=- are for the command line, "
                           "not the view server");
            if (verb == "render")
                server.render(request, words);
            else
                server.classes(request);
        }
        catch (const sbrt::Error &e) {
            // answered, and the server goes on (what the command line
            // stops at with G_fatal_error ends the server too)
            std::string message = e.what(); // one line: the protocol's
            std::replace(message.begin(), message.end(), '\n', ' ');
            std::fprintf(out, "error %s\n", message.c_str());
            std::fflush(out);
        }
    }
    std::free(line);
}
