/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The default palette of classes without a colour of their own:
 *            any PALETTE_SIZE first entries are distinguishable (nearest
 *            pair at least PALETTE_MIN_DE00 apart in CIEDE2000)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PALETTE_HPP
#define SBRT_PALETTE_HPP

#include <array>
#include <cstddef>
#include <cstdint>

namespace sbrt {

/// Entries of the palette whose distances are guaranteed.
constexpr size_t PALETTE_SIZE = 30;
/// The stated distance: for every n <= PALETTE_SIZE, the nearest pair of
/// entries 0 .. n-1 differs by at least this much (CIEDE2000; 1 is about
/// the smallest difference a person sees side by side, 10 an obviously
/// different colour). Checked by testsuite/unit/model/test_palette.cpp.
constexpr double PALETTE_MIN_DE00 = 15.0;

/// \brief Entry `k` (0, 1, ...) of the default palette. Beyond
/// PALETTE_SIZE the entries are golden-angle hues, distinct from their
/// neighbours but with no stated distance.
std::array<uint8_t, 3> palette_color(size_t k);

} // namespace sbrt

#endif
