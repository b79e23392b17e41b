/****************************************************************************
 * MODULE:    r3.sbrt.manage
 * PURPOSE:   -l: the SBRTs of the search path or of mapset=, as g.list
 *            lists maps
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>

#include <nlohmann/json.hpp>

#include "manage.hpp"
#include "output_format.hpp"
#include "sbrt_manage.hpp"
#include "sbrt_store.hpp"

std::vector<std::string> mapsets_to_list(const Option *mapset)
{
    std::vector<std::string> mapsets;
    if (!mapset->answers) {
        for (int i = 0; const char *name = G_get_mapset_name(i); ++i)
            mapsets.push_back(name);
        return mapsets;
    }
    for (int i = 0; const char *name = mapset->answers[i]; ++i) {
        if (std::string(name) == "*") {
            char **all = G_get_available_mapsets();
            for (int j = 0; all && all[j]; ++j)
                mapsets.push_back(all[j]);
        }
        else if (std::string(name) == ".") {
            mapsets.push_back(G_mapset());
        }
        else if (!sbrt_grass::is_location_mapset(name)) {
            // a name only: "../x" or a directory that is no mapset would
            // list what lies outside the location's mapsets (issue 28)
            G_fatal_error(_("Mapset <%s> does not exist in location <%s>: "
                            "mapset= takes the name of one of its mapsets "
                            "(g.mapsets -l lists them), '.' or '*'"),
                          name, G_location());
        }
        else {
            mapsets.push_back(name);
        }
    }
    return mapsets;
}

void print_sbrts(const std::vector<std::string> &mapsets, bool qualified,
                 sbrt_grass::OutputFormat format, char separator)
{
    const std::vector<sbrt_grass::StoredSbrt> sbrts =
        sbrt_grass::list_stored_sbrts(mapsets);
    if (format == sbrt_grass::OutputFormat::json) {
        nlohmann::ordered_json list = nlohmann::ordered_json::array();
        for (const sbrt_grass::StoredSbrt &sbrt : sbrts)
            list.push_back(
                {{"name", sbrt.name}, {"mapset", sbrt.mapset}, {"fullname", sbrt.qualified()}});
        fprintf(stdout, "%s\n", sbrt_grass::json_text(list).c_str());
        return;
    }
    if (format == sbrt_grass::OutputFormat::csv) {
        fputs(sbrt_grass::csv_record({"name", "mapset", "fullname"}, separator).c_str(),
              stdout);
        for (const sbrt_grass::StoredSbrt &sbrt : sbrts)
            fputs(sbrt_grass::csv_record({sbrt.name, sbrt.mapset, sbrt.qualified()}, separator)
                      .c_str(),
                  stdout);
        return;
    }
    for (size_t i = 0; i < sbrts.size(); ++i) {
        // a bare name must say which SBRT it is: g.list adds the mapset to
        // a name that several of the listed mapsets hold
        const bool ambiguous =
            (i + 1 < sbrts.size() && sbrts[i + 1].name == sbrts[i].name) ||
            (i > 0 && sbrts[i - 1].name == sbrts[i].name);
        if (qualified || ambiguous)
            fprintf(stdout, "%s\n", sbrts[i].qualified().c_str());
        else
            fprintf(stdout, "%s\n", sbrts[i].name.c_str());
    }
}
