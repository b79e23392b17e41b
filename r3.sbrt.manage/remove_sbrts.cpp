/****************************************************************************
 * MODULE:    r3.sbrt.manage
 * PURPOSE:   remove=: SBRTs of the current mapset, with g.remove's rules
 *            (GRASS 8.2): without -f only the list of what would go; names
 *            not found are passed over, a warning says when none was
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>
#include <cstring>
#include <set>

#include "util/error.hpp"
#include "manage.hpp"
#include "sbrt_manage.hpp"
#include "sbrt_store.hpp"

namespace {

/// The names to remove, sorted and each once as g.remove lists them; fatal
/// error for a name of another mapset or an illegal one.
std::set<std::string> names_to_remove(const Option *remove)
{
    std::set<std::string> names;
    bool illegal = false;
    for (int i = 0; const char *answer = remove->answers[i]; ++i) {
        char bare[GNAME_MAX], mapset[GMAPSET_MAX];
        std::string name = answer;
        if (strlen(answer) < GNAME_MAX &&
            G_name_is_fully_qualified(answer, bare, mapset)) {
            if (strcmp(mapset, G_mapset()) != 0)
                G_fatal_error(_("%s: Cannot remove or exclude files not in "
                                "the current mapset."),
                              answer);
            name = bare;
        }
        // G_legal_filename says what is wrong with each name
        illegal |= G_legal_filename(name.c_str()) < 0;
        names.insert(name);
    }
    if (illegal)
        G_fatal_error(_("Illegal filenames not allowed in the remove "
                        "option."));
    return names;
}

} // namespace

void remove_sbrts(const Option *remove, bool force)
{
    std::vector<std::string> found;
    for (const std::string &name : names_to_remove(remove))
        if (sbrt_grass::find_stored_sbrt(name, G_mapset()))
            found.push_back(name);
    if (!force)
        G_message(_("The following data base element files would be "
                    "deleted:"));
    if (found.empty()) {
        G_warning(_("No data base element files found"));
        return;
    }
    if (!force) {
        for (const std::string &name : found)
            fprintf(stdout, "%s/%s@%s\n", sbrt_grass::ELEMENT, name.c_str(),
                    G_mapset());
        fflush(stdout);
        G_warning(_("Nothing removed. You must use the force flag (-f) to "
                    "actually remove them. Exiting."));
        return;
    }
    bool failed = false;
    for (const std::string &name : found) {
        G_message(_("Removing %s <%s>"), SBRT_DESCRIPTION, name.c_str());
        try {
            sbrt_grass::remove_sbrt(name);
        }
        catch (const sbrt::Error &e) {
            G_warning(_("Unable to remove %s <%s>: %s"), SBRT_DESCRIPTION,
                      name.c_str(), e.what());
            failed = true;
        }
    }
    if (failed)
        G_fatal_error(_("Errors occurred during removal. See the warning "
                        "messages above for details."));
}
