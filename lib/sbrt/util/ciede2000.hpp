/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Colour difference CIEDE2000 (CIE 142-2001) between sRGB
 *            colours, after Sharma, Wu and Dalal (2005), "The CIEDE2000
 *            color-difference formula: implementation notes, supplementary
 *            test data, and mathematical observations", Color Research and
 *            Application 30(1)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CIEDE2000_HPP
#define SBRT_CIEDE2000_HPP

#include <array>
#include <cstdint>

namespace sbrt {

/// \brief A colour in CIE L*a*b* (D65 white).
struct Lab {
    double l = 0, a = 0, b = 0;
};

/// sRGB (IEC 61966-2-1, 8 bits a channel) -> CIE L*a*b* under D65.
Lab srgb_to_lab(const std::array<uint8_t, 3> &rgb);

/// \brief CIEDE2000 difference of two L*a*b* colours (kL = kC = kH = 1),
/// equations (1)-(23) of Sharma et al. (2005).
double ciede2000(const Lab &x, const Lab &y);

/// CIEDE2000 difference of two sRGB colours.
double ciede2000(const std::array<uint8_t, 3> &x, const std::array<uint8_t, 3> &y);

} // namespace sbrt

#endif
