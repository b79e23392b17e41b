/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   CIEDE2000 colour difference and sRGB -> L*a*b*
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/ciede2000.hpp"

#include <cmath>

namespace sbrt {

namespace {

constexpr double PI = 3.14159265358979323846;

double degrees(double radians) { return radians * 180.0 / PI; }
double radians(double degrees) { return degrees * PI / 180.0; }

/// sRGB channel (0-255) -> linear light (IEC 61966-2-1).
double linear(uint8_t channel)
{
    const double c = channel / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// f(t) of CIE 15 for L*a*b*.
double lab_f(double t)
{
    const double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3 * delta * delta) + 4.0 / 29.0;
}

/// Hue angle in degrees [0, 360) of (a, b); 0 where both are 0 (eq. 7).
double hue(double b, double a)
{
    if (a == 0 && b == 0)
        return 0;
    const double h = degrees(std::atan2(b, a));
    return h < 0 ? h + 360 : h;
}

} // namespace

Lab srgb_to_lab(const std::array<uint8_t, 3> &rgb)
{
    const double r = linear(rgb[0]), g = linear(rgb[1]), b = linear(rgb[2]);
    // sRGB primaries -> XYZ, relative to the D65 white (Xn, Yn, Zn)
    const double x = (0.4124564 * r + 0.3575761 * g + 0.1804375 * b) / 0.95047;
    const double y = (0.2126729 * r + 0.7151522 * g + 0.0721750 * b) / 1.0;
    const double z = (0.0193339 * r + 0.1191920 * g + 0.9503041 * b) / 1.08883;
    const double fx = lab_f(x), fy = lab_f(y), fz = lab_f(z);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

double ciede2000(const Lab &x, const Lab &y)
{
    // C'_i and h'_i (eqs. 2-7)
    const double c1 = std::hypot(x.a, x.b), c2 = std::hypot(y.a, y.b);
    const double c_mean = (c1 + c2) / 2;
    const double c7 = std::pow(c_mean, 7);
    const double g = 0.5 * (1 - std::sqrt(c7 / (c7 + std::pow(25.0, 7))));
    const double a1 = (1 + g) * x.a, a2 = (1 + g) * y.a;
    const double cp1 = std::hypot(a1, x.b), cp2 = std::hypot(a2, y.b);
    const double hp1 = hue(x.b, a1), hp2 = hue(y.b, a2);

    // dL', dC', dH' (eqs. 8-11)
    const double dl = y.l - x.l, dc = cp2 - cp1;
    double dh = 0;
    if (cp1 * cp2 != 0) {
        dh = hp2 - hp1;
        if (dh > 180)
            dh -= 360;
        else if (dh < -180)
            dh += 360;
    }
    const double d_big_h = 2 * std::sqrt(cp1 * cp2) * std::sin(radians(dh / 2));

    // means and weighting functions (eqs. 12-21)
    const double l_mean = (x.l + y.l) / 2, cp_mean = (cp1 + cp2) / 2;
    double hp_mean = hp1 + hp2;
    if (cp1 * cp2 != 0) {
        if (std::fabs(hp1 - hp2) <= 180)
            hp_mean /= 2;
        else
            hp_mean = hp_mean < 360 ? (hp_mean + 360) / 2 : (hp_mean - 360) / 2;
    }
    const double t = 1 - 0.17 * std::cos(radians(hp_mean - 30)) +
                     0.24 * std::cos(radians(2 * hp_mean)) +
                     0.32 * std::cos(radians(3 * hp_mean + 6)) -
                     0.20 * std::cos(radians(4 * hp_mean - 63));
    const double d_theta = 30 * std::exp(-std::pow((hp_mean - 275) / 25, 2));
    const double cp7 = std::pow(cp_mean, 7);
    const double rc = 2 * std::sqrt(cp7 / (cp7 + std::pow(25.0, 7)));
    const double l50 = (l_mean - 50) * (l_mean - 50);
    const double sl = 1 + 0.015 * l50 / std::sqrt(20 + l50);
    const double sc = 1 + 0.045 * cp_mean;
    const double sh = 1 + 0.015 * cp_mean * t;
    const double rt = -std::sin(radians(2 * d_theta)) * rc;

    // eq. 22
    const double tl = dl / sl, tc = dc / sc, th = d_big_h / sh;
    return std::sqrt(tl * tl + tc * tc + th * th + rt * tc * th);
}

double ciede2000(const std::array<uint8_t, 3> &x, const std::array<uint8_t, 3> &y)
{
    return ciede2000(srgb_to_lab(x), srgb_to_lab(y));
}

} // namespace sbrt
