/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An option naming an existing SBRT offered as a drop-down list
 *            in the modules' GUI dialogs
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "sbrt_choices.hpp"

#include <cstring>
#include <string>
#include <vector>

#include "sbrt_manage.hpp"
#include "sbrt_store.hpp"

namespace sbrt_grass {

namespace {

/// Whether the GUI asks for the interface; if so, `option` loses its
/// gisprompt.
bool describing_for_dialog(Option *option, int argc, char *argv[])
{
    bool describing = false;
    for (int i = 1; i < argc; ++i)
        describing = describing || std::strcmp(argv[i], "--interface-description") == 0;
    if (describing)
        option->gisprompt = nullptr;
    return describing;
}

/// `names` as the option's values (none: a text field).
void set_values(Option *option, const std::vector<std::string> &names)
{
    if (names.empty())
        return;
    std::string values;
    for (const std::string &name : names)
        values += (values.empty() ? "" : ",") + name;
    option->options = G_store(values.c_str());
}

} // namespace

void offer_own_sbrts_in_dialog(Option *option, int argc, char *argv[])
{
    if (!describing_for_dialog(option, argc, argv))
        return;
    std::vector<std::string> names;
    for (const StoredSbrt &sbrt : list_stored_sbrts({G_mapset()}))
        names.push_back(sbrt.name);
    set_values(option, names);
}

void offer_sbrts_in_dialog(Option *option, int argc, char *argv[])
{
    if (!describing_for_dialog(option, argc, argv))
        return;
    // name@mapset of each, and before them the plain names the search path
    // finds unambiguously: the dialog's list, and also what pygrass (and so
    // gunittest) checks a value against, which must take input=geo
    const std::vector<std::string> qualified = list_sbrts();
    std::vector<std::string> names;
    for (const std::string &q : qualified) {
        const std::string plain = q.substr(0, q.find('@'));
        size_t same = 0;
        for (const std::string &other : qualified)
            same += other.compare(0, other.find('@'), plain) == 0;
        if (same == 1)
            names.push_back(plain);
    }
    names.insert(names.end(), qualified.begin(), qualified.end());
    set_values(option, names);
}

} // namespace sbrt_grass
