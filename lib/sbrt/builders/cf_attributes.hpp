/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The CF attributes of a file variable that change its numbers
 *            (scale_factor, add_offset, _FillValue, missing_value, the
 *            valid range), checked as untrusted input before any use, and
 *            a hint when a class variable looks like a probability
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CF_ATTRIBUTES_HPP
#define SBRT_CF_ATTRIBUTES_HPP

#include <cstddef>
#include <string>
#include <vector>

namespace sbrt {

/// \brief One attribute of a file variable as the file has it.
struct FileAttribute {
    bool present = false;
    bool numeric = false;       ///< false: text, or a compound
    std::vector<double> values; ///< the numbers, when numeric
    std::string text;           ///< the text, when a string
};

/// \brief What one attribute must hold to be used.
struct AttributeRule {
    const char *key;         ///< "scale_factor"
    const char *meaning;     ///< "the factor stored values are multiplied by"
    size_t min_count = 1, max_count = 1;
    bool nan_allowed = false; ///< NaN (a float's fill, as xarray writes it)
    bool zero_allowed = true;
};

/// The rules of the attributes read (scale_factor, add_offset, _FillValue,
/// missing_value, valid_range, valid_min, valid_max).
const AttributeRule &attribute_rule(const std::string &key);

/// \brief The numbers of `attribute` (none when it is absent). Throws
/// sbrt::Error "`where`: attribute KEY is ...; it must be ...; mend it
/// (ncatted ...) or delete it" when it is text, has too few or too many
/// values, or a value that is infinite, NaN or 0 where the rule refuses it.
/// `variable` is the variable's own name (for the ncatted example), `file`
/// its file.
std::vector<double> checked_numbers(const FileAttribute &attribute,
                                    const AttributeRule &rule, const std::string &where,
                                    const std::string &variable, const std::string &file);

/// \brief Why a variable imported as classes looks like a probability or
/// a percentage ("86 distinct values, units %"), or "" when it does not:
/// its units are "%" or "percent", or its name or long_name says
/// probability ("prob", "kans", "likelihood", "chance"). `classes` is the
/// number of distinct values it gave.
std::string probability_hint(const std::string &name, const std::string &long_name,
                             const std::string &units, size_t classes);

} // namespace sbrt

#endif
