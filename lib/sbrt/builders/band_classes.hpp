/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Value -> class of one sample type of a file variable's bands
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BAND_CLASSES_HPP
#define SBRT_BAND_CLASSES_HPP

#include <cstdint>
#include <type_traits>
#include <vector>

#include "builders/classifier.hpp"
#include "builders/missing_values.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief Value -> class of one band's type. 8- and 16-bit integers without
/// rules are classes as they are, looked up in a table that has the
/// missing values already; everything else goes through the classifier
/// (range checks, rules).
template <typename T>
class BandClasses {
public:
    BandClasses(const MissingValues &missing, Classifier &classifier)
        : missing_(missing), classifier_(classifier)
    {
        if constexpr (TABLED) {
            if (classifier.has_rules())
                return;
            table_.resize(size_t(1) << (8 * sizeof(T)));
            for (size_t u = 0; u < table_.size(); ++u) {
                const T value = T(u);
                table_[u] = missing.is_missing(double(value)) ? NULL_CLASS
                                                              : int32_t(value);
            }
        }
    }

    int32_t operator()(T value)
    {
        if constexpr (TABLED) {
            if (!table_.empty())
                return table_[std::make_unsigned_t<T>(value)];
        }
        const double v = double(value);
        return missing_.is_missing(v) ? NULL_CLASS : classifier_.classify(v);
    }

private:
    static constexpr bool TABLED = std::is_integral_v<T> && sizeof(T) <= 2;
    const MissingValues &missing_;
    Classifier &classifier_;
    std::vector<int32_t> table_;
};

} // namespace sbrt

#endif
