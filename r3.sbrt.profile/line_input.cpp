/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * PURPOSE:   The profile's line from coordinates= or a vector map
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "line_input.hpp"

#include "module_errors.hpp"
#include "vector_map.hpp"

namespace {

bool has_cat(const line_cats *cats, int cat)
{
    for (int i = 0; i < cats->n_cats; ++i)
        if (cats->field[i] == 1 && cats->cat[i] == cat)
            return true;
    return false;
}

} // namespace

std::vector<glm::dvec2> read_line_vertices(const ProfileRequest &request)
{
    if (request.line.empty())
        return request.vertices;
    sbrt_grass::VectorMap map(request.line, "-1");
    std::vector<glm::dvec2> vertices;
    size_t lines = 0;
    while (const int type = map.next()) {
        if (!(type & GV_LINES) || (request.cat && !has_cat(map.cats(), *request.cat)))
            continue;
        if (lines++ == 0) {
            const line_pnts &p = map.points();
            for (int k = 0; k < p.n_points; ++k)
                vertices.push_back({p.x[k], p.y[k]});
        }
    }
    if (lines == 0 && request.cat)
        sbrt_grass::fail_with(_("line=%s has no line of category %d in layer 1 (v.category "
                                "option=print lists them)"),
                              request.line.c_str(), *request.cat);
    if (lines == 0)
        sbrt_grass::fail_with(_("line=%s has no lines: the profile needs a vector map of lines "
                                "(v.in.ascii, v.digit) or coordinates="),
                              request.line.c_str());
    if (lines > 1)
        G_warning(_("line=%s has %zu lines%s: the profile follows the first%s"),
                  request.line.c_str(), lines, request.cat ? " of that category" : "",
                  request.cat ? "" : " (choose one with cat=)");
    return vertices;
}
