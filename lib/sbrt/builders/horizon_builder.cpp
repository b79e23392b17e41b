/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Horizons -> SBRT with continuous heights
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/horizon_builder.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace sbrt {

HorizonStackBuilder::HorizonStackBuilder(const Frame &frame,
                                         std::vector<Material> units)
    : frame_(frame), effective_top_(units.size())
{
    frame_.validate("HorizonStackBuilder");
    if (units.empty())
        fail("HorizonStackBuilder: no horizons given");
    materials_.push_back(Material{NULL_CLASS, "EMPTY"});
    // units sharing a class id share one material
    for (const Material &unit : units) {
        if (unit.id == NULL_CLASS)
            fail("HorizonStackBuilder: a unit has no class id");
        auto same = std::find_if(
            materials_.begin() + 1, materials_.end(),
            [&](const Material &m) { return m.id == unit.id; });
        if (same == materials_.end()) {
            unit_material_.push_back(uint32_t(materials_.size()));
            materials_.push_back(unit);
        }
        else {
            unit_material_.push_back(uint32_t(same - materials_.begin()));
        }
    }
    offsets_.reserve(frame_.cells() + 1);
}

double HorizonStackBuilder::to_local(double z)
{
    const double local = frame_.local_z(z);
    if (local < 0 || local > frame_.depths) {
        ++clamped_;
        return std::clamp(local, 0.0, double(frame_.depths));
    }
    return local;
}

void HorizonStackBuilder::push(uint32_t material, double top)
{
    const float top32 = float(top);
    if (!intervals_.empty() && offsets_.back() < intervals_.size()) {
        Interval &last = intervals_.back();
        if (!(top32 > last.top))
            return; // rounds to zero thickness in float32
        if (last.material == material) {
            last.top = top32;
            return;
        }
    }
    if (intervals_.size() >= UINT32_MAX)
        fail("HorizonStackBuilder: more than 2^32-1 intervals");
    intervals_.push_back({material, top32});
}

void HorizonStackBuilder::add_row(const std::vector<const double *> &tops,
                                  const double *bottom)
{
    if (tops.size() != unit_material_.size())
        fail("HorizonStackBuilder: ", tops.size(), " horizons for ",
             unit_material_.size(), " units");
    if (row_ >= frame_.rows)
        fail("HorizonStackBuilder: more rows than the frame's ", frame_.rows);
    const size_t units = tops.size();
    for (int col = 0; col < frame_.cols; ++col) {
        // effective tops, top to bottom: no unit rises above the one above it
        double ceiling = frame_.depths;
        for (size_t i = 0; i < units; ++i) {
            const double z = tops[i][col];
            if (std::isnan(z)) {
                effective_top_[i] = NAN;
                continue;
            }
            ceiling = std::min(to_local(z), ceiling);
            effective_top_[i] = ceiling;
        }
        const double base =
            bottom && !std::isnan(bottom[col]) ? to_local(bottom[col]) : 0.0;

        // emit bottom-up: EMPTY below the base, then each unit with thickness
        if (base > 0)
            push(EMPTY, base);
        double reached = base;
        for (size_t k = units; k-- > 0;) {
            const double top = effective_top_[k];
            if (std::isnan(top) || !(top > reached))
                continue;
            push(unit_material_[k], top);
            reached = top;
        }
        // never store a trailing EMPTY interval
        if (intervals_.size() > offsets_.back() &&
            intervals_.back().material == EMPTY)
            intervals_.pop_back();
        offsets_.push_back(uint32_t(intervals_.size()));
    }
    ++row_;
}

Model HorizonStackBuilder::finish()
{
    if (row_ != frame_.rows)
        fail("HorizonStackBuilder: got ", row_, " rows, the frame has ",
             frame_.rows);
    return Model(frame_, std::move(materials_), std::move(offsets_),
                 std::move(intervals_));
}

} // namespace sbrt
