/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   A report's output= file written whole or not at all: into a
 *            temporary sibling, renamed over the name once complete
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GRASS_REPORT_FILE_HPP
#define SBRT_GRASS_REPORT_FILE_HPP

#include <cstdio>
#include <string>

namespace sbrt_grass {

/// \brief output= of a module that prints records (standard output for ""
/// and "-"). The file is made at once beside `name` (so that a name in a
/// folder that cannot be written fails before any work) and takes `name`
/// only in commit(): an error, a full disk or a kill before that leaves a
/// file of that name as it was, and the temporary one is removed.
class ReportFile {
public:
    explicit ReportFile(std::string name);
    ~ReportFile();
    ReportFile(const ReportFile &) = delete;
    ReportFile &operator=(const ReportFile &) = delete;

    FILE *get() const { return file_ ? file_ : stdout; }
    /// Flushes, checks and renames the file into place; throws
    /// sbrt::Error naming output= where writing failed (fail_with: the
    /// module's run_reporting_errors ends with it).
    void commit();

private:
    std::string name_, temporary_;
    FILE *file_ = nullptr;
};

} // namespace sbrt_grass

#endif
