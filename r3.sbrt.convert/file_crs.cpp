/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A file's CRS against the current location's (as r.in.gdal
 *            compares them; -o overrides)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "file_crs.hpp"

#include <ogr_spatialref.h>

#include <memory>

#include "grass.hpp"
extern "C" {
#include <grass/gprojects.h>
}

namespace {

std::string name_of(const OGRSpatialReference &srs)
{
    const char *name = srs.GetName();
    const char *authority = srs.GetAuthorityName(nullptr);
    const char *code = srs.GetAuthorityCode(nullptr);
    std::string s = name ? name : "unnamed CRS";
    if (authority && code)
        s += std::string(" (") + authority + ":" + code + ")";
    return s;
}

/// The location's CRS; nullptr for an XY location.
std::unique_ptr<OGRSpatialReference> location_crs()
{
    if (G_projection() == PROJECTION_XY)
        return nullptr;
    struct Key_Value *info = G_get_projinfo();
    struct Key_Value *units = G_get_projunits();
    struct Key_Value *epsg = G_get_projepsg();
    OGRSpatialReferenceH handle = GPJ_grass_to_osr2(info, units, epsg);
    G_free_key_value(info);
    G_free_key_value(units);
    G_free_key_value(epsg);
    if (!handle)
        return nullptr;
    return std::unique_ptr<OGRSpatialReference>(
        OGRSpatialReference::FromHandle(handle));
}

} // namespace

void check_file_crs(const FileVariable &variable, const std::string &file,
                    bool override_check)
{
    const std::shared_ptr<OGRSpatialReference> theirs = variable.spatial_ref();
    if (!theirs) {
        G_verbose_message(_("File <%s> names no CRS: its coordinates are taken "
                            "as the location's"),
                          file.c_str());
        return;
    }
    const std::unique_ptr<OGRSpatialReference> ours = location_crs();
    const char *criteria[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES",
                              "CRITERION=EQUIVALENT_EXCEPT_AXIS_ORDER_GEOGCRS",
                              nullptr};
    if (ours && ours->IsSame(theirs.get(), criteria))
        return;
    const std::string location =
        ours ? name_of(*ours) : std::string("XY (no CRS)");
    if (override_check) {
        G_warning(_("The CRS of file <%s>, %s, differs from the location's, "
                    "%s: coordinates taken as they are (-o)"),
                  file.c_str(), name_of(*theirs).c_str(), location.c_str());
        return;
    }
    G_fatal_error(_("The CRS of file <%s>, %s, differs from the location's, "
                    "%s. Import into a location with the file's CRS (e.g. "
                    "grass -c EPSG:code), or add -o to take the coordinates "
                    "as they are"),
                  file.c_str(), name_of(*theirs).c_str(), location.c_str());
}
