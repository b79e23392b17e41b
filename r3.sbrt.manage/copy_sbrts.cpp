/****************************************************************************
 * MODULE:    r3.sbrt.manage
 * PURPOSE:   copy=: SBRTs of the search path into the current mapset, with
 *            g.copy's rules (GRASS 8.2): a pair that cannot be copied is
 *            skipped with a warning, and the run fails when nothing was
 *            copied or a copy failed
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/error.hpp"
#include "manage.hpp"
#include "sbrt_manage.hpp"

namespace {

enum class Outcome { copied, skipped, failed };

Outcome copy_one(const char *key, const char *from, const char *to,
                 bool overwrite)
{
    const auto source = sbrt_grass::find_stored_sbrt(from, "");
    if (!source) {
        G_warning(_("<%s> does not exist. Skipping."), from);
        return Outcome::skipped;
    }
    // case-blind as g.copy: a mapset may live on a case-blind file system
    if (G_strcasecmp(source->mapset.c_str(), G_mapset()) == 0 &&
        G_strcasecmp(source->name.c_str(), to) == 0) {
        G_warning(_("%s=%s,%s: files are the same, no copy required. "
                    "Skipping."),
                  key, from, to);
        return Outcome::skipped;
    }
    if (sbrt_grass::find_stored_sbrt(to, G_mapset()) && !overwrite) {
        G_warning(_("<%s> already exists and overwrite is not enabled. "
                    "Skipping."),
                  to);
        return Outcome::skipped;
    }
    if (G_legal_filename(to) < 0) {
        G_warning(_("<%s> is an illegal file name. Skipping."), to);
        return Outcome::skipped;
    }
    G_message(_("Copying %s <%s> to current mapset as <%s>"), SBRT_DESCRIPTION,
              source->qualified().c_str(), to);
    try {
        sbrt_grass::copy_sbrt(*source, to);
    }
    catch (const sbrt::Error &e) {
        G_warning(_("Unable to copy %s <%s> to <%s>: %s"), SBRT_DESCRIPTION,
                  source->qualified().c_str(), to, e.what());
        return Outcome::failed;
    }
    return Outcome::copied;
}

} // namespace

void copy_sbrts(const Option *copy, bool overwrite)
{
    int copied = 0;
    bool failed = false;
    // the parser has checked that the names come in pairs
    for (int i = 0; copy->answers[i] && copy->answers[i + 1]; i += 2) {
        const Outcome outcome = copy_one(copy->key, copy->answers[i],
                                         copy->answers[i + 1], overwrite);
        copied += outcome == Outcome::copied;
        failed |= outcome == Outcome::failed;
    }
    if (copied == 0 && !failed)
        G_fatal_error(_("All inputs had to be skipped. Nothing to copy. See "
                        "the warning messages above for details."));
    if (copied == 0)
        G_fatal_error(_("Nothing was copied. See the warning messages above "
                        "for details."));
    if (failed)
        G_fatal_error(_("Errors occurred during copying. See the warning "
                        "messages above for details."));
}
