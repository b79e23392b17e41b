/****************************************************************************
 * MODULE:    r3.sbrt.manage
 * PURPOSE:   rename=: SBRTs within the current mapset, with g.rename's
 *            rules (GRASS 8.2): a pair that cannot be renamed is skipped
 *            with a warning and the run still succeeds; only a rename that
 *            fails on the file system fails the run
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/error.hpp"
#include "manage.hpp"
#include "sbrt_manage.hpp"

namespace {

/// False only when the file system refused the rename.
bool rename_one(const char *key, const char *old_name, const char *new_name,
                bool overwrite)
{
    const auto source = sbrt_grass::find_stored_sbrt(old_name, G_mapset());
    if (!source) {
        G_warning(_("%s <%s> not found"), SBRT_DESCRIPTION, old_name);
        return true;
    }
    if (sbrt_grass::find_stored_sbrt(new_name, G_mapset()) && !overwrite) {
        G_warning(_("<%s> already exists in mapset <%s>"), new_name,
                  G_mapset());
        return true;
    }
    if (G_legal_filename(new_name) < 0) {
        G_warning(_("<%s> is an illegal file name"), new_name);
        return true;
    }
    // case-blind as g.rename: on a case-blind file system the two names
    // would be one directory
    if (G_strcasecmp(source->name.c_str(), new_name) == 0) {
        G_warning(_("%s=%s,%s: files could be the same, no rename possible"),
                  key, old_name, new_name);
        return true;
    }
    G_message(_("Rename %s <%s> to <%s>"), SBRT_DESCRIPTION, old_name,
              new_name);
    try {
        sbrt_grass::rename_sbrt(source->name, new_name);
    }
    catch (const sbrt::Error &e) {
        G_warning(_("Unable to rename %s <%s> to <%s>: %s"), SBRT_DESCRIPTION,
                  old_name, new_name, e.what());
        return false;
    }
    return true;
}

} // namespace

void rename_sbrts(const Option *rename, bool overwrite)
{
    bool failed = false;
    // the parser has checked that the names come in pairs
    for (int i = 0; rename->answers[i] && rename->answers[i + 1]; i += 2)
        failed |= !rename_one(rename->key, rename->answers[i],
                              rename->answers[i + 1], overwrite);
    if (failed)
        G_fatal_error(_("Errors occurred during renaming. See the warning "
                        "messages above for details."));
}
