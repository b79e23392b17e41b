/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Clip planes, cross section and fence of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "sections_part.hpp"

#include <algorithm>
#include <sstream>

#include "input_part.hpp"
#include "request_error.hpp"
#include "scene/scene_parts.hpp"

void SectionsPart::define(OptionTable &table)
{
    Option *o = table.define("plane", TYPE_DOUBLE,
                             _("Clip planes: a point and a normal each; the side the "
                               "normal points to is removed"),
                             _("Sections"));
    o->multiple = YES;
    o->key_desc = "x,y,z,nx,ny,nz";
    o = table.define("section", TYPE_DOUBLE,
                     _("Vertical cross section through two points: the side "
                       "facing the camera is removed"),
                     _("Sections"));
    o->key_desc = "x1,y1,x2,y2";
    o = table.define_standard(G_OPT_V_INPUT, "fence",
                              _("Draws only the vertical curtains below its "
                                "lines (with boreholes= the cylinders too)"),
                              _("Sections"));
    o->label = _("Vector line map of a fence diagram");
}

void SectionsPart::read(const Answers &a)
{
    const std::vector<double> plane = a.numbers("plane");
    if (plane.size() % 6)
        bad_request(_("plane= takes six numbers per plane (x,y,z,nx,ny,nz), "
                      "not %zu"),
                    plane.size());
    if (plane.size() / 6 > size_t(sbrt::MAX_CLIP_PLANES))
        bad_request(_("plane= gives %zu planes; at most %d"), plane.size() / 6,
                    sbrt::MAX_CLIP_PLANES);
    for (size_t i = 0; i < plane.size(); i += 6) {
        std::array<double, 6> p;
        std::copy_n(plane.begin() + long(i), 6, p.begin());
        if (p[3] == 0 && p[4] == 0 && p[5] == 0)
            bad_request(_("plane=%g,%g,%g,%g,%g,%g: the normal is zero"), p[0], p[1], p[2],
                        p[3], p[4], p[5]);
        planes.push_back(p);
    }
    const std::vector<double> s = a.numbers("section");
    if (!s.empty()) {
        if (s.size() != 4)
            bad_request(_("section= takes four numbers x1,y1,x2,y2"));
        if (s[0] == s[2] && s[1] == s[3])
            bad_request(_("section=: the two points are the same"));
        section = {s[0], s[1], s[2], s[3]};
        if (planes.size() + 1 > size_t(sbrt::MAX_CLIP_PLANES))
            bad_request(_("plane= and section= give more than %d planes"),
                        sbrt::MAX_CLIP_PLANES);
    }
    fence = a.text("fence");
    check_map_name("fence", fence);
}

std::vector<sbrt::ClipPlane> SectionsPart::clip_planes(const sbrt::Camera &camera) const
{
    std::vector<sbrt::ClipPlane> clips;
    for (const auto &p : planes)
        clips.push_back({{p[0], p[1], p[2]}, {p[3], p[4], p[5]}});
    if (section) {
        const auto &s = *section;
        clips.push_back(sbrt::section_plane({s[0], s[1]}, {s[2], s[3]}, camera));
    }
    return clips;
}

std::string SectionsPart::key(const sbrt::Camera &camera) const
{
    std::ostringstream key;
    key << std::hexfloat;
    for (const sbrt::ClipPlane &p : clip_planes(camera))
        key << "plane " << p.point.x << ' ' << p.point.y << ' ' << p.point.z << ' '
            << p.normal.x << ' ' << p.normal.y << ' ' << p.normal.z << '\n';
    key << "fence " << fence;
    return key.str();
}
