/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   What the three formats share: a point's status, its surface,
 *            the heights' datum, numbers as text, the material of an entry
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

const std::string &vertical_datum(const LogSource &source)
{
    return source.model.vertical_datum();
}

std::string elevation_reference(const LogSource &source)
{
    const std::string &datum = vertical_datum(source);
    return datum.empty() ? source.elevation_unit : source.elevation_unit + " " + datum;
}

std::optional<double> surface_of(const PointLog &point)
{
    if (!point.log || point.log->is_empty())
        return std::nullopt;
    // a log runs from the top of its highest layer: its first entry is a layer
    return point.log->entries.front().top;
}
