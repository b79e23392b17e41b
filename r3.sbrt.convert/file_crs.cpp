/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A file's CRS against the current location's (as r.in.gdal
 *            compares them; -o overrides)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "file_crs.hpp"
#include "format/format.hpp"

#include <cstring>

#include <ogr_spatialref.h>

#include <memory>

#include "grass.hpp"
#include "util/safe_text.hpp"
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

/// A CRS from a user string (EPSG:code, WKT); nullptr where GDAL cannot
/// read it.
std::unique_ptr<OGRSpatialReference> crs_from(const char *text)
{
    if (!text || !*text)
        return nullptr;
    auto srs = std::make_unique<OGRSpatialReference>();
    srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (srs->SetFromUserInput(text) != OGRERR_NONE)
        return nullptr;
    return srs;
}

/// A string GRASS allocated, freed with G_free.
struct GrassString {
    char *text;
    ~GrassString() { G_free(text); }
};

/// The location's CRS; nullptr for an XY location. GRASS 8 keeps the code
/// (PROJ_SRID) and the WKT (PROJ_WKT) a location was made from: these name
/// the CRS, where PROJ_INFO through GPJ_grass_to_osr2 gives an "unknown" one.
std::unique_ptr<OGRSpatialReference> location_crs()
{
    if (G_projection() == PROJECTION_XY)
        return nullptr;
    for (char *(*read)(void) : {G_get_projsrid, G_get_projwkt}) {
        const GrassString text{read()};
        if (auto srs = crs_from(text.text))
            return srs;
    }
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

/// The horizontal part of a compound CRS (EPSG:7415 -> EPSG:28992): a
/// GRASS location has no vertical CRS, so heights are not compared.
std::shared_ptr<OGRSpatialReference>
horizontal_part(const std::shared_ptr<OGRSpatialReference> &srs)
{
    if (!srs->IsCompound())
        return srs;
    auto horizontal = std::make_shared<OGRSpatialReference>(*srs);
    if (horizontal->StripVertical() != OGRERR_NONE)
        return srs;
    return horizontal;
}

} // namespace

void check_file_crs(const FileVariable &variable, const std::string &file,
                    bool override_check)
{
    const std::shared_ptr<OGRSpatialReference> full = variable.spatial_ref();
    if (!full) {
        G_verbose_message(_("File <%s> names no CRS: its coordinates are taken "
                            "as the location's"),
                          file.c_str());
        return;
    }
    const std::shared_ptr<OGRSpatialReference> theirs = horizontal_part(full);
    if (theirs != full)
        G_verbose_message(_("File <%s> names the compound CRS %s; its "
                            "horizontal part, %s, is compared with the "
                            "location's"),
                          file.c_str(), name_of(*full).c_str(),
                          name_of(*theirs).c_str());
    const std::unique_ptr<OGRSpatialReference> ours = location_crs();
    const char *criteria[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES",
                              "CRITERION=EQUIVALENT_EXCEPT_AXIS_ORDER_GEOGCRS",
                              nullptr};
    if (ours && ours->IsSame(theirs.get(), criteria))
        return;
    const std::string location =
        ours ? name_of(*ours) : std::string("XY (no CRS)");
    const std::string file_crs =
        theirs == full ? name_of(*full)
                       : name_of(*full) + ", horizontally " + name_of(*theirs);
    if (override_check) {
        G_warning(_("The CRS of file <%s>, %s, differs from the location's, "
                    "%s: coordinates taken as they are (-o)"),
                  file.c_str(), file_crs.c_str(), location.c_str());
        return;
    }
    G_fatal_error(_("The CRS of file <%s>, %s, differs from the location's, "
                    "%s. Import into a location with the file's CRS (e.g. "
                    "grass -c EPSG:code), or add -o to take the coordinates "
                    "as they are"),
                  file.c_str(), file_crs.c_str(), location.c_str());
}

std::string vertical_datum(const FileVariable &variable)
{
    const std::shared_ptr<OGRSpatialReference> srs = variable.spatial_ref();
    if (!srs || !srs->IsCompound())
        return {};
    const char *name = srs->GetAttrValue("COMPD_CS|VERT_CS");
    if (!name)
        return {};
    // EPSG names vertical CRSs "<datum> height" or "<datum> depth"
    std::string datum = name;
    for (const char *suffix : {" height", " depth"}) {
        const size_t n = std::strlen(suffix);
        if (datum.size() > n && datum.compare(datum.size() - n, n, suffix) == 0)
            datum.erase(datum.size() - n);
    }
    // a CRS name is the file's text: one printable line, or no datum
    if (datum.size() > sbrt::MAX_DATUM_CHARS || sbrt::printable(datum) != datum) {
        G_warning(_("The vertical CRS's name of the file (%s) is no short line of "
                    "printable text: the model gets no vertical datum"),
                  sbrt::printable(sbrt::fit_bytes(datum, sbrt::MAX_DATUM_CHARS)).c_str());
        return {};
    }
    return datum;
}
