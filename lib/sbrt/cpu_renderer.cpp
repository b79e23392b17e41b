/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Multithreaded CPU rendering with the exact tracer
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "cpu_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>

#include "tracer.hpp"

namespace sbrt {

glm::dvec3 Shading::light_from(double azimuth, double elevation)
{
    const double az = azimuth * M_PI / 180, el = elevation * M_PI / 180;
    return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el),
            std::sin(el)};
}

std::array<uint8_t, 3> material_color(const Model &model, uint32_t material)
{
    const Material &m = model.materials()[material];
    if (m.has_color)
        return {m.red, m.green, m.blue};
    // golden-angle hues: neighbouring classes get distinct colours
    const double h = std::fmod(material * 137.508, 360.0) / 60.0;
    const double x = 1 - std::fabs(std::fmod(h, 2.0) - 1);
    const double rgb[6][3] = {{1, x, 0}, {x, 1, 0}, {0, 1, x},
                              {0, x, 1}, {x, 0, 1}, {1, 0, x}};
    const double *c = rgb[int(h) % 6];
    return {uint8_t(60 + 180 * c[0]), uint8_t(60 + 180 * c[1]),
            uint8_t(60 + 180 * c[2])};
}

Image render_cpu(const Model &model, const Camera &camera, double zexag,
                 const Shading &shading, unsigned threads)
{
    const Tracer tracer(model, zexag);
    Image image;
    image.rows = camera.rows();
    image.cols = camera.cols();
    const size_t pixels = size_t(image.rows) * image.cols;
    image.rgb.assign(pixels * 3, 0);
    image.material.assign(pixels, NULL_CLASS);
    image.elevation.assign(pixels, NAN);
    image.depth.assign(pixels, NAN);

    std::atomic<int> next_row{0};
    auto work = [&]() {
        for (int row; (row = next_row++) < image.rows;) {
            for (int col = 0; col < image.cols; ++col) {
                const size_t i = size_t(row) * image.cols + col;
                const Ray ray = camera.ray(row, col);
                const Hit hit = tracer.trace(ray);
                std::array<uint8_t, 3> rgb = shading.background;
                if (hit.is_hit()) {
                    const auto base = material_color(model, hit.material);
                    const double lambert =
                        std::max(0.0, glm::dot(shading.light, hit.normal));
                    const double intensity =
                        shading.ambient + (1 - shading.ambient) * lambert;
                    for (int k = 0; k < 3; ++k)
                        rgb[k] = uint8_t(std::lround(
                            std::clamp(base[k] * intensity, 0.0, 255.0)));
                    image.material[i] = model.materials()[hit.material].id;
                    image.elevation[i] = hit.point.z;
                    image.depth[i] = glm::length(
                        hit.point - tracer.unexaggerate(ray.origin));
                }
                for (int k = 0; k < 3; ++k)
                    image.rgb[i * 3 + k] = rgb[k];
            }
        }
    };
    if (threads == 0)
        threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread &t : pool)
        t.join();
    return image;
}

} // namespace sbrt
