/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   CF flag_values + flag_meanings -> labels by class id
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/flag_legend.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "util/error.hpp"

namespace sbrt {

std::vector<Material> flag_legend(const std::vector<double> &values,
                                  const std::string &meanings)
{
    std::istringstream in(meanings);
    std::vector<std::string> words;
    for (std::string word; in >> word;)
        words.push_back(word);
    if (words.size() != values.size())
        fail("flag_values has ", values.size(), " value", values.size() == 1 ? "" : "s",
             " and flag_meanings ", words.size(), " word", words.size() == 1 ? "" : "s",
             "; CF pairs them one by one, so which label belongs to which class is "
             "unknown");
    std::vector<Material> labels;
    for (size_t i = 0; i < values.size(); ++i) {
        const double v = values[i];
        if (!(v == std::floor(v)) || v <= double(std::numeric_limits<int32_t>::min()) ||
            v > double(std::numeric_limits<int32_t>::max()))
            fail("flag_values holds ", v, ", which is no class (an integer of 32 bits)");
        Material m;
        m.id = int32_t(v);
        m.label = words[i];
        std::replace(m.label.begin(), m.label.end(), '_', ' ');
        labels.push_back(m);
    }
    return labels;
}

} // namespace sbrt
