/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The outputs of an animation's frames, the dataset and the video
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "frames.hpp"
#include "request_error.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>


namespace {

/// The widest frame number field of a png= pattern (a frame number has at
/// most 10 digits).
constexpr int MAX_FRAME_DIGITS = 10;

std::string numbered(const std::string &name, int frame)
{
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "_%04d", frame);
    return name + suffix;
}

/// Position and length of the %d conversion of a pattern (npos: none).
std::pair<size_t, size_t> conversion(const std::string &png)
{
    const size_t at = png.find('%');
    if (at == std::string::npos)
        return {at, 0};
    size_t end = at + 1;
    while (end < png.size() && (std::isdigit(png[end]) || png[end] == '0'))
        ++end;
    if (end >= png.size() || png[end] != 'd' || png.find('%', end) != std::string::npos)
        bad_request(_("png=%s: a pattern takes one %%d (e.g. orbit_%%04d.png) and "
                      "no other %%"),
                    shortened(png).c_str());
    // a frame number has at most 10 digits: a wider field only pads the
    // name (%99999999d made one file of spaces for every frame)
    const std::string digits = png.substr(at + 1, end - at - 1);
    if (digits.size() > 2 || (!digits.empty() && std::atoi(digits.c_str()) > MAX_FRAME_DIGITS))
        bad_request(_("png=%s: the frame number's width %%%sd is too wide; at most "
                      "%%0%dd (e.g. orbit_%%04d.png)"),
                    shortened(png).c_str(), shortened(digits, 20).c_str(),
                    MAX_FRAME_DIGITS);
    return {at, end + 1 - at};
}

/// png= as a printf pattern of the frame number: as given, else with _%04d
/// before the extension (the names ffmpeg reads too).
std::string png_pattern(const std::string &png)
{
    if (conversion(png).first != std::string::npos)
        return png;
    const size_t slash = png.rfind('/');
    const size_t dot = png.rfind('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return png + "_%04d";
    return png.substr(0, dot) + "_%04d" + png.substr(dot);
}

std::string png_of_frame(const std::string &png, int frame)
{
    const std::string pattern = png_pattern(png);
    std::vector<char> path(pattern.size() + 32);
    std::snprintf(path.data(), path.size(), pattern.c_str(), frame);
    return path.data();
}

bool file_exists(const std::string &path)
{
    struct stat st;
    return stat(path.c_str(), &st) == 0;
}

bool raster_exists(const std::string &name)
{
    return G_find_raster2(name.c_str(), G_mapset()) != nullptr;
}

/// Whether `program` is an executable on the PATH.
bool on_path(const char *program)
{
    const char *path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':'))
        if (!dir.empty() && access((dir + "/" + program).c_str(), X_OK) == 0)
            return true;
    return false;
}

/// Runs a command (argv, null-terminated); its exit status.
int run_command(std::vector<const char *> argv)
{
    argv.push_back(nullptr);
    return G_vspawn_ex(argv[0], argv.data());
}

std::string extension(const std::string &path)
{
    const size_t dot = path.rfind('.');
    return dot == std::string::npos ? "" : path.substr(dot + 1);
}

} // namespace

RenderRequest frame_request(const RenderRequest &request, int frame)
{
    if (request.frames == 1)
        return request;
    RenderRequest r = request;
    for (std::string *name : {&r.output, &r.material, &r.hit_elevation, &r.depth, &r.value})
        if (!name->empty())
            *name = numbered(*name, frame);
    if (!r.png.empty())
        r.png = png_of_frame(request.png, frame);
    return r;
}

void check_png_pattern(const std::string &png)
{
    if (!png.empty())
        conversion(png);
}

bool frame_finished(const RenderRequest &frame)
{
    std::vector<std::string> maps = {frame.material, frame.hit_elevation, frame.depth,
                                     frame.value};
    if (!frame.output.empty())
        for (const char *suffix : {"", ".red", ".green", ".blue"})
            maps.push_back(frame.output + suffix);
    for (const std::string &map : maps)
        if (!map.empty() && !raster_exists(map))
            return false;
    return frame.png.empty() || file_exists(frame.png);
}

void check_video(const RenderRequest &request)
{
    if (request.video.empty())
        return;
    const std::string ext = extension(request.video);
    if (ext != "mp4" && ext != "webm" && ext != "gif")
        bad_request(_("video=%s: give a .mp4, .webm or .gif file"),
                      request.video.c_str());
    if (request.png.empty())
        bad_request(_("video= is made of the frames' PNG files: give png= (e.g. "
                      "png=orbit_%%04d.png), or render every frame in one run"));
    if (!on_path("ffmpeg"))
        bad_request(_("video=%s needs ffmpeg, which is not on the PATH: install "
                        "it (Debian: apt-get install ffmpeg), or leave video= out "
                        "and assemble the PNG files yourself"),
                      request.video.c_str());
}

void register_frames(const RenderRequest &request)
{
    if (request.strds.empty())
        return;
    // t.create fails on an existing dataset: a later range= run adds to it
    std::string maps;
    for (int k = request.first_frame; k <= request.last_frame; ++k)
        maps += (maps.empty() ? "" : ",") + frame_request(request, k).output;
    const std::string output = "output=" + request.strds;
    const std::string input = "input=" + request.strds;
    const std::string map_list = "maps=" + maps;
    const std::string start = "start=" + std::to_string(request.first_frame - 1);
    const bool exists =
        G_spawn_ex("t.info", "t.info", "-g", "--quiet", "type=strds", input.c_str(),
                   SF_REDIRECT_FILE, SF_STDOUT, SF_MODE_OUT, "/dev/null",
                   SF_REDIRECT_FILE, SF_STDERR, SF_MODE_OUT, "/dev/null",
                   static_cast<const char *>(nullptr)) == 0;
    if (!exists &&
        run_command({"t.create", "--quiet", "type=strds", "temporaltype=relative",
                     output.c_str(), "title=r3.sbrt.render frames",
                     "description=Frames of an r3.sbrt.render animation"}) != 0)
        bad_request(_("strds=%s: t.create failed (see above)"), request.strds.c_str());
    if (run_command({"t.register", "--quiet", "--overwrite", "type=raster",
                     input.c_str(), map_list.c_str(), start.c_str(), "unit=seconds",
                     "increment=1"}) != 0)
        bad_request(_("strds=%s: t.register failed (see above)"),
                      request.strds.c_str());
}

void assemble_video(const RenderRequest &request)
{
    if (request.video.empty())
        return;
    for (int k = 1; k <= request.frames; ++k)
        if (!file_exists(frame_request(request, k).png)) {
            // jobs of range= in parallel: the one that finds all frames
            // makes the video
            G_message(_("video=%s: frame %d is not rendered yet; a run that "
                        "completes the frames makes the video"),
                      request.video.c_str(), k);
            return;
        }
    // ffmpeg reads a numbered sequence through a printf pattern
    const std::string pattern = png_pattern(request.png);
    const std::string fps = std::to_string(request.fps);
    const std::string ext = extension(request.video);
    // even sizes for yuv420p; a GIF gets its own palette
    const char *filter =
        ext == "gif" ? "split[a][b];[a]palettegen[p];[b][p]paletteuse"
                     : "scale=trunc(iw/2)*2:trunc(ih/2)*2";
    std::vector<const char *> argv = {"ffmpeg", "-y", "-loglevel", "error",
                                      "-framerate", fps.c_str(), "-start_number", "1",
                                      "-i", pattern.c_str(), "-vf", filter};
    if (ext == "mp4")
        argv.insert(argv.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p"});
    else if (ext == "webm")
        argv.insert(argv.end(), {"-c:v", "libvpx-vp9", "-pix_fmt", "yuv420p"});
    const std::string temp = request.video + ".tmp." + ext;
    argv.push_back(temp.c_str());
    G_message(_("Assembling %d frames into <%s>..."), request.frames,
              request.video.c_str());
    if (run_command(argv) != 0) {
        std::remove(temp.c_str());
        bad_request(_("ffmpeg could not make video=%s (see above)"),
                      request.video.c_str());
    }
    if (std::rename(temp.c_str(), request.video.c_str()) != 0)
        bad_request(_("Cannot move the video into place as <%s>"),
                      request.video.c_str());
}

TemporaryFrames::TemporaryFrames(const RenderRequest &request) : frames_(request.frames)
{
    if (request.first_frame != 1 || request.last_frame != request.frames)
        bad_request(_("video= without png= keeps its frames only for this run: "
                      "render all %d frames (no range=), or give png= so that the "
                      "runs of range= share their frames"),
                    request.frames);
    // a folder in the mapset's temporary directory (removed by GRASS too
    // where a run is killed)
    char *name = G_tempfile();
    folder_ = name;
    G_free(name);
    if (mkdir(folder_.c_str(), 0700) != 0)
        bad_request(_("Cannot make a folder for the video's frames <%s>: %s"),
                    folder_.c_str(), std::strerror(errno));
    png_ = folder_ + "/frame_%04d.png";
}

TemporaryFrames::~TemporaryFrames()
{
    for (int k = 1; k <= frames_; ++k)
        std::remove(png_of_frame(png_, k).c_str());
    rmdir(folder_.c_str());
}
