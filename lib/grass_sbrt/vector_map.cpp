/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   A vector map open for reading feature by feature
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "vector_map.hpp"

#include <cerrno>
#include <cstdlib>

#include "util/error.hpp"
#include "module_errors.hpp"

namespace sbrt_grass {

namespace {

/// A map name as a message quotes it: a request's value can be megabytes.
std::string quoted(const std::string &name)
{
    constexpr size_t limit = 200;
    return name.size() <= limit ? name : name.substr(0, limit) + "...";
}

} // namespace

VectorMap::VectorMap(const std::string &name, const char *layer, const char *option)
{
    // Vect_open_old2 ends the process on a missing map: looked up first
    if (!G_find_vector2(name.c_str(), ""))
        sbrt::fail(_("Vector map"), " <", quoted(name), "> ", _("not found"),
                   option ? std::string(" (") + option + "=)" : std::string(), ": ",
                   _("g.list vector lists the maps"));
    Vect_set_open_level(1);
    if (Vect_open_old2(&map_, name.c_str(), "", layer) < 0)
        sbrt::fail(_("Unable to open vector map"), " <", quoted(name), ">");
    points_ = Vect_new_line_struct();
    cats_ = Vect_new_cats_struct();
}

VectorMap::~VectorMap()
{
    Vect_destroy_line_struct(points_);
    Vect_destroy_cats_struct(cats_);
    Vect_close(&map_);
}

int VectorMap::next()
{
    const int type = Vect_read_next_line(&map_, points_, cats_);
    if (type == -1)
        sbrt::fail(_("Unable to read vector map"), " <", Vect_get_full_name(&map_), ">");
    return type < 0 ? 0 : type;
}

int layer_number(Map_info &map, const std::string &layer)
{
    errno = 0;
    char *end = nullptr;
    const long number = std::strtol(layer.c_str(), &end, 10);
    if (!layer.empty() && *end == '\0' && errno == 0) {
        if (number < -1 || number > 2147483647L)
            fail_with(_("layer=%s: not a layer (a number from 1 up, -1 for every layer, or "
                        "the name of a layer of the map)"),
                      layer.c_str());
        return int(number);
    }
    if (const field_info *info = Vect_get_field_by_name(&map, layer.c_str()))
        return info->number;
    const char *name = Vect_get_full_name(&map);
    fail_with(_("layer=%s: vector map <%s> has no layer of that name (v.db.connect -p map=%s "
                "lists its layers; give a layer's number or name, or -1 for every layer)"),
              layer.c_str(), name, name);
}

} // namespace sbrt_grass
