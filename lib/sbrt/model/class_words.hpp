/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The words that name classes in rules files and list options:
 *            trimmed, compared without regard to case, class ids
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CLASS_WORDS_HPP
#define SBRT_CLASS_WORDS_HPP

#include <cstdint>
#include <string>

namespace sbrt {

/// `text` without leading and trailing blanks (space, tab, CR, LF).
std::string trim(const std::string &text);

/// Whether `a` and `b` are the same text but for the case of ASCII letters.
bool same_text(const std::string &a, const std::string &b);

/// The class id `text` (trimmed) spells: a whole decimal integer of 32
/// bits that is not NULL_CLASS; false where it is none.
bool parse_class_id(const std::string &text, int32_t &id);

} // namespace sbrt

#endif
