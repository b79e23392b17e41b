/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   What the three formats share: a point's status, numbers as
 *            text, the material of an entry
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "log_writers.hpp"

#include <cmath>

const char *point_status(const PointLog &point)
{
    if (!point.log)
        return "outside";
    return point.log->is_empty() ? "empty" : "ok";
}

std::string number_text(double value)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.15g", value == 0 ? 0.0 : value); // no "-0"
    return text;
}

std::string value_text(double value, const char *none)
{
    return std::isfinite(value) ? number_text(value) : std::string(none);
}

const sbrt::Material &material_of(const sbrt::Model &model, uint32_t material)
{
    return model.materials()[material];
}
